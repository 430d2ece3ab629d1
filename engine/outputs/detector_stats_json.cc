// SPDX-License-Identifier: MIT
#include "engine/outputs/detector_stats_json.h"

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;
using detector_stats::DetectorStats;
using detector_stats::ErrorSummary;
using detector_stats::ViewStats;

OrderedJson SummaryJson(const ErrorSummary& s) {
  return OrderedJson{{"count", s.count}, {"median", s.median}, {"p90", s.p90}, {"p99", s.p99}, {"mean", s.mean}};
}

OrderedJson ViewJson(const ViewStats& v) {
  return OrderedJson{{"camera", v.camera},
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

}  // namespace

OrderedJson DetectorStatsJson(const DetectorStats& s) {
  OrderedJson j;
  j["joints"] = s.joints;
  j["box"] = "projected GT statistic joints, clipped to the image";
  j["views"] = OrderedJson::array();
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
    j["detection_by_label"][classes[c]] = OrderedJson{{"persons", s.persons_by_label[c]},
                                                      {"detected", s.detected_by_label[c]},
                                                      {"rate", s.detection_rate_by_label[c]}};
  }
  j["box_diagonal_px_median"] = s.box_diagonal_px_median;
  j["box_diagonal_px_median_truncated"] = s.box_diagonal_px_median_truncated;
  j["error"] = OrderedJson{{"all", SummaryJson(s.all)},
                           {"hidden", SummaryJson(s.hidden)},
                           {"clear_persons", SummaryJson(s.clear_persons)},
                           {"hidden_persons", SummaryJson(s.hidden_persons)},
                           {"confidence_low", SummaryJson(s.confidence_low)},
                           {"confidence_mid", SummaryJson(s.confidence_mid)},
                           {"confidence_high", SummaryJson(s.confidence_high)}};
  j["by_visibility"] = OrderedJson::object();
  for (int v = 0; v < detector_stats::kNumVisibilities; ++v) {
    const detector_stats::VisibilityStats& b = s.by_visibility[v];
    j["by_visibility"][detector_stats::VisibilityName(v)] =
        OrderedJson{{"joints", b.joints},
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
  j["per_joint"] = OrderedJson::array();
  for (const detector_stats::JointStats& p : s.per_joint) {
    j["per_joint"].push_back(OrderedJson{{"joint", p.joint},
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

}  // namespace rpt::engine
