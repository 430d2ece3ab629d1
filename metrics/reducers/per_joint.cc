// SPDX-License-Identifier: MIT
// Per evaluated joint: mean error over the matched pairs (aligned if set) and PCK@100.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReducePerJoint(const EvalRecords& records, const MatchSets& matches, const EvalOptions& options,
                    MetricsResult* result) {
  const size_t num_joints = records.evaluated.size();
  std::vector<double> error_sum(num_joints, 0.0);
  std::vector<int> error_count(num_joints, 0), hits_100(num_joints, 0), matched_gt(num_joints, 0);
  for (size_t r = 0; r < records.pairs.size(); ++r) {
    if (!matches.at_gate[r]) continue;
    const PairRecord& record = records.pairs[r];
    for (size_t j = 0; j < num_joints; ++j) {
      const double e = record.joint_errors(j);
      if (std::isnan(e)) continue;  // GT-invalid
      ++matched_gt[j];
      if (e < 100.0) ++hits_100[j];
      const double reported = record.report_joint_errors(j);
      if (std::isfinite(reported)) {
        error_sum[j] += reported;
        ++error_count[j];
      }
    }
  }
  const bool all_gt = options.pck_denominator == PckDenominator::kAllGt;
  result->joints.clear();
  for (size_t j = 0; j < num_joints; ++j) {
    JointResult joint;
    joint.name = records.evaluated[j];
    joint.count = error_count[j];
    joint.mean_error_mm = joint.count > 0 ? error_sum[j] / joint.count : kNaN;
    joint.num_gt = all_gt ? records.gt_valid_per_joint[j] : matched_gt[j];
    joint.pck_100 = Percent(hits_100[j], joint.num_gt);
    result->joints.push_back(joint);
  }
}

}  // namespace rpt::metrics
