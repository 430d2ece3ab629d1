// SPDX-License-Identifier: MIT
// F1 at the gate: 2 TP / (2 TP + FP + FN).
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceF1(const EvalRecords& records, const MatchSets& matches, const EvalOptions&, MetricsResult* result) {
  const int tp = CountMatches(matches.at_gate);
  const int fp = records.num_pred_counted - tp;
  const int fn = records.num_gt - tp;
  result->f1 = Percent(2.0 * tp, 2.0 * tp + fp + fn);
}

}  // namespace rpt::metrics
