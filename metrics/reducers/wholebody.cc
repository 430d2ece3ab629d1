// SPDX-License-Identifier: MIT
// Whole-body MPJPE per group (WholeBodyGroups()): mean over the matched pairs of each pair's mean
// group error.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceWholeBody(const EvalRecords& records, const MatchSets& matches, const EvalOptions& options,
                     MetricsResult* result) {
  result->wholebody.clear();
  if (!options.wholebody_groups) return;
  const size_t num_groups = WholeBodyGroups().size();
  std::vector<double> sum(num_groups, 0.0);
  std::vector<int> count(num_groups, 0);
  for (size_t r = 0; r < records.pairs.size(); ++r) {
    if (!matches.at_gate[r]) continue;
    const std::vector<double>& errors = records.pairs[r].group_errors;
    for (size_t k = 0; k < errors.size(); ++k) {
      if (std::isnan(errors[k])) continue;
      sum[k] += errors[k];
      ++count[k];
    }
  }
  for (size_t k = 0; k < num_groups; ++k) {
    GroupResult group;
    group.name = WholeBodyGroups()[k].name;
    group.num_persons = count[k];
    group.num_joints = records.group_num_joints[k];
    group.mpjpe_mm = count[k] > 0 ? sum[k] / count[k] : kNaN;
    result->wholebody.push_back(group);
  }
}

}  // namespace rpt::metrics
