// SPDX-License-Identifier: MIT
#include "metrics/average_precision.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace rpt::metrics {

double AveragePrecision(std::span<const MatchRecord> records, int num_gt, double threshold_mm) {
  const std::vector<int> order = RankRecords(records);
  const std::vector<bool> is_tp = GreedyMatch(records, threshold_mm);
  std::vector<bool> ranked_is_tp(order.size());
  for (size_t i = 0; i < order.size(); ++i) ranked_is_tp[i] = is_tp[order[i]];
  return RankedAveragePrecision(ranked_is_tp, num_gt);
}

double RankedAveragePrecision(const std::vector<bool>& ranked_is_tp, int num_gt) {
  if (num_gt <= 0) return std::numeric_limits<double>::quiet_NaN();
  if (ranked_is_tp.empty()) return 0.0;
  const size_t n = ranked_is_tp.size();
  std::vector<double> precision(n);
  int tp = 0;
  for (size_t i = 0; i < n; ++i) {
    tp += ranked_is_tp[i] ? 1 : 0;
    precision[i] = static_cast<double>(tp) / static_cast<double>(i + 1);
  }
  for (size_t i = n - 1; i-- > 0;) precision[i] = std::max(precision[i], precision[i + 1]);

  double ap = 0.0;
  double previous_recall = 0.0;
  tp = 0;
  for (size_t i = 0; i < n; ++i) {
    tp += ranked_is_tp[i] ? 1 : 0;
    const double recall = static_cast<double>(tp) / num_gt;
    ap += (recall - previous_recall) * precision[i];
    previous_recall = recall;
  }
  return ap;
}

}  // namespace rpt::metrics
