// SPDX-License-Identifier: MIT
// PCK@100 / @500: GT-valid joints of matched pairs with error strictly below 100 / 500 mm, over all
// GT-valid joints (pck_denominator all_gt) or those of matched pairs (matched); also counts the
// GT-valid joints of matched pairs that the prediction lacks.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReducePck(const EvalRecords& records, const MatchSets& matches, const EvalOptions& options,
               MetricsResult* result) {
  int hits_100 = 0, hits_500 = 0, matched_valid = 0, missing = 0;
  for (size_t r = 0; r < records.pairs.size(); ++r) {
    if (!matches.at_gate[r]) continue;
    const Eigen::ArrayXd& errors = records.pairs[r].joint_errors;
    for (Eigen::Index j = 0; j < errors.size(); ++j) {
      const double e = errors(j);
      if (std::isnan(e)) continue;  // GT-invalid
      ++matched_valid;
      if (std::isinf(e)) ++missing;
      if (e < 100.0) ++hits_100;
      if (e < 500.0) ++hits_500;
    }
  }
  int all_valid = 0;
  for (const int n : records.gt_valid_per_joint) all_valid += n;
  const int denominator = options.pck_denominator == PckDenominator::kAllGt ? all_valid : matched_valid;
  result->pck_100 = Percent(hits_100, denominator);
  result->pck_500 = Percent(hits_500, denominator);
  result->num_missing_pred_joints = missing;
}

}  // namespace rpt::metrics
