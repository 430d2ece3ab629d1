// SPDX-License-Identifier: MIT
// Invalid: counted predictions that are not matches at the gate, over counted predictions.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceInvalid(const EvalRecords& records, const MatchSets& matches, const EvalOptions&, MetricsResult* result) {
  const int false_positives = records.num_pred_counted - CountMatches(matches.at_gate);
  result->invalid = Percent(false_positives, records.num_pred_counted);
}

}  // namespace rpt::metrics
