// SPDX-License-Identifier: MIT
// Invalid: counted predictions that are not matches at the gate, over counted predictions; and
// those predictions by cause (InvalidCauses), from each one's nearest-GT pair.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void InvalidTotals::Fold(const FrameRecords& frame) {
  if (!frame.counted) return;
  for (int p = 0; p < frame.num_predictions; ++p) {
    if (IsMatchedPrediction(frame, p)) continue;
    const PairRecord& nearest = frame.pairs[p];  // prediction p's nearest-GT pair
    if (nearest.gt_idx < 0) {
      ++causes.no_gt;
    } else if (nearest.error_mm < gate_mm) {
      ++causes.duplicate;
    } else if (nearest.error_mm < 2 * gate_mm) {
      ++(IsMatchedGt(frame, nearest.gt_idx) ? causes.near_matched_gt : causes.near_missed_gt);
    } else {
      ++causes.far_from_gt;
    }
  }
}

void InvalidTotals::Merge(const InvalidTotals& other) {
  causes.duplicate += other.causes.duplicate;
  causes.near_matched_gt += other.causes.near_matched_gt;
  causes.near_missed_gt += other.causes.near_missed_gt;
  causes.far_from_gt += other.causes.far_from_gt;
  causes.no_gt += other.causes.no_gt;
}

void ReduceInvalid(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const int false_positives = totals.counts.num_pred_counted - totals.counts.num_matches;
  result->invalid = Percent(false_positives, totals.counts.num_pred_counted);
  result->invalid_causes = totals.invalid.causes;
}

}  // namespace rpt::metrics
