// SPDX-License-Identifier: MIT
// Generic PCP, pooled over all evaluable parts of all GT persons, against each GT's nearest
// prediction or its matched prediction (EvalOptions::pcp_matching).
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void PcpTotals::Fold(const FrameRecords& frame) {
  for (const std::vector<PartOutcome>& outcomes : frame.pcp_nearest) {
    for (size_t k = 0; k < outcomes.size(); ++k) {
      if (outcomes[k] == PartOutcome::kNotEvaluated) continue;
      ++total[k];
      if (outcomes[k] == PartOutcome::kCorrect) ++correct_nearest[k];
    }
  }
  for (const PairRecord& pair : frame.pairs) {
    if (!(pair.flags & kMatch)) continue;
    for (size_t k = 0; k < pair.pcp.size(); ++k) {
      if (pair.pcp[k] == PartOutcome::kCorrect) ++correct_matched[k];
    }
  }
}

void PcpTotals::Merge(const PcpTotals& other) {
  for (size_t k = 0; k < total.size(); ++k) {
    total[k] += other.total[k];
    correct_nearest[k] += other.correct_nearest[k];
    correct_matched[k] += other.correct_matched[k];
  }
}

void ReducePcp(const MetricTotals& totals, const EvalOptions& options, MetricsResult* result) {
  const PcpTotals& pcp = totals.pcp;
  const bool nearest = options.pcp_matching == PcpMatching::kNearest;
  int correct = 0, total = 0;
  result->pcp_parts.clear();
  for (size_t k = 0; k < pcp.total.size(); ++k) {
    PcpPartResult part;
    part.name = GenericPcpParts()[k].name;
    part.correct = nearest ? pcp.correct_nearest[k] : pcp.correct_matched[k];
    part.total = pcp.total[k];
    part.pcp = Percent(part.correct, part.total);
    correct += part.correct;
    total += part.total;
    result->pcp_parts.push_back(part);
  }
  result->pcp = Percent(correct, total);
}

}  // namespace rpt::metrics
