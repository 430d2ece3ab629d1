// SPDX-License-Identifier: MIT
// Recall@100 / @500: GT persons matched at 100 / 500 mm, over all kept GT persons.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceRecall(const EvalRecords& records, const MatchSets& matches, const EvalOptions&, MetricsResult* result) {
  result->recall_100 = Percent(CountMatches(matches.at_100), records.num_gt);
  result->recall_500 = Percent(CountMatches(matches.at_500), records.num_gt);
}

}  // namespace rpt::metrics
