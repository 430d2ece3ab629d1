// SPDX-License-Identifier: MIT
// Legacy (Shelf/Campus) PCP: the per-actor counts collected frame by frame (LegacyPcpEvaluator).
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceLegacyPcp(const EvalRecords& records, const MatchSets&, const EvalOptions&, MetricsResult* result) {
  if (records.legacy) result->legacy_pcp = records.legacy->Finalize();
}

}  // namespace rpt::metrics
