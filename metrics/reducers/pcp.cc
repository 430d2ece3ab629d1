// SPDX-License-Identifier: MIT
// Generic PCP, pooled over all evaluable parts of all GT persons, against each GT's nearest
// prediction or its matched prediction (EvalOptions::pcp_matching).
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReducePcp(const EvalRecords& records, const MatchSets& matches, const EvalOptions& options,
               MetricsResult* result) {
  const size_t num_parts = records.pcp_total.size();
  std::vector<int> correct_matched(num_parts, 0);
  for (size_t r = 0; r < records.pairs.size(); ++r) {
    if (!matches.at_gate[r]) continue;
    const std::vector<PartOutcome>& outcomes = records.pairs[r].pcp;
    for (size_t k = 0; k < outcomes.size(); ++k) {
      if (outcomes[k] == PartOutcome::kCorrect) ++correct_matched[k];
    }
  }
  const bool nearest = options.pcp_matching == PcpMatching::kNearest;
  int correct = 0, total = 0;
  result->pcp_parts.clear();
  for (size_t k = 0; k < num_parts; ++k) {
    PcpPartResult part;
    part.name = GenericPcpParts()[k].name;
    part.correct = nearest ? records.pcp_correct_nearest[k] : correct_matched[k];
    part.total = records.pcp_total[k];
    part.pcp = Percent(part.correct, part.total);
    correct += part.correct;
    total += part.total;
    result->pcp_parts.push_back(part);
  }
  result->pcp = Percent(correct, total);
}

}  // namespace rpt::metrics
