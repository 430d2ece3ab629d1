// SPDX-License-Identifier: MIT
#include "metrics/eval_records.h"

namespace rpt::metrics {

std::vector<MatchRecord> NearestMatchRecords(const FrameRecords& frame) {
  std::vector<MatchRecord> records;
  records.reserve(frame.num_predictions);
  for (int p = 0; p < frame.num_predictions; ++p) {
    const PairRecord& pair = frame.pairs[p];
    records.push_back(MatchRecord{pair.gt_idx, pair.error_mm, pair.score});
  }
  return records;
}

}  // namespace rpt::metrics
