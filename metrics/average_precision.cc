// SPDX-License-Identifier: MIT
#include "metrics/average_precision.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace rpt::metrics {

double AveragePrecision(std::span<const MatchRecord> records, int num_gt, double threshold_mm) {
  if (num_gt <= 0) return std::numeric_limits<double>::quiet_NaN();
  if (records.empty()) return 0.0;
  const std::vector<int> order = RankRecords(records);
  const std::vector<bool> is_tp = GreedyMatch(records, threshold_mm);

  const size_t n = order.size();
  std::vector<double> recall(n), precision(n);
  int tp = 0;
  for (size_t i = 0; i < n; ++i) {
    tp += is_tp[order[i]] ? 1 : 0;
    recall[i] = static_cast<double>(tp) / num_gt;
    precision[i] = static_cast<double>(tp) / static_cast<double>(i + 1);
  }
  for (size_t i = n - 1; i-- > 0;) precision[i] = std::max(precision[i], precision[i + 1]);

  double ap = 0.0;
  double previous_recall = 0.0;
  for (size_t i = 0; i < n; ++i) {
    ap += (recall[i] - previous_recall) * precision[i];
    previous_recall = recall[i];
  }
  return ap;
}

}  // namespace rpt::metrics
