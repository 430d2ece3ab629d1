// SPDX-License-Identifier: MIT
// The counts of MetricsResult: frames, GT persons, predictions, matches at the gate.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceCounts(const EvalRecords& records, const MatchSets& matches, const EvalOptions&, MetricsResult* result) {
  result->num_frames = records.num_frames;
  result->num_frames_with_gt = records.num_frames_with_gt;
  result->num_gt_persons = records.num_gt;
  result->num_dropped_gt_persons = records.num_dropped_gt;
  result->num_predictions = records.num_pred_counted;
  result->num_predictions_total = records.num_pred_total;
  result->num_matches = CountMatches(matches.at_gate);
}

}  // namespace rpt::metrics
