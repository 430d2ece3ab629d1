// SPDX-License-Identifier: MIT
// All switches of the evaluation, with defaults. The definitions behind each switch and the
// reasons for each default are in docs/metrics.md. VisitFields (the convention of
// core/option_spec.h) names each field once; its key in the config section "metrics" is the
// field's name.
//
// Units: millimetres (mm) for every threshold (inputs are metres and converted once, on entry).
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/option_spec.h"

namespace rpt::metrics {

// How predictions are paired one-to-one with ground-truth persons.
enum class MatchingMode {
  kGreedy,     // VoxelPose: each prediction -> its nearest GT in the frame, then score-ranked greedy
               // over the whole dataset, accepting a pair if its error < threshold and the GT is free
  kHungarian,  // per frame: minimum-total-error one-to-one assignment among pairs below the threshold
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
  kNearest,  // the prediction of the same frame with the smallest MPJPE, no gate (legacy style)
  kMatched,  // the prediction matched to it by the main matching (gated, one-to-one)
};

// Layout rules of the legacy Shelf / Campus PCP (VoxelPose lib/dataset/{shelf,campus}.py).
enum class LegacyPcpLayout {
  kNone,    // legacy PCP not computed
  kShelf,   // COCO->Shelf14 with the Shelf head synthesis (nose-based, blended 75/25 with ears)
  kCampus,  // COCO->Shelf14 with the Campus head synthesis (ear-based)
};

}  // namespace rpt::metrics

namespace rpt {

template <>
struct EnumNames<metrics::MatchingMode> {
  static constexpr std::array<std::pair<metrics::MatchingMode, std::string_view>, 2> values = {
      {{metrics::MatchingMode::kGreedy, "greedy"}, {metrics::MatchingMode::kHungarian, "hungarian"}}};
};
template <>
struct EnumNames<metrics::PckDenominator> {
  static constexpr std::array<std::pair<metrics::PckDenominator, std::string_view>, 2> values = {
      {{metrics::PckDenominator::kAllGt, "all_gt"}, {metrics::PckDenominator::kMatchedGt, "matched_gt"}}};
};
template <>
struct EnumNames<metrics::Alignment> {
  static constexpr std::array<std::pair<metrics::Alignment, std::string_view>, 2> values = {
      {{metrics::Alignment::kNone, "none"}, {metrics::Alignment::kPelvis, "pelvis"}}};
};
template <>
struct EnumNames<metrics::PcpMatching> {
  static constexpr std::array<std::pair<metrics::PcpMatching, std::string_view>, 2> values = {
      {{metrics::PcpMatching::kNearest, "nearest"}, {metrics::PcpMatching::kMatched, "matched"}}};
};
template <>
struct EnumNames<metrics::LegacyPcpLayout> {
  static constexpr std::array<std::pair<metrics::LegacyPcpLayout, std::string_view>, 3> values = {
      {{metrics::LegacyPcpLayout::kNone, "none"},
       {metrics::LegacyPcpLayout::kShelf, "shelf"},
       {metrics::LegacyPcpLayout::kCampus, "campus"}}};
};

}  // namespace rpt

namespace rpt::metrics {

struct EvalOptions {
  // Joints evaluated and used for matching, by name (empty = EvaluationJoints13(), the paper's 13).
  // Every name must exist in the GT and in the prediction joint lists, else ConfigError.
  JointNames evaluated_joints;
  // GT joints with score <= this are invalid and excluded everywhere (VoxelPose / skelda: 0.1).
  double min_gt_score = 0.1;
  // Predicted joints with score <= this are missing: infinitely wrong for PCK/PCP, excluded from MPJPE (0).
  double min_pred_score = 0.0;
  // Pairing rule (default greedy by score: VoxelPose protocol, required for AP; metrics.md 3.1 / 8.1).
  MatchingMode matching = MatchingMode::kGreedy;
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
  PcpMatching pcp_matching = PcpMatching::kNearest;
  // Generic PCP alpha: part correct iff mean endpoint error <= alpha * GT part length (0.5, standard).
  double pcp_alpha = 0.5;
  // Compute MPJPE per whole-body group All / Body / Face / Hands (H3WB index groups, resolved by name).
  bool wholebody_groups = true;

  // Legacy Shelf/Campus PCP (metrics.md 4), off by default: only Shelf/Campus runs need it.
  // The layout picks the head-synthesis rule; kNone = not computed.
  LegacyPcpLayout legacy_pcp = LegacyPcpLayout::kNone;
  // true: frames without any prediction are skipped (Faster-VoxelPose, optimistic). Default false:
  // their actors count all 10 parts wrong (mvpose, the correct behaviour; metrics.md 2.2).
  bool legacy_pcp_skip_empty_frames = false;
  // The reported average is the mean per-actor PCP of actor ids 0..legacy_pcp_actors-1 (VoxelPose: 3).
  int legacy_pcp_actors = 3;
  // Part correct iff mean endpoint error <= alpha * GT part length (VoxelPose: 0.5).
  double legacy_pcp_alpha = 0.5;
  // Names of the 14 GT joints in Shelf14 order (empty = Shelf14Joints()); lets a reader keep its own names.
  JointNames legacy_pcp_gt_joints;

  // Empty when valid; otherwise "metrics.key: problem" for the first invalid value (the
  // convention of core/options_check.h).
  std::string Check() const;
  // evaluated_joints, or EvaluationJoints13() when empty.
  const JointNames& EvaluatedJoints() const;
};

// The key of the first field (VisitFields order) in which `a` and `b` differ; empty when they are equal.
std::string FirstDifferentOption(const EvalOptions& a, const EvalOptions& b);

template <class Visitor, OptionsOf<EvalOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("evaluated_joints", o.evaluated_joints,
    OptionSpec{.help = "joints evaluated and used for matching, each in GT and predictions once (empty = the "
                       "paper's 13)"});
  v("min_gt_score", o.min_gt_score,
    OptionSpec{.help = "GT joints with a lower or equal score are invalid", .min = 0, .max = 1});
  v("min_pred_score", o.min_pred_score,
    OptionSpec{.help = "predicted joints with a lower or equal score are missing", .min = 0, .max = 1});
  v("matching", o.matching,
    OptionSpec{.help = "score-ranked greedy over the dataset (VoxelPose) or per-frame Hungarian"});
  v("match_threshold_mm", o.match_threshold_mm,
    OptionSpec{.help = "a pair matches iff its MPJPE is below", .unit = "mm", .min = 0, .min_exclusive = true});
  v("pck_denominator", o.pck_denominator, OptionSpec{.help = "joints of all GT persons, or of matched ones only"});
  v("count_preds_without_gt", o.count_preds_without_gt,
    OptionSpec{.help = "predictions in frames without GT count as invalid and as AP false positives"});
  v("alignment", o.alignment, OptionSpec{.help = "reported MPJPE absolute or pelvis-aligned"});
  v("pcp_matching", o.pcp_matching,
    OptionSpec{.help = "generic PCP against the nearest prediction (no gate) or the matched one"});
  v("pcp_alpha", o.pcp_alpha,
    OptionSpec{.help = "generic PCP: part correct iff mean endpoint error <= alpha x GT part length", .min = 0,
               .min_exclusive = true});
  v("wholebody_groups", o.wholebody_groups, OptionSpec{.help = "MPJPE per whole-body group All|Body|Face|Hands"});
  v("legacy_pcp", o.legacy_pcp,
    OptionSpec{.help = "legacy Shelf/Campus PCP with VoxelPose head synthesis (none: not computed)"});
  v("legacy_pcp_skip_empty_frames", o.legacy_pcp_skip_empty_frames,
    OptionSpec{.help = "legacy PCP: skip frames without predictions (Faster-VoxelPose, optimistic)"});
  v("legacy_pcp_actors", o.legacy_pcp_actors,
    OptionSpec{.help = "legacy PCP: the average is over actor ids 0..n-1", .min = 1, .max = 10000});
  v("legacy_pcp_alpha", o.legacy_pcp_alpha,
    OptionSpec{.help = "legacy PCP: part correct iff mean endpoint error <= alpha x GT part length", .min = 0,
               .min_exclusive = true});
  v("legacy_pcp_gt_joints", o.legacy_pcp_gt_joints,
    OptionSpec{.help = "legacy PCP: names of the 14 GT joints in Shelf14 order (empty = the Shelf14 names)"});
}

}  // namespace rpt::metrics
