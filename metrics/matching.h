// SPDX-License-Identifier: MIT
// GT <-> prediction assignment.
//
// Cost matrices have one row per prediction and one column per GT person of a frame; entries are
// MPJPE(p, g) in mm (+inf = not comparable). Two rules (docs/metrics.md "Matching"):
//  * greedy by score (default, VoxelPose Panoptic protocol): NearestGt() per frame, then
//    GreedyMatch() over the records of the whole dataset;
//  * per-frame Hungarian with gating: HungarianMatch().
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace rpt::metrics {

// For each prediction (row), the GT column with the smallest cost (first on ties), or -1 when the
// frame has no GT or every cost is +inf / NaN. Many predictions may share a GT.
std::vector<int> NearestGt(const Eigen::MatrixXd& cost);

// For each GT (column), the prediction row with the smallest cost (first on ties), or -1.
std::vector<int> NearestPrediction(const Eigen::MatrixXd& cost);

// One candidate pair of the whole dataset. gt_id is a dataset-wide GT person id (-1 = none).
struct MatchRecord {
  int gt_id = -1;
  double error_mm = 0.0;  // MPJPE(p, g); +inf when gt_id == -1
  double score = 0.0;     // person score of the prediction (higher = more confident)
};

// The order in which GreedyMatch() and AveragePrecision() visit records: score descending, then
// error ascending (the fallback when predictions carry equal or no scores), then input order.
std::vector<int> RankRecords(std::span<const MatchRecord> records);

// The rule of RankRecords() for two records: true when (score_a, error_a) is visited before
// (score_b, error_b) regardless of their input order.
inline bool RanksBefore(double score_a, double error_a_mm, double score_b, double error_b_mm) {
  if (score_a != score_b) return score_a > score_b;
  return error_a_mm < error_b_mm;
}

// Score-ranked greedy matching (VoxelPose _eval_list_to_ap / _eval_list_to_mpjpe): visiting records in
// RankRecords() order, record r is a true positive iff error_mm < threshold_mm (strict) and its GT has
// no true positive yet. A record is never re-assigned to another GT. Returns one flag per record.
std::vector<bool> GreedyMatch(std::span<const MatchRecord> records, double threshold_mm);

// Per-frame Hungarian matching with gating: among the pairs with cost < gate_mm (strict), the
// one-to-one assignment with the most pairs and, among those, the smallest total cost.
// Returns for each prediction (row) its GT column, or -1.
std::vector<int> HungarianMatch(const Eigen::MatrixXd& cost, double gate_mm);

}  // namespace rpt::metrics
