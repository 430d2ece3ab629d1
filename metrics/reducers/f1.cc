// SPDX-License-Identifier: MIT
// F1 at the gate: 2 TP / (2 TP + FP + FN).
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceF1(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const int tp = totals.counts.num_matches;
  const int fp = totals.counts.num_pred_counted - tp;
  const int fn = totals.counts.num_gt - tp;
  result->f1 = Percent(2.0 * tp, 2.0 * tp + fp + fn);
}

}  // namespace rpt::metrics
