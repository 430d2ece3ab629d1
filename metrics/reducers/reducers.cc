// SPDX-License-Identifier: MIT
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

MetricTotals::MetricTotals(const EvalOptions& options) {
  const size_t num_joints = options.EvaluatedJoints().size();
  const size_t num_parts = GenericPcpParts().size();
  const size_t num_groups = options.wholebody_groups ? WholeBodyGroups().size() : 0;
  counts.gt_valid_per_joint.assign(num_joints, 0);
  invalid.gate_mm = options.match_threshold_mm;
  per_joint.error_sum_mm.assign(num_joints, 0.0);
  per_joint.error_count.assign(num_joints, 0);
  per_joint.hits_100.assign(num_joints, 0);
  per_joint.matched_gt.assign(num_joints, 0);
  pcp.total.assign(num_parts, 0);
  pcp.correct_nearest.assign(num_parts, 0);
  pcp.correct_matched.assign(num_parts, 0);
  if (options.legacy_pcp != LegacyPcpLayout::kNone) legacy_pcp.evaluator.emplace(options);
  wholebody.sum_mm.assign(num_groups, 0.0);
  wholebody.count.assign(num_groups, 0);
  wholebody.joints.assign(num_groups, 0);
  wholebody.filled.assign(num_groups, 0);
}

void MetricTotals::Fold(const FrameRecords& frame) {
  counts.Fold(frame);
  recall.Fold(frame);
  invalid.Fold(frame);
  mpjpe.Fold(frame);
  pck.Fold(frame);
  per_joint.Fold(frame);
  ap.Fold(frame);
  pcp.Fold(frame);
  legacy_pcp.Fold(frame);
  wholebody.Fold(frame);
}

void MetricTotals::Merge(const MetricTotals& other) {
  counts.Merge(other.counts);
  recall.Merge(other.recall);
  invalid.Merge(other.invalid);
  mpjpe.Merge(other.mpjpe);
  pck.Merge(other.pck);
  per_joint.Merge(other.per_joint);
  ap.Merge(other.ap);
  pcp.Merge(other.pcp);
  legacy_pcp.Merge(other.legacy_pcp);
  wholebody.Merge(other.wholebody);
}

std::span<const MetricReducer> MetricReducers() {
  static constexpr MetricReducer kReducers[] = {
      ReduceCounts, ReduceRecall,  ReduceInvalid, ReduceF1,        ReduceMpjpe,     ReducePck,
      ReducePerJoint, ReduceAp,    ReducePcp,     ReduceLegacyPcp, ReduceWholeBody,
  };
  return kReducers;
}

}  // namespace rpt::metrics
