// SPDX-License-Identifier: MIT
// `rpt detector-stats`: how the 2D detections of an input err against its projected ground
// truth (datasets/detector_stats/statistics.h), as markdown tables or JSON. Works on real
// detections and on simulated ones (--simulate --detector PROFILE), which is how the simulated
// detector is fitted to real ones (docs/detector_model.md).
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli/load_input.h"
#include "core/text.h"
#include "datasets/detector_stats/statistics.h"

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

void RunDetectorStats(const DetectorStatsArgs& args) {
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = LoadInput(args.input, /*require_detections=*/true, &input_warnings);
  PrintInputWarnings(input_warnings);
  detector_stats::StatsOptions options;
  std::stringstream list(args.joints);
  for (std::string item; std::getline(list, item, ',');) {
    if (!item.empty()) options.joints.push_back(item);
  }
  options.association.gate_relative = args.gate;
  options.min_joints_in_image = args.min_joints_in_image;
  detector_stats::StatsAccumulator accumulator(options);
  for (const Sequence& sequence : sequences) accumulator.Add(sequence);
  const DetectorStats stats = accumulator.Finalize();
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
  command->add_flag("--json", args->json, "print the statistics as JSON");
  command->callback([args] { RunDetectorStats(*args); });
}

}  // namespace rpt::cli
