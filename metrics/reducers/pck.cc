// SPDX-License-Identifier: MIT
// PCK@100 / @500: GT-valid joints of matched pairs with error strictly below 100 / 500 mm, over all
// GT-valid joints (pck_denominator all_gt) or those of matched pairs (matched); also counts the
// GT-valid joints of matched pairs that the prediction lacks.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void PckTotals::Fold(const FrameRecords& frame) {
  for (const PairRecord& pair : frame.pairs) {
    if (!(pair.flags & kMatch)) continue;
    for (const double e : pair.joint_errors) {
      if (std::isnan(e)) continue;  // GT-invalid
      ++matched_valid;
      if (std::isinf(e)) ++missing;
      if (e < 100.0) ++hits_100;
      if (e < 500.0) ++hits_500;
    }
  }
}

void PckTotals::Merge(const PckTotals& other) {
  hits_100 += other.hits_100;
  hits_500 += other.hits_500;
  matched_valid += other.matched_valid;
  missing += other.missing;
}

void ReducePck(const MetricTotals& totals, const EvalOptions& options, MetricsResult* result) {
  int all_valid = 0;
  for (const int n : totals.counts.gt_valid_per_joint) all_valid += n;
  const PckTotals& pck = totals.pck;
  const int denominator = options.pck_denominator == PckDenominator::kAllGt ? all_valid : pck.matched_valid;
  result->pck_100 = Percent(pck.hits_100, denominator);
  result->pck_500 = Percent(pck.hits_500, denominator);
  result->num_missing_pred_joints = pck.missing;
}

}  // namespace rpt::metrics
