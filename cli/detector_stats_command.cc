// SPDX-License-Identifier: MIT
// `rpt detector-stats`: how the 2D detections of an input err against its projected ground
// truth (datasets/detector_stats/statistics.h), as markdown tables or JSON. Works on real
// detections and on simulated ones (--simulate --detector PROFILE). --compare PROFILE,... puts
// the input's detections and simulated profiles on the same ground truth and cameras side by
// side in one table, which is how the simulated detector is fitted to real ones
// (docs/detector_model.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "cli/load_input.h"
#include "core/errors.h"
#include "core/text.h"
#include "datasets/detector_stats/statistics.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::cli {
namespace {

using Json = nlohmann::ordered_json;
using detector_stats::DetectorStats;
using detector_stats::ErrorSummary;
using detector_stats::ViewStats;

struct DetectorStatsArgs {
  InputArgs input;
  std::string joints;  // comma-separated
  double gate = 0.5;
  int min_joints_in_image = 2;
  bool json = false;
  std::vector<std::string> compare;  // simulated profiles to put next to the input's detections
};

Json SummaryJson(const ErrorSummary& s) {
  return Json{{"count", s.count}, {"median", s.median}, {"p90", s.p90}, {"p99", s.p99}, {"mean", s.mean}};
}

Json ViewJson(const ViewStats& v) {
  return Json{{"camera", v.camera},
              {"views", v.views},
              {"gt_in_view", v.gt_in_view},
              {"detected", v.detected},
              {"detection_rate", v.detection_rate()},
              {"detections", v.detections},
              {"duplicates", v.duplicates},
              {"false_positives", v.false_positives},
              {"false_positives_per_view", v.false_positives_per_view()},
              {"false_positives_near_gt", v.false_positives_near_gt},
              {"on_unlabelled_persons", v.on_unlabelled}};
}

Json StatsJson(const DetectorStats& s) {
  Json j;
  j["joints"] = s.joints;
  j["box"] = "projected GT statistic joints, clipped to the image";
  j["views"] = Json::array();
  for (const ViewStats& v : s.views) j["views"].push_back(ViewJson(v));
  j["total"] = ViewJson(s.total);
  j["persons_in_view"] = s.persons_in_view;
  j["persons_truncated"] = s.persons_truncated;
  j["truncated_share"] = s.truncated_share;
  j["persons_in_any_view"] = s.persons_in_any_view;
  j["persons_by_detecting_views"] = {{"0", s.persons_by_detecting_views[0]},
                                     {"1", s.persons_by_detecting_views[1]},
                                     {"2", s.persons_by_detecting_views[2]},
                                     {"3+", s.persons_by_detecting_views[3]}};
  const char* classes[3] = {"mostly_visible", "mostly_hidden", "unknown"};
  for (int c = 0; c < 3; ++c) {
    j["detection_by_label"][classes[c]] = Json{{"persons", s.persons_by_label[c]},
                                               {"detected", s.detected_by_label[c]},
                                               {"rate", s.detection_rate_by_label[c]}};
  }
  j["box_diagonal_px_median"] = s.box_diagonal_px_median;
  j["box_diagonal_px_median_truncated"] = s.box_diagonal_px_median_truncated;
  j["error"] = Json{{"all", SummaryJson(s.all)},
                    {"hidden", SummaryJson(s.hidden)},
                    {"clear_persons", SummaryJson(s.clear_persons)},
                    {"hidden_persons", SummaryJson(s.hidden_persons)},
                    {"confidence_low", SummaryJson(s.confidence_low)},
                    {"confidence_mid", SummaryJson(s.confidence_mid)},
                    {"confidence_high", SummaryJson(s.confidence_high)}};
  j["by_visibility"] = Json::object();
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
    const detector_stats::VisibilityStats& b = s.by_visibility[v];
    j["by_visibility"][detector_stats::VisibilityName(v)] = Json{{"joints", b.joints},
                                                                  {"of_detected", b.of_detected},
                                                                  {"missing", b.missing},
                                                                  {"missing_rate", b.missing_rate()},
                                                                  {"confidence_mean", b.confidence_mean},
                                                                  {"confidence_histogram", b.confidence_histogram},
                                                                  {"error", SummaryJson(b.error)}};
  }
  j["hidden_share"] = s.hidden_share;
  j["joints_in_image"] = s.joints_in_image;
  j["joints_missing"] = s.joints_missing;
  j["missing_rate"] = s.missing_rate;
  j["reported_outside"] = s.reported_outside;
  j["confidence_histogram"] = s.confidence_histogram;
  j["confidence_mean"] = s.confidence_mean;
  j["confidence_median"] = s.confidence_median;
  j["false_positive_confidence_mean"] = s.false_positive_confidence_mean;
  j["false_positive_joints_mean"] = s.false_positive_joints_mean;
  j["detected_joints_mean"] = s.detected_joints_mean;
  j["swap_candidates"] = s.swap_candidates;
  j["swaps"] = s.swaps;
  j["swap_rate"] = s.swap_rate;
  j["per_joint"] = Json::array();
  for (const detector_stats::JointStats& p : s.per_joint) {
    j["per_joint"].push_back(Json{{"joint", p.joint},
                                  {"error", SummaryJson(p.error)},
                                  {"in_image", p.in_image},
                                  {"missing", p.missing},
                                  {"hidden", p.hidden},
                                  {"hidden_missing", p.hidden_missing},
                                  {"confidence_mean", p.confidence_mean},
                                  {"down_count", p.down_count},
                                  {"down_mean", p.down_mean},
                                  {"down_median", p.down_median},
                                  {"out_count", p.out_count},
                                  {"out_mean", p.out_mean},
                                  {"out_median", p.out_median}});
  }
  return j;
}

std::string Percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %%", 100.0 * fraction);
  return text;
}

void PrintErrorRow(const char* name, const ErrorSummary& s) {
  if (s.count == 0) {
    std::printf("| %s | 0 | - | - | - | - |\n", name);
    return;
  }
  std::printf("| %s | %ld | %.3f | %.3f | %.3f | %.3f |\n", name, s.count, s.median, s.p90, s.p99, s.mean);
}

void PrintMarkdown(const DetectorStats& s, const std::string& input) {
  std::printf("# Detector statistics: %s\n\n", input.c_str());
  std::printf("Statistic joints: %s. Box: the projected GT statistic joints, clipped to the image; errors are\n"
              "pixel distances divided by its diagonal (box units).\n\n",
              Join(s.joints).c_str());
  std::printf("## Detection per view\n\n");
  std::printf("| camera | views | GT persons in view | detected | rate | detections | exact duplicates | false positives | per view | near a GT person | on 2D-only persons |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto row = [](const ViewStats& v) {
    std::printf("| %s | %ld | %ld | %ld | %s | %ld | %ld | %ld | %.3f | %ld | %ld |\n", v.camera.c_str(), v.views,
                v.gt_in_view, v.detected, Percent(v.detection_rate()).c_str(), v.detections, v.duplicates, v.false_positives,
                v.false_positives_per_view(), v.false_positives_near_gt, v.on_unlabelled);
  };
  for (const ViewStats& v : s.views) row(v);
  row(s.total);
  std::printf("\nDetection rate by the 2D labels: mostly visible %s of %ld, mostly hidden %s of %ld, no labels %s of %ld.\n",
              Percent(s.detection_rate_by_label[0]).c_str(), s.persons_by_label[0],
              Percent(s.detection_rate_by_label[1]).c_str(), s.persons_by_label[1],
              Percent(s.detection_rate_by_label[2]).c_str(), s.persons_by_label[2]);

  std::printf("\n## Joint errors (box units)\n\n");
  std::printf("| joints | count | median | p90 | p99 | mean |\n|---|---:|---:|---:|---:|---:|\n");
  PrintErrorRow("all", s.all);
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
    const std::string name = std::string(detector_stats::VisibilityName(v)) + " (2D label)";
    PrintErrorRow(name.c_str(), s.by_visibility[v].error);
  }
  PrintErrorRow("hidden: occluded or not labelled", s.hidden);
  PrintErrorRow("persons neither truncated nor hidden", s.clear_persons);
  PrintErrorRow("persons truncated or partly hidden", s.hidden_persons);
  PrintErrorRow("confidence <= 0.5", s.confidence_low);
  PrintErrorRow("confidence 0.5-0.9", s.confidence_mid);
  PrintErrorRow("confidence >= 0.9", s.confidence_high);

  std::printf("\n## By 2D label (in-image statistic joints of GT persons in view)\n\n");
  std::printf("| label | joints | share | missing (detected persons) | confidence mean |\n|---|---:|---:|---:|---:|\n");
  long labelled = 0;
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) labelled += s.by_visibility[v].joints;
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
    const detector_stats::VisibilityStats& b = s.by_visibility[v];
    std::printf("| %s | %ld | %s | %s of %ld | %.3f |\n", detector_stats::VisibilityName(v), b.joints,
                Percent(labelled > 0 ? static_cast<double>(b.joints) / labelled : 0).c_str(),
                Percent(b.missing_rate()).c_str(), b.of_detected, b.confidence_mean);
  }

  std::printf("\n## Other statistics\n\n| statistic | value |\n|---|---|\n");
  std::printf("| missing joints (in-image GT joints of detected persons) | %s of %ld |\n",
              Percent(s.missing_rate).c_str(), s.joints_in_image);
  std::printf("| hidden share (occluded or not labelled, views with 2D labels) | %s |\n", Percent(s.hidden_share).c_str());
  std::printf("| truncated persons (a joint outside the image) | %s of %ld |\n", Percent(s.truncated_share).c_str(),
              s.persons_in_view);
  std::printf("| GT persons detected in 0 / 1 / 2 / 3+ views (of %ld in view of a camera, per frame) | %s / %s / %s / %s |\n",
              s.persons_in_any_view, Percent(s.ShareDetectedInViews(0)).c_str(), Percent(s.ShareDetectedInViews(1)).c_str(),
              Percent(s.ShareDetectedInViews(2)).c_str(), Percent(s.ShareDetectedInViews(3)).c_str());
  std::printf("| box diagonal, median px (whole / truncated persons) | %.0f / %.0f |\n", s.box_diagonal_px_median,
              s.box_diagonal_px_median_truncated);
  std::printf("| left/right swaps (closer to the mirrored GT joint) | %s of %ld |\n", Percent(s.swap_rate).c_str(),
              s.swap_candidates);
  std::printf("| confidence mean / median | %.3f / %.3f |\n", s.confidence_mean, s.confidence_median);
  std::printf("| confidence mean of false positives | %.3f |\n", s.false_positive_confidence_mean);
  std::printf("| reported statistic joints per detection (paired / false positive) | %.2f / %.2f |\n",
              s.detected_joints_mean, s.false_positive_joints_mean);
  std::printf("| reported joints whose GT is outside the image | %ld |\n", s.reported_outside);
  std::printf("\n## Confidence distribution (reported joints of detected persons)\n\n| bin |");
  for (int b = 0; b < 10; ++b) std::printf(" %.1f-%.1f |", b / 10.0, (b + 1) / 10.0);
  std::printf("\n|---|");
  for (int b = 0; b < 10; ++b) std::printf("---:|");
  long total = 0;
  for (long n : s.confidence_histogram) total += n;
  std::printf("\n| share |");
  for (long n : s.confidence_histogram) std::printf(" %s |", Percent(total > 0 ? static_cast<double>(n) / total : 0).c_str());

  std::printf("\n\n## Per joint (box units; offsets: down = along shoulders->hips, out = away from the midline)\n\n");
  std::printf("| joint | count | median | p90 | missing | hidden | missing of hidden | confidence | down mean | down median | out mean | out median |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto share = [](long a, long b) { return Percent(b > 0 ? static_cast<double>(a) / b : 0); };
  for (const detector_stats::JointStats& p : s.per_joint) {
    std::printf("| %s | %ld | %.3f | %.3f | %s | %s | %s | %.3f | %+.3f | %+.3f | %+.3f | %+.3f |\n", p.joint.c_str(),
                p.error.count, p.error.median, p.error.p90, share(p.missing, p.in_image).c_str(),
                share(p.hidden, p.in_image).c_str(), share(p.hidden_missing, p.hidden).c_str(), p.confidence_mean, p.down_mean,
                p.down_median, p.out_mean, p.out_median);
  }
}

std::string Describe(const InputArgs& input) {
  std::string text = !input.dataset.empty() ? "dataset " + input.dataset : "labels " + input.labels;
  for (const std::string& param : input.params) text += " " + param;
  if (input.simulate) {
    const std::string profile = input.simulate_perfect ? "perfect" : input.detector.empty() ? "realistic" : input.detector;
    text += ", simulated detector '" + profile + "', seed " + std::to_string(input.seed);
  } else if (!input.detections.empty()) {
    text += ", detections " + input.detections;
  } else {
    text += ", the dataset's detections";
  }
  return text;
}

// ---- --compare: one column per detector ----------------------------------------------------

// A labelled column of the comparison table.
struct Column {
  std::string name;
  DetectorStats stats;
};

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  std::string out = text;
  // A signed value that rounds to zero prints as "0.000", not "-0.000" or "+0.000".
  if ((out[0] == '-' || out[0] == '+') && out.find_first_not_of("0.", 1) == std::string::npos) out.erase(0, 1);
  return out;
}

// Cells made of several values ("a / b / c"); a value that does not exist is "-", a cell
// without any value is a single "-".
struct Cell {
  std::vector<std::string> parts;
  Cell& Add(bool present, const char* format, double value) {
    parts.push_back(present ? Format(format, value) : "-");
    return *this;
  }
  std::string Text() const {
    bool any = false;
    for (const std::string& p : parts) any |= p != "-";
    return any ? Join(parts, " / ") : "-";
  }
};

double Share(long part, long whole) { return whole > 0 ? static_cast<double>(part) / whole : 0; }

std::string Errors(const ErrorSummary& e) {
  return Cell{}.Add(e.count > 0, "%.3f", e.median).Add(e.count > 0, "%.3f", e.p90).Add(e.count > 0, "%.3f", e.p99).Text();
}

// Occluded or not labelled.
bool IsHidden(int visibility) {
  return visibility == detector_stats::kOccluded || visibility == detector_stats::kNotLabelled;
}

long Reported(const detector_stats::VisibilityStats& b) {
  long n = 0;
  for (long count : b.confidence_histogram) n += count;
  return n;
}

// Whether any view has 2D labels (or simulated ones): else nothing is known to be hidden.
bool HasLabels(const DetectorStats& s) {
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
    if (v != detector_stats::kUnknown && s.by_visibility[v].joints > 0) return true;
  }
  return false;
}

const detector_stats::JointStats* FindJointStats(const DetectorStats& s, const std::string& joint) {
  for (const detector_stats::JointStats& p : s.per_joint) {
    if (p.joint == joint) return &p;
  }
  return nullptr;
}

// The rows of the comparison, as in docs/detector_model.md: box units with 3 decimals,
// confidences with 2.
using RowFunction = std::string (*)(const DetectorStats&);
const std::vector<std::pair<const char*, RowFunction>>& CompareRows() {
  static const std::vector<std::pair<const char*, RowFunction>> rows = {
      {"GT persons in view", [](const DetectorStats& s) { return std::to_string(s.persons_in_view); }},
      {"detection rate, GT persons in view",
       [](const DetectorStats& s) { return Cell{}.Add(s.total.gt_in_view > 0, "%.3f", s.total.detection_rate()).Text(); }},
      {"... mostly visible / mostly hidden persons",
       [](const DetectorStats& s) {
         return Cell{}
             .Add(s.persons_by_label[0] > 0, "%.3f", s.detection_rate_by_label[0])
             .Add(s.persons_by_label[1] > 0, "%.3f", s.detection_rate_by_label[1])
             .Text();
       }},
      {"GT persons detected in 0 / 1 / 2 / 3+ views",
       [](const DetectorStats& s) {
         const bool any = s.persons_in_any_view > 0;
         return Cell{}
             .Add(any, "%.3f", s.ShareDetectedInViews(0))
             .Add(any, "%.3f", s.ShareDetectedInViews(1))
             .Add(any, "%.3f", s.ShareDetectedInViews(2))
             .Add(any, "%.3f", s.ShareDetectedInViews(3))
             .Text();
       }},
      {"false positives per view",
       [](const DetectorStats& s) { return Cell{}.Add(s.total.views > 0, "%.3f", s.total.false_positives_per_view()).Text(); }},
      {"joint error, all: median / p90 / p99", [](const DetectorStats& s) { return Errors(s.all); }},
      {"visible joints", [](const DetectorStats& s) { return Errors(s.by_visibility[detector_stats::kVisible].error); }},
      {"hidden joints (occluded or not labelled)", [](const DetectorStats& s) { return Errors(s.hidden); }},
      {"persons neither truncated nor hidden", [](const DetectorStats& s) { return Errors(s.clear_persons); }},
      {"confidence <= 0.5", [](const DetectorStats& s) { return Errors(s.confidence_low); }},
      {"confidence 0.5-0.9", [](const DetectorStats& s) { return Errors(s.confidence_mid); }},
      {"confidence >= 0.9", [](const DetectorStats& s) { return Errors(s.confidence_high); }},
      {"hidden share of in-image joints",
       [](const DetectorStats& s) { return Cell{}.Add(HasLabels(s), "%.3f", s.hidden_share).Text(); }},
      {"missing joints: all / visible / hidden",
       [](const DetectorStats& s) {
         long hidden = 0, hidden_missing = 0;
         for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
           if (!IsHidden(v)) continue;
           hidden += s.by_visibility[v].of_detected;
           hidden_missing += s.by_visibility[v].missing;
         }
         const detector_stats::VisibilityStats& visible = s.by_visibility[detector_stats::kVisible];
         return Cell{}
             .Add(s.joints_in_image > 0, "%.3f", s.missing_rate)
             .Add(visible.of_detected > 0, "%.3f", visible.missing_rate())
             .Add(hidden > 0, "%.3f", Share(hidden_missing, hidden))
             .Text();
       }},
      {"confidence mean: visible / hidden joints",
       [](const DetectorStats& s) {
         double hidden_sum = 0;
         long hidden = 0;
         for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
           if (!IsHidden(v)) continue;
           hidden += Reported(s.by_visibility[v]);
           hidden_sum += Reported(s.by_visibility[v]) * s.by_visibility[v].confidence_mean;
         }
         const detector_stats::VisibilityStats& visible = s.by_visibility[detector_stats::kVisible];
         return Cell{}
             .Add(Reported(visible) > 0, "%.2f", visible.confidence_mean)
             .Add(hidden > 0, "%.2f", hidden > 0 ? hidden_sum / hidden : 0)
             .Text();
       }},
      {"share of confidences >= 0.9 / < 0.5",
       [](const DetectorStats& s) {
         long total = 0, low = 0;
         for (int b = 0; b < 10; ++b) {
           total += s.confidence_histogram[b];
           if (b < 5) low += s.confidence_histogram[b];
         }
         return Cell{}
             .Add(total > 0, "%.3f", Share(s.confidence_histogram[9], total))
             .Add(total > 0, "%.3f", Share(low, total))
             .Text();
       }},
      {"left/right swaps", [](const DetectorStats& s) { return Cell{}.Add(s.swap_candidates > 0, "%.3f", s.swap_rate).Text(); }},
      {"hip offset, down / out (medians)",
       [](const DetectorStats& s) {
         // The mean of both hips' medians (each hip's alone: the per-joint table).
         double down = 0, out = 0;
         int down_n = 0, out_n = 0;
         for (const char* joint : {"hip_left", "hip_right"}) {
           const detector_stats::JointStats* p = FindJointStats(s, joint);
           if (p == nullptr) continue;
           if (p->down_count > 0) down += p->down_median, ++down_n;
           if (p->out_count > 0) out += p->out_median, ++out_n;
         }
         return Cell{}
             .Add(down_n > 0, "%+.3f", down_n > 0 ? down / down_n : 0)
             .Add(out_n > 0, "%+.3f", out_n > 0 ? out / out_n : 0)
             .Text();
       }},
      {"truncated persons",
       [](const DetectorStats& s) { return Cell{}.Add(s.persons_in_view > 0, "%.3f", s.truncated_share).Text(); }},
      {"false positives: mean confidence / reported joints",
       [](const DetectorStats& s) {
         const bool any = s.total.false_positives > 0;
         return Cell{}
             .Add(any, "%.2f", s.false_positive_confidence_mean)
             .Add(any, "%.1f", s.false_positive_joints_mean)
             .Text();
       }},
      {"box diagonal, median px",
       [](const DetectorStats& s) { return Cell{}.Add(s.persons_in_view > 0, "%.0f", s.box_diagonal_px_median).Text(); }},
  };
  return rows;
}

void PrintComparison(const std::vector<Column>& columns, const std::string& input, uint64_t seed) {
  std::printf("# Detector statistics: %s, against simulated detectors (seed %llu)\n\n", input.c_str(),
              static_cast<unsigned long long>(seed));
  std::printf("The simulated detectors run on the input's ground truth and cameras. Statistic joints: %s",
              Join(columns.front().stats.joints).c_str());
  for (size_t c = 1; c < columns.size(); ++c) {
    if (columns[c].stats.joints != columns.front().stats.joints) {
      std::printf("; %s: %s", columns[c].name.c_str(), Join(columns[c].stats.joints).c_str());
    }
  }
  std::printf(". Errors in box units (the projected GT statistic joints, clipped to the image).\n\n");

  std::printf("| statistic |");
  for (const Column& c : columns) std::printf(" %s |", c.name.c_str());
  std::printf("\n|---|");
  for (size_t c = 0; c < columns.size(); ++c) std::printf("---:|");
  std::printf("\n");
  for (const auto& [name, value] : CompareRows()) {
    std::printf("| %s |", name);
    for (const Column& c : columns) std::printf(" %s |", value(c.stats).c_str());
    std::printf("\n");
  }

  // Per joint: the columns' values side by side in each cell.
  std::vector<std::string> names;
  for (const Column& c : columns) names.push_back(c.name);
  std::vector<std::string> joints;
  for (const Column& c : columns) {
    for (const detector_stats::JointStats& p : c.stats.per_joint) {
      if (std::find(joints.begin(), joints.end(), p.joint) == joints.end()) joints.push_back(p.joint);
    }
  }
  std::printf("\nPer joint (%s; offsets: medians, down = along shoulders->hips, out = away from the midline):\n\n",
              Join(names, " / ").c_str());
  std::printf("| joint | error median | missing | hidden | missing when hidden | confidence | offset down | offset out |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& joint : joints) {
    Cell error, missing, hidden, hidden_missing, confidence, down, out;
    for (const Column& c : columns) {
      const detector_stats::JointStats* p = FindJointStats(c.stats, joint);
      const detector_stats::JointStats none;
      const detector_stats::JointStats& j = p != nullptr ? *p : none;
      error.Add(j.error.count > 0, "%.3f", j.error.median);
      missing.Add(j.in_image > 0, "%.0f", 100.0 * Share(j.missing, j.in_image));
      hidden.Add(j.in_image > 0 && HasLabels(c.stats), "%.0f", 100.0 * Share(j.hidden, j.in_image));
      hidden_missing.Add(j.hidden > 0, "%.0f", 100.0 * Share(j.hidden_missing, j.hidden));
      confidence.Add(j.error.count > 0, "%.2f", j.confidence_mean);
      down.Add(j.down_count > 0, "%+.3f", j.down_median);
      out.Add(j.out_count > 0, "%+.3f", j.out_median);
    }
    auto percent = [](const Cell& cell) {
      const std::string text = cell.Text();
      return text == "-" ? text : text + " %";
    };
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", joint.c_str(), error.Text().c_str(),
                percent(missing).c_str(), percent(hidden).c_str(), percent(hidden_missing).c_str(),
                confidence.Text().c_str(), down.Text().c_str(), out.Text().c_str());
  }

  std::printf("\nConfidence histogram (%% of the reported joints of detected persons, bins of 0.1):\n\n|");
  for (int b = 0; b < 10; ++b) std::printf(" | %.1f", b / 10.0);
  std::printf(" |\n|---|");
  for (int b = 0; b < 10; ++b) std::printf("---:|");
  std::printf("\n");
  for (const Column& c : columns) {
    long total = 0;
    for (long n : c.stats.confidence_histogram) total += n;
    std::printf("| %s |", c.name.c_str());
    for (long n : c.stats.confidence_histogram) std::printf(" %.1f |", 100.0 * Share(n, total));
    std::printf("\n");
  }
}

DetectorStats ComputeStats(const std::vector<Sequence>& sequences, const DetectorStatsArgs& args) {
  detector_stats::StatsOptions options;
  std::stringstream list(args.joints);
  for (std::string item; std::getline(list, item, ',');) {
    if (!item.empty()) options.joints.push_back(item);
  }
  options.association.gate_relative = args.gate;
  options.min_joints_in_image = args.min_joints_in_image;
  detector_stats::StatsAccumulator accumulator(options);
  for (const Sequence& sequence : sequences) accumulator.Add(sequence);
  return accumulator.Finalize();
}

// The input's own name for the column header: the dataset, else the labels file.
std::string InputColumnName(const InputArgs& input) {
  if (!input.dataset.empty()) return "input: " + input.dataset;
  return "input: " + std::filesystem::path(input.labels).filename().string();
}

void RunComparison(const DetectorStatsArgs& args) {
  if (args.input.simulate || args.input.simulate_perfect) {
    throw ConfigError(
        "--compare excludes --simulate: it measures the input's own detections and simulates each listed "
        "profile itself on the same ground truth (seed: --seed)");
  }
  for (size_t i = 0; i < args.compare.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (args.compare[i] == args.compare[k]) throw ConfigError("--compare lists '" + args.compare[i] + "' twice");
    }
  }
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = LoadInput(args.input, /*require_detections=*/true, &input_warnings);
  PrintInputWarnings(input_warnings);
  std::vector<Column> columns;
  std::vector<InputArgs> inputs;
  columns.push_back({InputColumnName(args.input), ComputeStats(sequences, args)});
  inputs.push_back(args.input);
  for (const std::string& profile : args.compare) {
    std::vector<Sequence> simulated = sequences;  // same GT and cameras
    SimulateInputDetections(profile, args.input.seed, &simulated);
    columns.push_back({profile, ComputeStats(simulated, args)});
    InputArgs described = args.input;
    described.simulate = true;
    described.detector = profile;
    described.detections.clear();
    inputs.push_back(described);
  }
  if (args.json) {
    Json j = Json::object();
    for (size_t c = 0; c < columns.size(); ++c) {
      Json entry;
      entry["input"] = Describe(inputs[c]);
      entry.update(StatsJson(columns[c].stats));
      j[c == 0 ? std::string("input") : args.compare[c - 1]] = std::move(entry);
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  PrintComparison(columns, Describe(args.input), args.input.seed);
}

void RunDetectorStats(const DetectorStatsArgs& args) {
  if (!args.compare.empty()) {
    RunComparison(args);
    return;
  }
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = LoadInput(args.input, /*require_detections=*/true, &input_warnings);
  PrintInputWarnings(input_warnings);
  const DetectorStats stats = ComputeStats(sequences, args);
  if (args.json) {
    Json j;
    j["input"] = Describe(args.input);
    j.update(StatsJson(stats));
    std::cout << j.dump(2) << "\n";
    return;
  }
  PrintMarkdown(stats, Describe(args.input));
}

}  // namespace

void RegisterDetectorStatsCommand(CLI::App& app) {
  auto args = std::make_shared<DetectorStatsArgs>();
  CLI::App* command = app.add_subcommand(
      "detector-stats", "Measure how the 2D detections of an input err against its projected ground truth");
  AddInputOptions(command, &args->input);
  command->add_option("--joints", args->joints,
                      "statistic joints, comma-separated (default: the dataset's evaluated joints)");
  command->add_option("--gate", args->gate, "association gate: mean joint distance / GT box diagonal")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--min-joints-in-image", args->min_joints_in_image,
                      "a GT person counts as in view with this many statistic joints in the image")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--compare", args->compare,
                      "PROFILE[,PROFILE...]: one table of the input's detections next to these simulated detector "
                      "profiles (" + Join(synthetic::DetectorProfileNames(), "|") +
                          ") on the same ground truth and cameras (seed: --seed; not with --simulate)")
      ->delimiter(',')
      ->check(CLI::IsMember(synthetic::DetectorProfileNames()));
  command->add_flag("--json", args->json,
                    "print the statistics as JSON (with --compare: an object keyed \"input\" and by profile)");
  command->callback([args] { RunDetectorStats(*args); });
}

}  // namespace rpt::cli
