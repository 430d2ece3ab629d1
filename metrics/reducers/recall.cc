// SPDX-License-Identifier: MIT
// Recall@100 / @500: GT persons matched at 100 / 500 mm, over all kept GT persons.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void RecallTotals::Fold(const FrameRecords& frame) {
  for (const PairRecord& pair : frame.pairs) {
    num_matches_100 += (pair.flags & kMatch100) ? 1 : 0;
    num_matches_500 += (pair.flags & kMatch500) ? 1 : 0;
  }
}

void RecallTotals::Merge(const RecallTotals& other) {
  num_matches_100 += other.num_matches_100;
  num_matches_500 += other.num_matches_500;
}

void ReduceRecall(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  result->recall_100 = Percent(totals.recall.num_matches_100, totals.counts.num_gt);
  result->recall_500 = Percent(totals.recall.num_matches_500, totals.counts.num_gt);
}

}  // namespace rpt::metrics
