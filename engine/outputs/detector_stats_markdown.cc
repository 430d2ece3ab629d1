// SPDX-License-Identifier: MIT
#include "engine/outputs/detector_stats_markdown.h"

#include <cstdio>

#include "core/text.h"
#include "engine/outputs/text_escaping.h"

namespace rpt::engine {
namespace {

using detector_stats::DetectorStats;
using detector_stats::ErrorSummary;
using detector_stats::ViewStats;

std::string PercentOneDecimal(double fraction) {
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

}  // namespace

void PrintDetectorStatsMarkdown(const DetectorStats& s, const std::string& input) {
  std::printf("# Detector statistics: %s\n\n", MarkdownText(input).c_str());
  std::printf(
      "Statistic joints: %s. Box: the projected GT statistic joints, clipped to the image; errors are\n"
      "pixel distances divided by its diagonal (box units).\n\n",
      MarkdownText(Join(s.joints)).c_str());
  std::printf("## Detection per view\n\n");
  std::printf("| camera | views | GT persons in view | detected | rate | detections | exact duplicates | false positives | per view | near a GT person | on 2D-only persons |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto row = [](const ViewStats& v) {
    std::printf("| %s | %ld | %ld | %ld | %s | %ld | %ld | %ld | %.3f | %ld | %ld |\n", MarkdownText(v.camera).c_str(),
                v.views, v.gt_in_view, v.detected, PercentOneDecimal(v.detection_rate()).c_str(), v.detections,
                v.duplicates, v.false_positives, v.false_positives_per_view(), v.false_positives_near_gt,
                v.on_unlabelled);
  };
  for (const ViewStats& v : s.views) row(v);
  row(s.total);
  std::printf(
      "\nDetection rate by the 2D labels: mostly visible %s of %ld, mostly hidden %s of %ld, no labels %s of %ld.\n",
      PercentOneDecimal(s.detection_rate_by_label[0]).c_str(), s.persons_by_label[0],
      PercentOneDecimal(s.detection_rate_by_label[1]).c_str(), s.persons_by_label[1],
      PercentOneDecimal(s.detection_rate_by_label[2]).c_str(), s.persons_by_label[2]);

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
                PercentOneDecimal(labelled > 0 ? static_cast<double>(b.joints) / labelled : 0).c_str(),
                PercentOneDecimal(b.missing_rate()).c_str(), b.of_detected, b.confidence_mean);
  }

  std::printf("\n## Other statistics\n\n| statistic | value |\n|---|---|\n");
  std::printf("| missing joints (in-image GT joints of detected persons) | %s of %ld |\n",
              PercentOneDecimal(s.missing_rate).c_str(), s.joints_in_image);
  std::printf("| hidden share (occluded or not labelled, views with 2D labels) | %s |\n",
              PercentOneDecimal(s.hidden_share).c_str());
  std::printf("| truncated persons (a joint outside the image) | %s of %ld |\n",
              PercentOneDecimal(s.truncated_share).c_str(), s.persons_in_view);
  std::printf(
      "| GT persons detected in 0 / 1 / 2 / 3+ views (of %ld in view of a camera, per frame) | %s / %s / %s / %s |\n",
      s.persons_in_any_view, PercentOneDecimal(s.ShareDetectedInViews(0)).c_str(),
      PercentOneDecimal(s.ShareDetectedInViews(1)).c_str(), PercentOneDecimal(s.ShareDetectedInViews(2)).c_str(),
      PercentOneDecimal(s.ShareDetectedInViews(3)).c_str());
  std::printf("| box diagonal, median px (whole / truncated persons) | %.0f / %.0f |\n", s.box_diagonal_px_median,
              s.box_diagonal_px_median_truncated);
  std::printf("| left/right swaps (closer to the mirrored GT joint) | %s of %ld |\n",
              PercentOneDecimal(s.swap_rate).c_str(), s.swap_candidates);
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
  for (long n : s.confidence_histogram)
    std::printf(" %s |", PercentOneDecimal(total > 0 ? static_cast<double>(n) / total : 0).c_str());

  std::printf("\n\n## Per joint (box units; offsets: down = along shoulders->hips, out = away from the midline)\n\n");
  std::printf("| joint | count | median | p90 | missing | hidden | missing of hidden | confidence | down mean | down median | out mean | out median |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto share = [](long a, long b) { return PercentOneDecimal(b > 0 ? static_cast<double>(a) / b : 0); };
  for (const detector_stats::JointStats& p : s.per_joint) {
    std::printf("| %s | %ld | %.3f | %.3f | %s | %s | %s | %.3f | %+.3f | %+.3f | %+.3f | %+.3f |\n",
                MarkdownText(p.joint).c_str(), p.error.count, p.error.median, p.error.p90,
                share(p.missing, p.in_image).c_str(), share(p.hidden, p.in_image).c_str(),
                share(p.hidden_missing, p.hidden).c_str(), p.confidence_mean, p.down_mean, p.down_median, p.out_mean,
                p.out_median);
  }
}

}  // namespace rpt::engine
