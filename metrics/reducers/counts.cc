// SPDX-License-Identifier: MIT
// The counts of MetricsResult: frames, GT persons, predictions, matches at the gate.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void CountTotals::Fold(const FrameRecords& frame) {
  ++num_frames;
  if (!frame.gt.empty()) ++num_frames_with_gt;
  num_gt += static_cast<int>(frame.gt.size());
  num_dropped_gt += frame.num_dropped_gt;
  num_pred_total += frame.num_predictions;
  if (frame.counted) num_pred_counted += frame.num_predictions;
  for (const PairRecord& pair : frame.pairs) num_matches += (pair.flags & kMatch) ? 1 : 0;
  for (const EvalPerson& person : frame.gt) {
    for (Eigen::Index j = 0; j < person.valid.size(); ++j) gt_valid_per_joint[j] += person.valid(j) ? 1 : 0;
  }
}

void CountTotals::Merge(const CountTotals& other) {
  num_frames += other.num_frames;
  num_frames_with_gt += other.num_frames_with_gt;
  num_gt += other.num_gt;
  num_dropped_gt += other.num_dropped_gt;
  num_pred_counted += other.num_pred_counted;
  num_pred_total += other.num_pred_total;
  num_matches += other.num_matches;
  for (size_t j = 0; j < gt_valid_per_joint.size(); ++j) gt_valid_per_joint[j] += other.gt_valid_per_joint[j];
}

void ReduceCounts(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const CountTotals& counts = totals.counts;
  result->num_frames = counts.num_frames;
  result->num_frames_with_gt = counts.num_frames_with_gt;
  result->num_gt_persons = counts.num_gt;
  result->num_dropped_gt_persons = counts.num_dropped_gt;
  result->num_predictions = counts.num_pred_counted;
  result->num_predictions_total = counts.num_pred_total;
  result->num_matches = counts.num_matches;
}

}  // namespace rpt::metrics
