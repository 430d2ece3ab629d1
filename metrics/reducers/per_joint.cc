// SPDX-License-Identifier: MIT
// Per evaluated joint: mean error over the matched pairs (aligned if set) and PCK@100.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void PerJointTotals::Fold(const FrameRecords& frame) {
  for (const PairRecord& pair : frame.pairs) {
    if (!(pair.flags & kMatch)) continue;
    for (size_t j = 0; j < error_sum_mm.size(); ++j) {
      const double e = pair.joint_errors(j);
      if (std::isnan(e)) continue;  // GT-invalid
      ++matched_gt[j];
      if (e < 100.0) ++hits_100[j];
      const double reported = pair.report_joint_errors(j);
      if (std::isfinite(reported)) {
        error_sum_mm[j] += reported;
        ++error_count[j];
      }
    }
  }
}

void PerJointTotals::Merge(const PerJointTotals& other) {
  for (size_t j = 0; j < error_sum_mm.size(); ++j) {
    error_sum_mm[j] += other.error_sum_mm[j];
    error_count[j] += other.error_count[j];
    hits_100[j] += other.hits_100[j];
    matched_gt[j] += other.matched_gt[j];
  }
}

void ReducePerJoint(const MetricTotals& totals, const EvalOptions& options, MetricsResult* result) {
  const PerJointTotals& per_joint = totals.per_joint;
  const JointNames& evaluated = options.EvaluatedJoints();
  const bool all_gt = options.pck_denominator == PckDenominator::kAllGt;
  result->joints.clear();
  for (size_t j = 0; j < evaluated.size(); ++j) {
    JointResult joint;
    joint.name = evaluated[j];
    joint.count = per_joint.error_count[j];
    joint.mean_error_mm = joint.count > 0 ? per_joint.error_sum_mm[j] / joint.count : kNaN;
    joint.num_gt = all_gt ? totals.counts.gt_valid_per_joint[j] : per_joint.matched_gt[j];
    joint.pck_100 = Percent(per_joint.hits_100[j], joint.num_gt);
    result->joints.push_back(joint);
  }
}

}  // namespace rpt::metrics
