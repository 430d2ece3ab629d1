// SPDX-License-Identifier: MIT
#include "engine/detector_stats_comparison.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <utility>

#include "core/text.h"
#include "engine/outputs/text_escaping.h"

namespace rpt::engine {
namespace {

using detector_stats::DetectorStats;
using detector_stats::ErrorSummary;


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
struct ComparisonCell {
  std::vector<std::string> parts;
  ComparisonCell& Add(bool present, const char* format, double value) {
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
  return ComparisonCell{}
      .Add(e.count > 0, "%.3f", e.median)
      .Add(e.count > 0, "%.3f", e.p90)
      .Add(e.count > 0, "%.3f", e.p99)
      .Text();
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
       [](const DetectorStats& s) {
         return ComparisonCell{}.Add(s.total.gt_in_view > 0, "%.3f", s.total.detection_rate()).Text();
       }},
      {"... mostly visible / mostly hidden persons",
       [](const DetectorStats& s) {
         return ComparisonCell{}
             .Add(s.persons_by_label[0] > 0, "%.3f", s.detection_rate_by_label[0])
             .Add(s.persons_by_label[1] > 0, "%.3f", s.detection_rate_by_label[1])
             .Text();
       }},
      {"GT persons detected in 0 / 1 / 2 / 3+ views",
       [](const DetectorStats& s) {
         const bool any = s.persons_in_any_view > 0;
         return ComparisonCell{}
             .Add(any, "%.3f", s.ShareDetectedInViews(0))
             .Add(any, "%.3f", s.ShareDetectedInViews(1))
             .Add(any, "%.3f", s.ShareDetectedInViews(2))
             .Add(any, "%.3f", s.ShareDetectedInViews(3))
             .Text();
       }},
      {"false positives per view",
       [](const DetectorStats& s) {
         return ComparisonCell{}.Add(s.total.views > 0, "%.3f", s.total.false_positives_per_view()).Text();
       }},
      {"joint error, all: median / p90 / p99", [](const DetectorStats& s) { return Errors(s.all); }},
      {"visible joints",
       [](const DetectorStats& s) { return Errors(s.by_visibility[detector_stats::kVisible].error); }},
      {"hidden joints (occluded or not labelled)", [](const DetectorStats& s) { return Errors(s.hidden); }},
      {"persons neither truncated nor hidden", [](const DetectorStats& s) { return Errors(s.clear_persons); }},
      {"confidence <= 0.5", [](const DetectorStats& s) { return Errors(s.confidence_low); }},
      {"confidence 0.5-0.9", [](const DetectorStats& s) { return Errors(s.confidence_mid); }},
      {"confidence >= 0.9", [](const DetectorStats& s) { return Errors(s.confidence_high); }},
      {"hidden share of in-image joints",
       [](const DetectorStats& s) { return ComparisonCell{}.Add(HasLabels(s), "%.3f", s.hidden_share).Text(); }},
      {"missing joints: all / visible / hidden",
       [](const DetectorStats& s) {
         long hidden = 0, hidden_missing = 0;
         for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
           if (!IsHidden(v)) continue;
           hidden += s.by_visibility[v].of_detected;
           hidden_missing += s.by_visibility[v].missing;
         }
         const detector_stats::VisibilityStats& visible = s.by_visibility[detector_stats::kVisible];
         return ComparisonCell{}
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
         return ComparisonCell{}
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
         return ComparisonCell{}
             .Add(total > 0, "%.3f", Share(s.confidence_histogram[9], total))
             .Add(total > 0, "%.3f", Share(low, total))
             .Text();
       }},
      {"left/right swaps",
       [](const DetectorStats& s) { return ComparisonCell{}.Add(s.swap_candidates > 0, "%.3f", s.swap_rate).Text(); }},
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
         return ComparisonCell{}
             .Add(down_n > 0, "%+.3f", down_n > 0 ? down / down_n : 0)
             .Add(out_n > 0, "%+.3f", out_n > 0 ? out / out_n : 0)
             .Text();
       }},
      {"truncated persons",
       [](const DetectorStats& s) {
         return ComparisonCell{}.Add(s.persons_in_view > 0, "%.3f", s.truncated_share).Text();
       }},
      {"false positives: mean confidence / reported joints",
       [](const DetectorStats& s) {
         const bool any = s.total.false_positives > 0;
         return ComparisonCell{}
             .Add(any, "%.2f", s.false_positive_confidence_mean)
             .Add(any, "%.1f", s.false_positive_joints_mean)
             .Text();
       }},
      {"box diagonal, median px",
       [](const DetectorStats& s) {
         return ComparisonCell{}.Add(s.persons_in_view > 0, "%.0f", s.box_diagonal_px_median).Text();
       }},
  };
  return rows;
}

}  // namespace

void PrintDetectorStatsComparison(const std::vector<DetectorStatsColumn>& columns, const std::string& input, uint64_t seed) {
  std::printf("# Detector statistics: %s, against simulated detectors (seed %llu)\n\n", MarkdownText(input).c_str(),
              static_cast<unsigned long long>(seed));
  std::printf("The simulated detectors run on the input's ground truth and cameras. Statistic joints: %s",
              MarkdownText(Join(columns.front().stats.joints)).c_str());
  for (size_t c = 1; c < columns.size(); ++c) {
    if (columns[c].stats.joints != columns.front().stats.joints) {
      std::printf("; %s: %s", MarkdownText(columns[c].name).c_str(),
                  MarkdownText(Join(columns[c].stats.joints)).c_str());
    }
  }
  std::printf(". Errors in box units (the projected GT statistic joints, clipped to the image).\n\n");

  std::printf("| statistic |");
  for (const DetectorStatsColumn& c : columns) std::printf(" %s |", MarkdownText(c.name).c_str());
  std::printf("\n|---|");
  for (size_t c = 0; c < columns.size(); ++c) std::printf("---:|");
  std::printf("\n");
  for (const auto& [name, value] : CompareRows()) {
    std::printf("| %s |", name);
    for (const DetectorStatsColumn& c : columns) std::printf(" %s |", value(c.stats).c_str());
    std::printf("\n");
  }

  // Per joint: the columns' values side by side in each cell.
  std::vector<std::string> names;
  for (const DetectorStatsColumn& c : columns) names.push_back(c.name);
  std::vector<std::string> joints;
  for (const DetectorStatsColumn& c : columns) {
    for (const detector_stats::JointStats& p : c.stats.per_joint) {
      if (std::find(joints.begin(), joints.end(), p.joint) == joints.end()) joints.push_back(p.joint);
    }
  }
  std::printf("\nPer joint (%s; offsets: medians, down = along shoulders->hips, out = away from the midline):\n\n",
              MarkdownText(Join(names, " / ")).c_str());
  std::printf("| joint | error median | missing | hidden | missing when hidden | confidence | offset down | offset out |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& joint : joints) {
    ComparisonCell error, missing, hidden, hidden_missing, confidence, down, out;
    for (const DetectorStatsColumn& c : columns) {
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
    auto percent = [](const ComparisonCell& cell) {
      const std::string text = cell.Text();
      return text == "-" ? text : text + " %";
    };
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", MarkdownText(joint).c_str(), error.Text().c_str(),
                percent(missing).c_str(), percent(hidden).c_str(), percent(hidden_missing).c_str(),
                confidence.Text().c_str(), down.Text().c_str(), out.Text().c_str());
  }

  std::printf("\nConfidence histogram (%% of the reported joints of detected persons, bins of 0.1):\n\n|");
  for (int b = 0; b < 10; ++b) std::printf(" | %.1f", b / 10.0);
  std::printf(" |\n|---|");
  for (int b = 0; b < 10; ++b) std::printf("---:|");
  std::printf("\n");
  for (const DetectorStatsColumn& c : columns) {
    long total = 0;
    for (long n : c.stats.confidence_histogram) total += n;
    std::printf("| %s |", c.name.c_str());
    for (long n : c.stats.confidence_histogram) std::printf(" %.1f |", 100.0 * Share(n, total));
    std::printf("\n");
  }
}

}  // namespace rpt::engine
