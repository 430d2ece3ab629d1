// SPDX-License-Identifier: MIT
// All switches of the evaluation, with defaults. The definitions behind each switch and the
// reasons for each default are in docs/metrics.md (which follows the recommendations of the
// research note shared/docs/metrics.md, section 8).
//
// Units: millimetres (mm) for every threshold (inputs are metres and converted once, on entry).
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"

namespace rpt::metrics {

// How predictions are paired one-to-one with ground-truth persons.
enum class MatchingMode {
  kGreedyScore,  // VoxelPose: each prediction -> its nearest GT in the frame, then score-ranked greedy
                 // over the whole dataset, accepting a pair if its error < threshold and the GT is free
  kHungarian,    // per frame: minimum-total-error one-to-one assignment among pairs below the threshold
};

// Denominator of PCK@t.
enum class PckDenominator {
  kAllGt,      // GT-valid joints of all GT persons: missed persons count as wrong
  kMatchedGt,  // GT-valid joints of matched GT persons only
};

// Alignment applied before the reported MPJPE values (overall, per joint, whole-body groups).
enum class Alignment {
  kNone,    // absolute world coordinates
  kPelvis,  // GT and prediction each translated so that their pelvis (mid-hip) is at the origin
};

// Which prediction the generic PCP scores a GT person against.
enum class PcpMatching {
  kNearestPrediction,  // the prediction of the same frame with the smallest MPJPE, no gate (legacy style)
  kMatched,            // the prediction matched to it by the main matching (gated, one-to-one)
};

// Layout rules of the legacy Shelf / Campus PCP (VoxelPose lib/dataset/{shelf,campus}.py).
enum class LegacyPcpLayout {
  kNone,    // legacy PCP not computed
  kShelf,   // COCO->Shelf14 with the Shelf head synthesis (nose-based, blended 75/25 with ears)
  kCampus,  // COCO->Shelf14 with the Campus head synthesis (ear-based)
};

struct LegacyPcpOptions {
  // Head-synthesis rule and on/off switch. Default off: only Shelf/Campus runs need it.
  LegacyPcpLayout layout = LegacyPcpLayout::kNone;
  // Names of the 14 GT joints in Shelf14 order (empty = Shelf14Joints()); lets a reader keep its own names.
  JointNames gt_joints;
  // true: frames without any prediction are skipped (Faster-VoxelPose, optimistic). Default false:
  // their actors count all 10 parts wrong (mvpose, the correct behaviour; metrics.md 2.2).
  bool skip_frames_without_predictions = false;
  // The reported average is the mean per-actor PCP of actor ids 0..num_averaged_actors-1 (VoxelPose: 3).
  int num_averaged_actors = 3;
  // PCP alpha: part correct iff mean endpoint error <= alpha * GT part length (VoxelPose: 0.5).
  double alpha = 0.5;
};

struct EvalOptions {
  // Joints evaluated and used for matching, by name (empty = EvaluationJoints13(), the paper's 13).
  // Every name must exist in the GT and in the prediction joint lists, else ConfigError.
  JointNames evaluated_joints;
  // GT joints with score <= this are invalid and excluded everywhere (VoxelPose / skelda: 0.1).
  double min_gt_score = 0.1;
  // Predicted joints with score <= this are missing: infinitely wrong for PCK/PCP, excluded from MPJPE (0).
  double min_pred_score = 0.0;
  // Pairing rule (default greedy by score: VoxelPose protocol, required for AP; metrics.md 3.1 / 8.1).
  MatchingMode matching = MatchingMode::kGreedyScore;
  // A pair is a match (TP) iff its MPJPE < this, mm (VoxelPose 500; also the Recall@500 / Invalid gate).
  double match_threshold_mm = 500.0;
  // PCK denominator (default all GT: matched-only would make PCK@500 ~100 % and uninformative; 8.2).
  PckDenominator pck_denominator = PckDenominator::kAllGt;
  // true: predictions in frames without (kept) GT persons count as Invalid and as AP false positives.
  // Default true (metrics.md 8.3); false mimics VoxelPose, which skips GT-empty frames.
  bool count_preds_without_gt = true;
  // Alignment of the reported MPJPE values (default none: absolute multi-view error; metrics.md 8.6).
  // Matching, Recall, PCK and PCP always use absolute coordinates.
  Alignment alignment = Alignment::kNone;
  // Generic PCP pairing (default nearest prediction without gate, mimicking legacy PCP; metrics.md 8.4).
  PcpMatching pcp_matching = PcpMatching::kNearestPrediction;
  // Generic PCP alpha: part correct iff mean endpoint error <= alpha * GT part length (0.5, standard).
  double pcp_alpha = 0.5;
  // Compute MPJPE per whole-body group All / Body / Face / Hands (H3WB index groups, resolved by name).
  bool wholebody_groups = true;
  // Legacy Shelf/Campus PCP (off by default).
  LegacyPcpOptions legacy_pcp;

  // Throws rpt::ConfigError naming the offending field.
  void Check() const;
  // evaluated_joints, or EvaluationJoints13() when empty.
  const JointNames& EvaluatedJoints() const;
};

}  // namespace rpt::metrics
