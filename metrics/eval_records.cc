// SPDX-License-Identifier: MIT
#include "metrics/eval_records.h"

#include <utility>

namespace rpt::metrics {

MatchSets SelectMatches(const EvalRecords& records, const EvalOptions& options) {
  const std::vector<PairRecord>& pairs = records.pairs;
  MatchSets sets;
  sets.at_gate.assign(pairs.size(), false);
  sets.at_100.assign(pairs.size(), false);
  sets.at_500.assign(pairs.size(), false);
  if (options.matching == MatchingMode::kGreedy) {
    // The nearest-GT records drive greedy matching (as they drive AP).
    std::vector<size_t> nearest_idx;
    std::vector<MatchRecord> nearest_records;
    for (size_t r = 0; r < pairs.size(); ++r) {
      if (!(pairs[r].flags & kNearest)) continue;
      nearest_idx.push_back(r);
      nearest_records.push_back(pairs[r].match);
    }
    const std::pair<double, std::vector<bool>*> gates[] = {
        {options.match_threshold_mm, &sets.at_gate}, {100.0, &sets.at_100}, {500.0, &sets.at_500}};
    for (const auto& [threshold, set] : gates) {
      const std::vector<bool> is_tp = GreedyMatch(nearest_records, threshold);
      for (size_t i = 0; i < is_tp.size(); ++i) (*set)[nearest_idx[i]] = is_tp[i];
    }
  } else {
    for (size_t r = 0; r < pairs.size(); ++r) {
      sets.at_gate[r] = pairs[r].flags & kHungarianMatch;
      sets.at_100[r] = pairs[r].flags & kHungarian100;
      sets.at_500[r] = pairs[r].flags & kHungarian500;
    }
  }
  return sets;
}

int CountMatches(const std::vector<bool>& matched) {
  int count = 0;
  for (const bool m : matched) count += m ? 1 : 0;
  return count;
}

}  // namespace rpt::metrics
