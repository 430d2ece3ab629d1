// SPDX-License-Identifier: MIT
// MPJPE: mean over the matched pairs of the per-person MPJPE (aligned if set); pairs that cannot be
// aligned are counted in num_unaligned_matches and left out.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void MpjpeTotals::Fold(const FrameRecords& frame) {
  for (const PairRecord& pair : frame.pairs) {
    if (!(pair.flags & kMatch)) continue;
    if (std::isnan(pair.report_error_mm)) {
      ++num_unaligned;
    } else {
      sum_mm += pair.report_error_mm;
      ++count;
    }
  }
}

void MpjpeTotals::Merge(const MpjpeTotals& other) {
  sum_mm += other.sum_mm;
  count += other.count;
  num_unaligned += other.num_unaligned;
}

void ReduceMpjpe(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const MpjpeTotals& mpjpe = totals.mpjpe;
  result->mpjpe_mm = mpjpe.count > 0 ? mpjpe.sum_mm / mpjpe.count : kNaN;
  result->num_unaligned_matches = mpjpe.num_unaligned;
}

}  // namespace rpt::metrics
