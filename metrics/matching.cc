// SPDX-License-Identifier: MIT
#include "metrics/matching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rpt::metrics {
namespace {

// Minimum-cost assignment of every row to a distinct column (rows <= cols), O(rows^2 * cols).
// Shortest augmenting paths with potentials (Jonker-Volgenant style Hungarian method).
std::vector<int> SolveAssignment(const Eigen::MatrixXd& cost) {
  const int n = static_cast<int>(cost.rows());
  const int m = static_cast<int>(cost.cols());
  const double kInf = std::numeric_limits<double>::infinity();
  // 1-based arrays; column 0 is a virtual start column.
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> row_of_col(m + 1, 0), way(m + 1, 0);
  for (int i = 1; i <= n; ++i) {
    row_of_col[0] = i;
    int col0 = 0;
    std::vector<double> min_to(m + 1, kInf);
    std::vector<bool> used(m + 1, false);
    do {
      used[col0] = true;
      const int i0 = row_of_col[col0];
      double delta = kInf;
      int col1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double reduced = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (reduced < min_to[j]) {
          min_to[j] = reduced;
          way[j] = col0;
        }
        if (min_to[j] < delta) {
          delta = min_to[j];
          col1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[row_of_col[j]] += delta;
          v[j] -= delta;
        } else {
          min_to[j] -= delta;
        }
      }
      col0 = col1;
    } while (row_of_col[col0] != 0);
    do {
      const int col1 = way[col0];
      row_of_col[col0] = row_of_col[col1];
      col0 = col1;
    } while (col0 != 0);
  }
  std::vector<int> col_of_row(n, -1);
  for (int j = 1; j <= m; ++j) {
    if (row_of_col[j] > 0) col_of_row[row_of_col[j] - 1] = j - 1;
  }
  return col_of_row;
}

}  // namespace

std::vector<int> NearestGt(const Eigen::MatrixXd& cost) {
  std::vector<int> nearest(cost.rows(), -1);
  for (Eigen::Index p = 0; p < cost.rows(); ++p) {
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index g = 0; g < cost.cols(); ++g) {
      if (cost(p, g) < best) {  // false for NaN and +inf
        best = cost(p, g);
        nearest[p] = static_cast<int>(g);
      }
    }
  }
  return nearest;
}

std::vector<int> NearestPrediction(const Eigen::MatrixXd& cost) {
  return NearestGt(cost.transpose());
}

std::vector<int> RankRecords(std::span<const MatchRecord> records) {
  std::vector<int> order(records.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return RanksBefore(records[a].score, records[a].error_mm, records[b].score, records[b].error_mm);
  });
  return order;
}

std::vector<bool> GreedyMatch(std::span<const MatchRecord> records, double threshold_mm) {
  std::vector<bool> is_tp(records.size(), false);
  std::vector<bool> gt_taken;
  for (const int r : RankRecords(records)) {
    const MatchRecord& record = records[r];
    if (record.gt_id < 0 || !(record.error_mm < threshold_mm)) continue;
    if (static_cast<size_t>(record.gt_id) >= gt_taken.size()) gt_taken.resize(record.gt_id + 1, false);
    if (gt_taken[record.gt_id]) continue;
    gt_taken[record.gt_id] = true;
    is_tp[r] = true;
  }
  return is_tp;
}

std::vector<int> HungarianMatch(const Eigen::MatrixXd& cost, double gate_mm) {
  const Eigen::Index num_pred = cost.rows();
  const Eigen::Index num_gt = cost.cols();
  std::vector<int> assignment(num_pred, -1);
  if (num_pred == 0 || num_gt == 0) return assignment;

  // Pairs at or above the gate (and +inf / NaN) get a "forbidden" cost so large that one more
  // admissible pair always lowers the total: every admissible cost is < gate' (the largest admissible
  // cost + 1), and at most k = min(rows, cols) pairs exist, so big = gate' * (k + 1) suffices.
  double max_admissible = 0.0;
  for (Eigen::Index p = 0; p < num_pred; ++p) {
    for (Eigen::Index g = 0; g < num_gt; ++g) {
      if (cost(p, g) < gate_mm) max_admissible = std::max(max_admissible, cost(p, g));
    }
  }
  const double big = (max_admissible + 1.0) * static_cast<double>(std::min(num_pred, num_gt) + 1);
  Eigen::MatrixXd gated(num_pred, num_gt);
  for (Eigen::Index p = 0; p < num_pred; ++p) {
    for (Eigen::Index g = 0; g < num_gt; ++g) gated(p, g) = cost(p, g) < gate_mm ? cost(p, g) : big;
  }

  const bool transpose = num_pred > num_gt;  // the solver needs rows <= cols
  const std::vector<int> solved = SolveAssignment(transpose ? Eigen::MatrixXd(gated.transpose()) : gated);
  for (size_t r = 0; r < solved.size(); ++r) {
    const int c = solved[r];
    if (c < 0) continue;
    const int p = transpose ? c : static_cast<int>(r);
    const int g = transpose ? static_cast<int>(r) : c;
    if (cost(p, g) < gate_mm) assignment[p] = g;
  }
  return assignment;
}

}  // namespace rpt::metrics
