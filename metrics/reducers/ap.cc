// SPDX-License-Identifier: MIT
// AP at kApThresholdsMm over the counted nearest-GT records (VoxelPose protocol, whatever the matching).
#include "metrics/average_precision.h"
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceAp(const EvalRecords& records, const MatchSets&, const EvalOptions&, MetricsResult* result) {
  std::vector<MatchRecord> ap_records;
  for (const PairRecord& record : records.pairs) {
    if ((record.flags & kNearest) && record.counted) ap_records.push_back(record.match);
  }
  for (size_t k = 0; k < kApThresholdsMm.size(); ++k) {
    result->ap[k] = 100.0 * AveragePrecision(ap_records, records.num_gt, kApThresholdsMm[k]);
  }
}

}  // namespace rpt::metrics
