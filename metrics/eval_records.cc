// SPDX-License-Identifier: MIT
#include "metrics/eval_records.h"

#include <algorithm>

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

bool IsMatchedPrediction(const FrameRecords& frame, int p) {
  return std::any_of(frame.pairs.begin(), frame.pairs.end(),
                     [p](const PairRecord& pair) { return pair.pred_idx == p && (pair.flags & kMatch) != 0; });
}

bool IsMatchedGt(const FrameRecords& frame, int g) {
  return std::any_of(frame.pairs.begin(), frame.pairs.end(),
                     [g](const PairRecord& pair) { return pair.gt_idx == g && (pair.flags & kMatch) != 0; });
}

}  // namespace rpt::metrics
