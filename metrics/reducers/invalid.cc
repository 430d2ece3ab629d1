// SPDX-License-Identifier: MIT
// Invalid: counted predictions that are not matches at the gate, over counted predictions.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceInvalid(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const int false_positives = totals.counts.num_pred_counted - totals.counts.num_matches;
  result->invalid = Percent(false_positives, totals.counts.num_pred_counted);
}

}  // namespace rpt::metrics
