// SPDX-License-Identifier: MIT
// AP at kApThresholdsMm over the counted nearest-GT records (VoxelPose protocol, whatever the matching).
// A record's true-positive flag at a threshold is its frame's greedy matching (a record competes
// only with the records of its GT person, all in its frame); the ranking is over the whole run.
#include <algorithm>
#include <numeric>

#include "metrics/average_precision.h"
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

void ApTotals::Fold(const FrameRecords& frame) {
  if (!frame.counted) return;
  const std::vector<MatchRecord> nearest = NearestMatchRecords(frame);
  const size_t first = entries.size();
  for (const MatchRecord& record : nearest) entries.push_back(Entry{record.score, record.error_mm, 0});
  for (size_t k = 0; k < kApThresholdsMm.size(); ++k) {
    const std::vector<bool> is_tp = GreedyMatch(nearest, kApThresholdsMm[k]);
    for (size_t i = 0; i < is_tp.size(); ++i) {
      if (is_tp[i]) entries[first + i].is_tp |= static_cast<std::uint8_t>(1u << k);
    }
  }
}

void ApTotals::Merge(const ApTotals& other) {
  entries.insert(entries.end(), other.entries.begin(), other.entries.end());
}

void ReduceAp(const MetricTotals& totals, const EvalOptions&, MetricsResult* result) {
  const std::deque<ApTotals::Entry>& entries = totals.ap.entries;
  // RankRecords() over the entries: score descending, error ascending, then the order added.
  std::vector<int> order(entries.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return RanksBefore(entries[a].score, entries[a].error_mm, entries[b].score, entries[b].error_mm);
  });
  std::vector<bool> ranked_is_tp(order.size());
  for (size_t k = 0; k < kApThresholdsMm.size(); ++k) {
    for (size_t i = 0; i < order.size(); ++i) ranked_is_tp[i] = (entries[order[i]].is_tp >> k) & 1u;
    result->ap[k] = 100.0 * RankedAveragePrecision(ranked_is_tp, totals.counts.num_gt);
  }
}

}  // namespace rpt::metrics
