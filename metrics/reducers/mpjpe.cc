// SPDX-License-Identifier: MIT
// MPJPE: mean over the matched pairs of the per-person MPJPE (aligned if set); pairs that cannot be
// aligned are counted in num_unaligned_matches and left out.
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ReduceMpjpe(const EvalRecords& records, const MatchSets& matches, const EvalOptions&, MetricsResult* result) {
  double sum = 0.0;
  int count = 0;
  int unaligned = 0;
  for (size_t r = 0; r < records.pairs.size(); ++r) {
    if (!matches.at_gate[r]) continue;
    const double error = records.pairs[r].report_error_mm;
    if (std::isnan(error)) {
      ++unaligned;
    } else {
      sum += error;
      ++count;
    }
  }
  result->mpjpe_mm = count > 0 ? sum / count : kNaN;
  result->num_unaligned_matches = unaligned;
}

}  // namespace rpt::metrics
