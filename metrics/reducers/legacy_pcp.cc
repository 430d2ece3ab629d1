// SPDX-License-Identifier: MIT
// Legacy (Shelf/Campus) PCP: the per-actor counts of LegacyPcpEvaluator, fed frame by frame.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void LegacyPcpTotals::Fold(const FrameRecords& frame) {
  if (evaluator) evaluator->AddFrame(frame.legacy_actors, frame.legacy_predictions);
}

void LegacyPcpTotals::Merge(const LegacyPcpTotals& other) {
  if (evaluator && other.evaluator) evaluator->Merge(*other.evaluator);
}

void ReduceLegacyPcp(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  if (totals.legacy_pcp.evaluator) result->legacy_pcp = totals.legacy_pcp.evaluator->Finalize();
}

}  // namespace rpt::metrics
