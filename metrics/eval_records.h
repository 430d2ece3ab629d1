// SPDX-License-Identifier: MIT
// EvalRecords: what MetricsAccumulator collects frame by frame (candidate prediction/GT pairs with
// their errors, GT and prediction counts, per-joint and per-part totals), and MatchSets: which of
// those pairs are matches at the gate, at 100 mm and at 500 mm. Every metric is a pure function of
// the two (metrics/reducers/).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/joints.h"
#include "metrics/eval_options.h"
#include "metrics/matching.h"
#include "metrics/pcp.h"

namespace rpt::metrics {

// Flags of a pair record.
enum PairFlag : std::uint8_t {
  kNearest = 1,         // the prediction's nearest GT (greedy matching, AP)
  kHungarianMatch = 2,  // Hungarian pair at match_threshold_mm
  kHungarian100 = 4,    // Hungarian pair at 100 mm
  kHungarian500 = 8,    // Hungarian pair at 500 mm
};

// One candidate (prediction, GT) pair: a prediction's nearest GT or a Hungarian pair. A prediction
// of a frame without GT has one record with gt_idx -1 and an infinite error.
struct PairRecord {
  MatchRecord match;                   // gt_id, error (absolute MPJPE), score
  std::uint8_t flags = 0;              // PairFlag bits
  int pred_idx = -1;                   // prediction index within its frame
  int gt_idx = -1;                     // kept-GT index within its frame (-1 = none)
  bool counted = true;                 // prediction counts for Invalid / AP
  double report_error_mm = 0.0;        // MPJPE used for reporting (aligned if set; NaN = unaligned)
  Eigen::ArrayXd joint_errors;         // absolute, evaluated joints (NaN GT-invalid, +inf missing)
  Eigen::ArrayXd report_joint_errors;  // aligned if set
  std::vector<double> group_errors;    // per whole-body group mean (NaN = no joint)
  std::vector<PartOutcome> pcp;        // generic PCP outcomes of this pair
};

struct EvalRecords {
  JointNames evaluated;            // evaluated joints, in EvalOptions order
  std::vector<PairRecord> pairs;   // in the order frames were added
  int num_frames = 0;
  int num_frames_with_gt = 0;
  int num_gt = 0;                  // kept GT persons
  int num_dropped_gt = 0;          // GT persons without a valid evaluated joint
  int num_pred_counted = 0;        // predictions counted for Invalid / AP
  int num_pred_total = 0;
  std::vector<int> gt_valid_per_joint;   // GT-valid count per evaluated joint over all kept GT
  std::vector<int> pcp_total;            // evaluable generic PCP parts over all kept GT
  std::vector<int> pcp_correct_nearest;  // correct parts against each GT's nearest prediction
  std::vector<int> group_num_joints;     // joints of each whole-body group present in both lists
  std::optional<LegacyPcpEvaluator> legacy;  // legacy PCP counts, when legacy_pcp != kNone
};

// One flag per pair: matched at match_threshold_mm, at 100 mm, at 500 mm (greedy by score over the
// nearest-GT pairs, or the Hungarian flags, following EvalOptions::matching).
struct MatchSets {
  std::vector<bool> at_gate, at_100, at_500;
};
MatchSets SelectMatches(const EvalRecords& records, const EvalOptions& options);

// Number of true flags.
int CountMatches(const std::vector<bool>& matched);

}  // namespace rpt::metrics
