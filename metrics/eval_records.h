// SPDX-License-Identifier: MIT
// FrameRecords: what MetricsAccumulator::Add collects about one frame (the kept GT persons, the
// candidate prediction/GT pairs with their errors and match flags, the inputs of both PCPs). Every
// metric family folds a frame's records into its running totals (metrics/reducers/) as soon as the
// frame is added, so nothing is kept per frame and an evaluation's memory does not grow with it.
//
// Matching is resolved per frame. Hungarian matching is per frame by definition. Greedy matching
// (VoxelPose) ranks the nearest-GT pairs of the whole run by score, but a pair only competes with
// pairs of the same GT person, i.e. of the same frame, and the run's ranking orders a frame's pairs
// as the frame's own ranking does (RankRecords: a stable sort): greedy matching of a frame's pairs
// alone gives the frame's part of the run's greedy matching.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "metrics/matching.h"
#include "metrics/pcp.h"
#include "metrics/person_error.h"

namespace rpt::metrics {

// Flags of a pair record.
enum PairFlag : std::uint8_t {
  kNearest = 1,   // the prediction's nearest GT (greedy matching, AP)
  kMatch = 2,     // a match at match_threshold_mm (following EvalOptions::matching)
  kMatch100 = 4,  // a match at 100 mm (Recall@100)
  kMatch500 = 8,  // a match at 500 mm (Recall@500)
};

// One candidate (prediction, GT) pair of a frame: a prediction's nearest GT or a Hungarian pair. A
// prediction of a frame without GT has one record with gt_idx -1 and an infinite error.
struct PairRecord {
  int pred_idx = -1;                   // prediction index within the frame
  int gt_idx = -1;                     // kept-GT index within the frame (-1 = none)
  double error_mm = 0.0;               // MPJPE(p, g), absolute; +inf without GT
  double score = 0.0;                  // person score of the prediction (higher = more confident)
  std::uint8_t flags = 0;              // PairFlag bits
  double report_error_mm = 0.0;        // MPJPE used for reporting (aligned if set; NaN = unaligned)
  Eigen::ArrayXd joint_errors;         // absolute, evaluated joints (NaN GT-invalid, +inf missing)
  Eigen::ArrayXd report_joint_errors;  // aligned if set
  std::vector<double> group_errors;    // per whole-body group mean (NaN = no joint)
  std::vector<int> group_joints;       // per group: the joints in that mean
  std::vector<int> group_filled;       // of those: filled from a neighbour, not triangulated
  std::vector<PartOutcome> pcp;        // generic PCP outcomes of this pair
};

struct FrameRecords {
  std::vector<int> kept_gt_idx;  // per kept GT person (a valid evaluated joint): its index in the frame's GT
  std::vector<EvalPerson> gt;    // the kept GT persons, evaluated joints
  int num_dropped_gt = 0;        // GT persons without a valid evaluated joint
  int num_predictions = 0;
  bool counted = true;  // the predictions count for Invalid / AP (kept GT, or count_preds_without_gt)
  // pairs[p] for p < num_predictions is prediction p's nearest-GT pair (kNearest); Hungarian pairs
  // that are not also nearest pairs follow. The kMatch* flags are resolved.
  std::vector<PairRecord> pairs;
  // Generic PCP of each kept GT person against its nearest prediction (no gate; no prediction: wrong).
  std::vector<std::vector<PartOutcome>> pcp_nearest;
  // Joints of each whole-body group present in both joint lists; empty when the groups are off or
  // a joint list is empty (a frame without persons may omit it).
  std::vector<int> group_num_joints;
  std::vector<int> group_gt_only_joints;  // per group: joints only the GT's list has (as above)
  // Legacy PCP inputs (when legacy_pcp != kNone): the GT actors and all predictions in Shelf14 layout.
  std::vector<LegacyActor> legacy_actors;
  std::vector<Shelf14> legacy_predictions;
};

// Whether prediction p is a match at the gate (kMatch): in any of the frame's pairs, as Hungarian
// matching may pair it with a GT person other than its nearest.
bool IsMatchedPrediction(const FrameRecords& frame, int p);
// Whether kept GT person g (kept-GT index) is matched at the gate (kMatch) by any prediction.
bool IsMatchedGt(const FrameRecords& frame, int g);

// The frame's nearest-GT pairs as MatchRecords (gt_id = kept-GT index), prediction order: the input
// of greedy matching and AP.
std::vector<MatchRecord> NearestMatchRecords(const FrameRecords& frame);

}  // namespace rpt::metrics
