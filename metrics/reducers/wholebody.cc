// SPDX-License-Identifier: MIT
// Whole-body MPJPE per group (WholeBodyGroups()): mean over the matched pairs of each pair's mean
// group error.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void WholeBodyTotals::Fold(const FrameRecords& frame) {
  if (!frame.group_num_joints.empty()) {
    group_num_joints = frame.group_num_joints;
    group_gt_only_joints = frame.group_gt_only_joints;
  }
  for (const PairRecord& pair : frame.pairs) {
    if (!(pair.flags & kMatch)) continue;
    for (size_t k = 0; k < pair.group_errors.size(); ++k) {
      if (std::isnan(pair.group_errors[k])) continue;
      sum_mm[k] += pair.group_errors[k];
      ++count[k];
      joints[k] += pair.group_joints[k];
      filled[k] += pair.group_filled[k];
    }
  }
}

void WholeBodyTotals::Merge(const WholeBodyTotals& other) {
  for (size_t k = 0; k < sum_mm.size(); ++k) {
    sum_mm[k] += other.sum_mm[k];
    count[k] += other.count[k];
    joints[k] += other.joints[k];
    filled[k] += other.filled[k];
  }
  if (!other.group_num_joints.empty()) {
    group_num_joints = other.group_num_joints;
    group_gt_only_joints = other.group_gt_only_joints;
  }
}

void ReduceWholeBody(const MetricTotals& totals, const EvalOptions& options, MetricsResult* result) {
  result->wholebody.clear();
  if (!options.wholebody_groups) return;
  const WholeBodyTotals& wholebody = totals.wholebody;
  for (size_t k = 0; k < WholeBodyGroups().size(); ++k) {
    GroupResult group;
    group.name = WholeBodyGroups()[k].name;
    group.num_persons = wholebody.count[k];
    group.num_joints = wholebody.group_num_joints.empty() ? 0 : wholebody.group_num_joints[k];
    group.num_gt_only_joints = wholebody.group_gt_only_joints.empty() ? 0 : wholebody.group_gt_only_joints[k];
    group.mpjpe_mm = wholebody.count[k] > 0 ? wholebody.sum_mm[k] / wholebody.count[k] : kNaN;
    group.filled_share = wholebody.joints[k] > 0 ? static_cast<double>(wholebody.filled[k]) / wholebody.joints[k] : 0.0;
    result->wholebody.push_back(group);
  }
}

}  // namespace rpt::metrics
