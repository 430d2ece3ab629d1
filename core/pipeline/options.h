// SPDX-License-Identifier: MIT
// Options of every pipeline step, one section per step, named like the step (and like the
// config-file section and the timing output). A step reads its own section only (the step table
// binds each step to it, step_functions.h); what several steps need that is no step's choice (the
// room, the continuity gap, the score of filled joints) is resolved once into the Triangulator's
// model (model.h) and handed to the steps as input.
//
// Beside each struct, VisitFields names every field once with its key, help text, unit and valid
// range (the convention of core/option_spec.h); the struct's initialisers are the defaults.
// Everything that reads or writes options by name (config files, --set, `rpt config --dump`, the
// generated docs/options.md, Check()) is a visitor of these functions.
//
// Units: metres (m), metres per second (m/s), pixels (px). Image-space distances that depend on
// how large a person appears are given relative to the 2D pose's bounding-box diagonal (rel).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/option_spec.h"

namespace rpt {

// Undistortion and preparation of the 2D poses.
struct UndistortOptions {
  double min_joint_score = 0.1;    // 2D joints with a lower score are treated as missing
  bool add_derived_joints = true;  // append hip_middle, shoulder_middle, head (computed in 2D)
  // Poses with fewer valid core joints are dropped. With triangulate.min_core_joints (a pair's
  // proposal needs that many core joints seen in both views) at the same value, such a pose could
  // not be in any proposal; dropping it here keeps it out of the pairs and the pre-filter.
  int min_core_joints = 3;
  // A pose that repeats an earlier pose of its view exactly (every joint's pixel and score) is
  // dropped: a copy adds no evidence, but its extra pairs would count twice in grouping (a file
  // artifact: MVOR's shipped OpenPose detections repeat 22 % of their poses).
  bool drop_exact_copies = true;
};

template <class Visitor, OptionsOf<UndistortOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("min_joint_score", o.min_joint_score,
    OptionSpec{.help = "2D joints with a lower score (or NaN) are missing", .min = 0, .max = 1});
  v("add_derived_joints", o.add_derived_joints,
    OptionSpec{.help = "append hip_middle, shoulder_middle, head (computed in 2D)"});
  v("min_core_joints", o.min_core_joints,
    OptionSpec{.help = "2D poses with fewer valid core joints are dropped before pairing (at "
                       "triangulate.min_core_joints they could form no proposal)",
               .min = 1, .max = 1000});
  v("drop_exact_copies", o.drop_exact_copies,
    OptionSpec{.help = "drop a 2D pose that repeats an earlier pose of its view exactly (pixels and scores)"});
}

// Step 2: keep pairs whose two poses both match the same last-frame person, or neither does.
// The match radius grows with the time since the last frame, so sparsely sampled sequences
// (e.g. every 12th frame) keep their true pairs: radius = max_distance_rel + person_speed_m_s *
// elapsed / 1.8 m (1.8 m: the typical bbox diagonal of a person, to turn metres into rel).
struct PrefilterOptions {
  bool enabled = true;
  double max_distance_rel = 0.25;  // match radius at zero elapsed time (fraction of bbox diagonal)
  double person_speed_m_s = 2.0;   // assumed top speed of a person, widens the radius over time
  double ambiguity_ratio = 1.5;    // second-closest person must be this much farther for a match
  // With many cameras a tracked person yields k(k-1)/2 pairs; keep only this many per person: first
  // the best_pairs_per_pose best pairs of each of its poses, then the best others. Best = sin of the
  // angle between the two viewing rays at the person x the 2D confidence both poses share on the
  // core joints. 0: keep all.
  int max_pairs_per_person = 30;
  // Pairs of each pose a person's budget keeps before the best others (even above the budget). One:
  // with 31 cameras a fifth faster than two; a pose whose only pair the score filter drops can then
  // form a copy of its person with others like it, which verify drops (duplicate_distance_m). Two
  // keep a little more of the person's pairs (docs/algorithm.md, step 2).
  int best_pairs_per_pose = 1;
  // An ambiguous pose pairs with every pose matched to a person it is near (one per view); keep
  // only this many of those pairs per person, the best as above. 0: keep all.
  int max_pairs_per_ambiguous_pose = 4;
};

template <class Visitor, OptionsOf<PrefilterOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, OptionSpec{.help = "filter pairs with the last frame's persons (ablation: false)"});
  v("max_distance_rel", o.max_distance_rel,
    OptionSpec{.help = "match radius at zero elapsed time, fraction of the pose's bbox diagonal",
               .unit = "rel", .min = 0, .max = 100});
  v("person_speed_m_s", o.person_speed_m_s,
    OptionSpec{.help = "assumed top speed of a person, widens the match radius with the time since the last frame",
               .unit = "m/s", .min = 0, .max = 1000});
  v("ambiguity_ratio", o.ambiguity_ratio,
    OptionSpec{.help = "the second-closest person must be this much farther for a match", .min = 1, .max = 1000});
  v("max_pairs_per_person", o.max_pairs_per_person,
    OptionSpec{.help = "pairs kept per tracked person: each pose's best_pairs_per_pose best, then the best others; "
                       "best = sin of the ray angle at the person x shared 2D confidence (0: keep all)",
               .min = 0, .max = 1e9});
  v("best_pairs_per_pose", o.best_pairs_per_pose,
    OptionSpec{.help = "pairs of each pose that max_pairs_per_person keeps first, even above it (1 is faster with "
                       "many cameras, 2 keeps more of each person's pairs)",
               .min = 1, .max = 4});
  v("max_pairs_per_ambiguous_pose", o.max_pairs_per_ambiguous_pose,
    OptionSpec{.help = "pairs kept between an ambiguous pose and the poses matched to one person it is near; best "
                       "as for max_pairs_per_person (0: keep all)",
               .min = 0, .max = 1e9});
}

enum class TriangulationMethod { kMidpoint, kDlt };
template <>
struct EnumNames<TriangulationMethod> {
  static constexpr std::array<std::pair<TriangulationMethod, std::string_view>, 2> values = {
      {{TriangulationMethod::kMidpoint, "midpoint"}, {TriangulationMethod::kDlt, "dlt"}}};
};

// Steps 3, 4 and 10.
struct TriangulateOptions {
  TriangulationMethod method = TriangulationMethod::kMidpoint;
  // Step 3: the joints used for association. Default: shoulders, hips, elbows, wrists, knees, ankles.
  std::vector<std::string> core_joints;  // empty = DefaultCoreJoints()
  int min_core_joints = 3;               // a pair needs this many core joints seen in both views (step 4)
  // Association pairs every pose of a view with every pose of the other views: time and memory grow
  // with the square of the persons per view (1600 took 4.7 s and 1 GB for one frame). A frame with
  // more persons in one view is refused (InputError) instead of stalling a run. The pairs of a
  // frame (every pose of a view with every pose of each other view) are bounded too: 10 views of
  // 500 poses each are 11 million pairs (2.7 GB for one frame).
  int max_persons_per_view = 500;
  int max_pairs_per_frame = 1000000;
  // Step 10, per joint of a group seen in 3 or more of its poses: a view whose ray passes farther
  // from the point the other views agree on than robust_min_m (scaled by that point's depth
  // uncertainty) and than robust_ratio x the median distance of the other views' rays is dropped
  // for that joint (at most down to 2 views), so an occluded joint reported at a wrong place is not
  // averaged in (triangulate_full.h). Off: it improved no case measured (docs/algorithm.md).
  bool robust_views = false;
  double robust_min_m = 0.15;  // m at the joint: smaller disagreements are detection noise
  double robust_ratio = 4.0;   // x the median distance of the other views' rays
};

template <class Visitor, OptionsOf<TriangulateOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("method", o.method,
    OptionSpec{.help = "ray mid-point, or linear DLT (least squares through the 3x3 normal equations)"});
  v("core_joints", o.core_joints,
    OptionSpec{.help = "joints used for association (empty = shoulders, hips, elbows, wrists, knees, ankles)"});
  v("min_core_joints", o.min_core_joints,
    OptionSpec{.help = "a pair needs this many core joints seen in both views", .min = 1, .max = 1000});
  v("max_persons_per_view", o.max_persons_per_view,
    OptionSpec{.help = "a frame with more 2D poses in one view is refused (association cost grows with the square)",
               .min = 1, .max = 100000});
  v("max_pairs_per_frame", o.max_pairs_per_frame,
    OptionSpec{.help = "a frame with more pairs of 2D poses across views is refused (memory grows with the pairs)",
               .min = 1, .max = 1000000000});
  v("robust_views", o.robust_views,
    OptionSpec{.help = "step 10: per joint seen in 3+ views of a person, drop the views that disagree with the "
                       "others (robust_min_m, robust_ratio) before the merge"});
  v("robust_min_m", o.robust_min_m,
    OptionSpec{.help = "robust_views: a view is dropped only if its ray's distance from the other views' point, "
                       "over sqrt(1 + that point's depth variance), exceeds this",
               .unit = "m", .min = 0, .max = 100, .min_exclusive = true});
  v("robust_ratio", o.robust_ratio,
    OptionSpec{.help = "robust_views: ... and farther than this many times the median distance of the other "
                       "views' rays",
               .min = 1, .max = 1e6});
}

// Step 5 and the room. The room is an axis-aligned box, a property of the scene: center_m and
// size_m describe it (a size component <= 0 leaves that axis unbounded) and the Triangulator
// resolves them into its model's Room (core/room.h), which room_check and postprocess.drop_outside_room
// both use. margin_m is the room check's own tolerance.
struct RoomCheckOptions {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
  double margin_m = 0.5;  // proposals this far outside the box are still inside
};

template <class Visitor, OptionsOf<RoomCheckOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("center_m", o.center_m,
    OptionSpec{.help = "room centre (used when room_check.size_m is set; else the dataset's room)", .unit = "m"});
  v("size_m", o.size_m,
    OptionSpec{.help = "room size per axis (<= 0: unbounded; all zero: the dataset's room)", .unit = "m"});
  v("margin_m", o.margin_m,
    OptionSpec{.help = "tolerance around the room box for proposals", .unit = "m", .min = 0, .max = 1e6});
}

enum class ScoreMode { kCombined, kReprojectionOnly, kTriangulationOnly };
template <>
struct EnumNames<ScoreMode> {
  static constexpr std::array<std::pair<ScoreMode, std::string_view>, 3> values = {
      {{ScoreMode::kCombined, "combined"},
       {ScoreMode::kReprojectionOnly, "reprojection"},
       {ScoreMode::kTriangulationOnly, "triangulation"}}};
};

// How the score kernels are scaled: to the noise level estimated from the data (residuals in
// metres at the joint's depth, see noise_scale.h), or by the fixed constants of the first release
// (reprojection error relative to the pose's bounding box).
enum class ScoreScale { kAdaptive, kFixed };
template <>
struct EnumNames<ScoreScale> {
  static constexpr std::array<std::pair<ScoreScale, std::string_view>, 2> values = {
      {{ScoreScale::kAdaptive, "adaptive"}, {ScoreScale::kFixed, "fixed"}}};
};

// Steps 6-7: per-joint score from reprojection error, ray gap and 2D confidence; limb pruning.
struct ScoreOptions {
  ScoreMode mode = ScoreMode::kCombined;
  bool use_confidence = true;       // weight joints by their 2D confidence
  ScoreScale scale = ScoreScale::kAdaptive;
  double scale_factor = 5.0;        // adaptive: kernel scale = scale_factor x estimated noise (m)
  double noise_prior_m = 0.02;      // adaptive: noise level assumed before the data has spoken (m)
  double reprojection_scale_rel = 0.08;  // fixed: reprojection error (rel) at which the score is exp(-1)
  double ray_gap_scale_m = 0.12;    // fixed: distance between the two rays at which the score is exp(-1)
  double trim_fraction = 0.25;      // the pair score leaves out this share of its worst joints
  bool prune_limbs = true;          // invalidate joints of implausibly short or long limbs
};

template <class Visitor, OptionsOf<ScoreOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("mode", o.mode, OptionSpec{.help = "combined, or only one error term (the paper's ablations)"});
  v("use_confidence", o.use_confidence, OptionSpec{.help = "weight joints by their 2D confidence (ablation: false)"});
  v("scale", o.scale,
    OptionSpec{.help = "kernel scale: adaptive (estimated detection noise) or fixed (the first release's)"});
  v("scale_factor", o.scale_factor,
    OptionSpec{.help = "adaptive: kernel scale = factor x estimated noise", .min = 0, .min_exclusive = true});
  v("noise_prior_m", o.noise_prior_m,
    OptionSpec{.help = "adaptive: noise level assumed before the data has spoken", .unit = "m", .min = 0,
               .min_exclusive = true});
  v("trim_fraction", o.trim_fraction,
    OptionSpec{.help = "the pair score leaves out this share of its worst joints", .min = 0, .max = 0.9});
  v("reprojection_scale_rel", o.reprojection_scale_rel,
    OptionSpec{.help = "fixed: reprojection error giving score factor e^-1", .unit = "rel", .min = 0,
               .min_exclusive = true});
  v("ray_gap_scale_m", o.ray_gap_scale_m,
    OptionSpec{.help = "fixed: ray gap giving score factor e^-1", .unit = "m", .min = 0, .min_exclusive = true});
  v("prune_limbs", o.prune_limbs, OptionSpec{.help = "invalidate joints of implausibly short or long limbs"});
}

// Step 8.
struct FilterOptions {
  double min_match_score = 0.7;  // pairs with a lower pair score are dropped
};

template <class Visitor, OptionsOf<FilterOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("min_match_score", o.min_match_score,
    OptionSpec{.help = "pairs with a lower pair score are dropped", .min = 0, .max = 1});
}

// Step 9.
struct GroupOptions {
  double max_distance_m = 0.25;  // mean core-joint distance for a proposal to join a group
  // Groups with fewer proposals are dropped. 0 = automatic: 1 below 10 cameras, 2 from 10 up (the
  // paper recommends raising it with many cameras, where accidental consistent pairs appear).
  int min_group_size = 0;
  bool exclusive_poses = true;  // a 2D pose belongs to one person: the strongest group keeps it
  bool drop_mirrored = true;    // drop a group that is another group with left/right swapped
};

template <class Visitor, OptionsOf<GroupOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("max_distance_m", o.max_distance_m,
    OptionSpec{.help = "mean core-joint distance for a proposal to join a group", .unit = "m", .min = 0,
               .min_exclusive = true});
  v("min_group_size", o.min_group_size,
    OptionSpec{.help = "groups with fewer proposals are dropped (0 = automatic: 1 below 10 cameras, else 2)",
               .min = 0, .max = 1e6});
  v("exclusive_poses", o.exclusive_poses,
    OptionSpec{.help = "a 2D pose belongs to one person: the strongest group keeps it (removes phantoms)"});
  v("drop_mirrored", o.drop_mirrored,
    OptionSpec{.help = "drop a group that is another group with left/right swapped"});
}

// Step 11.
struct MergeOptions {
  double max_distance_m = 0.2;  // drop joint proposals this far from the mean (0: keep all)
  int top_k = 3;                // then keep the k closest (0: keep all)
  bool score_weighted = true;   // weighted average by joint score instead of plain mean
  double min_joint_score = 0.1; // joint proposals below are ignored
  bool keep_best_when_all_far = true;  // if the distance filter drops every candidate, keep the
                                       // highest-scoring one instead of leaving the joint missing
};

template <class Visitor, OptionsOf<MergeOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("max_distance_m", o.max_distance_m,
    OptionSpec{.help = "drop joint proposals this far from the mean (0: keep all)", .unit = "m", .min = 0,
               .max = 1e6});
  v("top_k", o.top_k,
    OptionSpec{.help = "then keep the k closest joint proposals (0: keep all)", .min = 0, .max = 1e6});
  v("score_weighted", o.score_weighted,
    OptionSpec{.help = "weighted average by joint score instead of plain mean"});
  v("min_joint_score", o.min_joint_score,
    OptionSpec{.help = "joint proposals with a lower score are ignored", .min = 0, .max = 1});
  v("keep_best_when_all_far", o.keep_best_when_all_far,
    OptionSpec{.help = "keep the highest-scoring candidate when the distance filter drops all of them"});
}

// Step 11a (an addition): re-triangulate each merged joint from all of its person's views (refine.h).
struct RefineOptions {
  bool enabled = true;
  int iterations = 1;         // reweighting passes from the merged joint (a second: a little more accuracy, more time)
  double scale_factor = 1.0;  // the weights' scale s, in units of the frame's score kernel scale S
  double cutoff = 3.0;        // views whose ray is farther than cutoff x s get no weight
  // A joint no pair triangulated that exactly one of the person's views detected is placed on that
  // view's ray at its neighbour's depth (provenance lifted) instead of being filled later.
  bool one_view_joints = true;
};

template <class Visitor, OptionsOf<RefineOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled,
    OptionSpec{.help = "re-triangulate each merged joint from all of its person's views (robust weights)"});
  v("iterations", o.iterations,
    OptionSpec{.help = "reweighting passes, starting from the merged joint", .min = 1, .max = 100});
  v("scale_factor", o.scale_factor,
    OptionSpec{.help = "scale s of the weights c / (1 + (d / s)^2), in units of the frame's score kernel scale",
               .min = 1e-6, .max = 1e6});
  v("cutoff", o.cutoff,
    OptionSpec{.help = "views whose ray passes farther than cutoff x s from the joint get no weight", .min = 0,
               .max = 1e6});
  v("one_view_joints", o.one_view_joints,
    OptionSpec{.help = "a joint only one of its person's views detected goes on that view's ray at its neighbour's "
                       "depth (provenance lifted; with refine.enabled)"});
}

// Step 11b (an addition): re-score each person against all views, drop unsupported ones.
struct VerifyOptions {
  bool enabled = true;
  int min_empty_views = 2;             // drop when this many views (and more than support it) see nobody there
  double min_inside_fraction = 0.8;    // a view is "empty" only if this share of the joints lands in the image
  // A person whose core joints lie this close (mean distance over the joints both have) to a
  // stronger person's, and made from none of its views, is that person again: dropped. 0 = off.
  double duplicate_distance_m = 0.25;
  // A person with fewer joints than another, at least 2 of whose joints each lie this close to the
  // other's same joint, is a part of that person (a body whose poses formed two groups): dropped.
  // 0 = off.
  double part_distance_m = 0.15;
};

template <class Visitor, OptionsOf<VerifyOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, OptionSpec{.help = "re-score each person against all views, drop unsupported ones"});
  v("min_empty_views", o.min_empty_views,
    OptionSpec{.help = "empty views needed (and more than supporting ones) to drop a person", .min = 1, .max = 1e6});
  v("min_inside_fraction", o.min_inside_fraction,
    OptionSpec{.help = "a view is empty only if this share of the joints lands in the image", .min = 0, .max = 1});
  v("duplicate_distance_m", o.duplicate_distance_m,
    OptionSpec{.help = "mean core-joint distance under which a person from none of a stronger person's views duplicates it "
                       "and is dropped (0 = off)",
               .unit = "m", .min = 0, .max = 10});
  v("part_distance_m", o.part_distance_m,
    OptionSpec{.help = "a person with fewer joints than another and 2 joints this close to the other's same joints is "
                       "a part of it and is dropped (0 = off)",
               .unit = "m", .min = 0, .max = 10});
}

// Step 12b (an addition, off by default): persons seen by one camera only, placed at the depth
// their 2D limb lengths imply (single_view.h).
struct SingleViewOptions {
  bool enabled = false;
  double min_joint_score = 0.3;       // confidence of the joints used
  int min_core_joints = 6;            // confident core joints a pose needs
  double score_factor = 0.5;          // joint scores = 2D confidence x this (rank below triangulated persons)
  double duplicate_distance_m = 0.5;  // centre distance under which a lifted person duplicates another
  double max_overlap_iou = 0.3;       // poses overlapping a found person's projection this much are that person
  // The other views' verdict (view_verdict.h), the rule of verification (step 11b) with its own
  // values: a pose is not lifted when min_empty_views other views are empty.
  int min_empty_views = 2;
  double min_inside_fraction = 0.8;  // a view is empty only if this share of the joints lands in the image
  // The ground-plane and body-size prior (single_view.h): stand the person upright on the floor
  // (world z up) instead of at the limb-length depth, and lift it only if its body size, posture
  // and place are plausible. Physical values, the same for every dataset.
  bool ground_prior = false;
  double floor_z_m = 0.0;        // world z of the floor (readers give z up, floor near z = 0)
  double ankle_height_m = 0.08;  // ankle joint centre above the floor
  double hip_height_m = 0.90;    // hip joint centre above the floor when standing (no ankle seen)
  double min_body_scale = 0.75;  // body size / typical adult's, measured from the limbs once placed
  double max_body_scale = 1.30;
  double min_upright = 0.5;      // cosine between the hip-to-shoulder direction and the vertical
  // Track assistance (needs track.enabled): a pose matching a live track's projection is placed
  // at the track's depth, its scores times exp(-age / track_decay_s), age = time since the
  // track's last multi-view support; not after track_max_age_s.
  bool track_assist = false;
  double track_max_age_s = 1.0;
  double track_decay_s = 0.5;
  double track_max_distance = 0.5;  // mean 2D joint distance to the track's projection / the pose's box diagonal
};

template <class Visitor, OptionsOf<SingleViewOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled,
    OptionSpec{.help = "place persons seen by one camera at the depth their 2D limb lengths imply"});
  v("min_joint_score", o.min_joint_score, OptionSpec{.help = "confidence of the joints used", .min = 0, .max = 1});
  v("min_core_joints", o.min_core_joints,
    OptionSpec{.help = "confident core joints a pose needs", .min = 2, .max = 1e6});
  v("score_factor", o.score_factor,
    OptionSpec{.help = "joint scores = 2D confidence x this (ranks below triangulated persons)", .min = 1e-6,
               .max = 1});
  v("duplicate_distance_m", o.duplicate_distance_m,
    OptionSpec{.help = "centre distance under which a lifted person duplicates another", .unit = "m", .min = 0,
               .max = 1e6});
  v("max_overlap_iou", o.max_overlap_iou,
    OptionSpec{.help = "poses overlapping a found person's projection this much are that person", .min = 0,
               .max = 1});
  v("min_empty_views", o.min_empty_views,
    OptionSpec{.help = "a pose is not lifted when this many other views see nobody there",
               .min = 1, .max = 1e6});
  v("min_inside_fraction", o.min_inside_fraction,
    OptionSpec{.help = "a view is empty only if this share of the lifted joints lands in the image", .min = 0,
               .max = 1});
  v("ground_prior", o.ground_prior,
    OptionSpec{.help = "stand the person upright on the floor (ankles, else hips, at their height) and lift it only "
                       "if its body size, posture and place are plausible; false: the limb-length depth"});
  v("floor_z_m", o.floor_z_m,
    OptionSpec{.help = "world z of the floor (z up)", .unit = "m", .min = -1e6, .max = 1e6});
  v("ankle_height_m", o.ankle_height_m,
    OptionSpec{.help = "ankle joint centre above the floor", .unit = "m", .min = 0, .max = 10});
  v("hip_height_m", o.hip_height_m,
    OptionSpec{.help = "hip joint centre above the floor of a standing person (used when no ankle is seen)",
               .unit = "m", .min = 0, .max = 10});
  v("min_body_scale", o.min_body_scale,
    OptionSpec{.help = "smallest plausible body size relative to a typical adult (limb lengths once placed)",
               .min = 0, .max = 100});
  v("max_body_scale", o.max_body_scale,
    OptionSpec{.help = "largest plausible body size relative to a typical adult", .min = 0, .max = 100});
  v("min_upright", o.min_upright,
    OptionSpec{.help = "cosine between the placed hip-to-shoulder direction and the vertical, at least", .min = -1,
               .max = 1});
  v("track_assist", o.track_assist,
    OptionSpec{.help = "place a pose that matches a live track's projection at the track's depth (needs tracking)"});
  v("track_max_age_s", o.track_max_age_s,
    OptionSpec{.help = "no track assistance once the track's last multi-view support is older", .unit = "s",
               .min = 0, .max = 1e6});
  v("track_decay_s", o.track_decay_s,
    OptionSpec{.help = "track-assisted joint scores x exp(-age / this), age since the last multi-view support",
               .unit = "s", .min = 1e-6, .max = 1e6});
  v("track_max_distance", o.track_max_distance,
    OptionSpec{.help = "mean 2D joint distance to a track's projection, as a share of the pose's box diagonal, "
                       "under which the pose is that track's",
               .min = 0, .max = 100});
}

// Step 12.
struct PostprocessOptions {
  bool enabled = true;
  int min_valid_joints = 4;         // persons with fewer valid joints are dropped
  double min_extent_m = 0.2;        // drop persons whose bounding box diagonal is smaller
  double max_extent_m = 3.0;        // ... or larger
  bool drop_outside_room = true;    // drop persons whose centre is outside the room (+ room_margin_m)
  double room_margin_m = 0.5;       // tolerance around the room box for persons
  bool replace_wrong_joints = true; // joints of implausible limbs take their neighbour's place
  bool fill_missing_joints = true;  // missing joints take their neighbour's position
  double filled_joint_score = 0.05; // score given to filled joints (> 0 so they count as present)
};

template <class Visitor, OptionsOf<PostprocessOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, OptionSpec{.help = "post-process persons (ablation: false)"});
  v("min_valid_joints", o.min_valid_joints,
    OptionSpec{.help = "persons with fewer valid joints are dropped", .min = 0, .max = 1e6});
  v("min_extent_m", o.min_extent_m,
    OptionSpec{.help = "drop persons whose bounding-box diagonal is smaller", .unit = "m", .min = 0, .max = 1e6});
  v("max_extent_m", o.max_extent_m,
    OptionSpec{.help = "drop persons whose bounding-box diagonal is larger (>= min_extent_m)", .unit = "m",
               .min = 0, .max = 1e6});
  v("drop_outside_room", o.drop_outside_room,
    OptionSpec{.help = "drop persons whose centre is outside the room (+ room_margin_m)"});
  v("room_margin_m", o.room_margin_m,
    OptionSpec{.help = "tolerance around the room box for persons", .unit = "m", .min = 0, .max = 1e6});
  v("replace_wrong_joints", o.replace_wrong_joints,
    OptionSpec{.help = "joints of implausible limbs take their neighbour's place"});
  v("fill_missing_joints", o.fill_missing_joints,
    OptionSpec{.help = "missing joints take their neighbour's position"});
  v("filled_joint_score", o.filled_joint_score,
    OptionSpec{.help = "score given to filled joints (> 0 so they count as present)", .min = 1e-9, .max = 1});
}

// Step 13.
struct TrackOptions {
  bool enabled = true;
  // Frames further apart than this, or without a known time (NaN timestamp), are not continuous:
  // tracks end (nothing coasts), neither the pre-filter nor speed clipping use the frame before,
  // and smoothing restarts. A property of the input rather than of tracking: the Triangulator reads
  // it into its model (model.h) and judges every frame's continuity with it.
  double max_gap_s = 1.0;
  double max_distance_m = 0.5;  // mean core-joint distance to continue a track
  // At low frame rates people move further than max_distance_m between frames: a track continues
  // within max(max_distance_m, max_person_speed_m_s x the time since it was last seen). At 2 fps
  // walking people (0.8 m/s) got a new id nearly every frame; from 4 fps on the distance decides.
  double max_person_speed_m_s = 2.0;
  int max_missing_frames = 3;   // a lost person is still returned (last pose) this many frames
  // A joint post-processing filled from its neighbour keeps, instead, its offset from that
  // neighbour in the track's last output (when both were present there).
  bool hold_missing_joints = true;
};

template <class Visitor, OptionsOf<TrackOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, OptionSpec{.help = "persistent ids across frames (ablation: false)"});
  v("max_distance_m", o.max_distance_m,
    OptionSpec{.help = "mean core-joint distance to continue a track", .unit = "m", .min = 0,
               .min_exclusive = true});
  v("max_person_speed_m_s", o.max_person_speed_m_s,
    OptionSpec{.help = "at low frame rates: a track continues within max(max_distance_m, this x the time since it "
                       "was last seen)",
               .unit = "m/s", .min = 0, .max = 1e6});
  v("max_gap_s", o.max_gap_s,
    OptionSpec{.help = "frames further apart (or with unknown time) start afresh: no coasting, no pre-filter",
               .unit = "s", .min = 0, .max = 1e9});
  v("max_missing_frames", o.max_missing_frames,
    OptionSpec{.help = "a lost person is still returned (last pose) this many frames", .min = 0, .max = 1e6});
  v("hold_missing_joints", o.hold_missing_joints,
    OptionSpec{.help = "a missing joint of a tracked person keeps its offset from its neighbour joint in the "
                       "track's last output (else it sits on the neighbour)"});
}

// Step 14.
struct ClipSpeedOptions {
  bool enabled = true;
  double max_speed_m_s = 10.0;  // per joint, between consecutive outputs of one track
};

template <class Visitor, OptionsOf<ClipSpeedOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, OptionSpec{.help = "clip each joint's speed per track (needs track.enabled)"});
  v("max_speed_m_s", o.max_speed_m_s,
    OptionSpec{.help = "maximum joint speed between consecutive outputs of one track", .unit = "m/s", .min = 0,
               .min_exclusive = true});
}

// Step 15 (optional, off by default): per-track bone-length consistency. Each track keeps the
// lengths of each limb over its last `window` observations; once a limb has `min_observations`,
// a length differing from their median by more than max(tolerance_rel x median, min_tolerance_m)
// makes the limb disagree. The joints explaining the disagreeing limbs (a wrist moved 30 cm: its
// forearm disagrees, the elbow's upper arm does not) are marked missing and, with
// postprocess.fill_missing_joints, filled from their neighbour like in step 12
// (bone_lengths.h). Off by default until it is shown to help on real detections.
struct BoneLengthOptions {
  bool enabled = false;
  double tolerance_rel = 0.25;   // relative disagreement with the track's running length
  double min_tolerance_m = 0.05; // floor of the tolerance, for short bones (hands, face)
  int min_observations = 10;     // a limb is checked once its track has observed it this often
  int window = 50;               // observations per limb the running median is taken over
};

template <class Visitor, OptionsOf<BoneLengthOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled,
    OptionSpec{.help = "mark joints whose bones disagree with their track's lengths (needs track.enabled)"});
  v("tolerance_rel", o.tolerance_rel,
    OptionSpec{.help = "a limb disagrees beyond this fraction of its track's running length", .min = 0.01,
               .max = 10});
  v("min_tolerance_m", o.min_tolerance_m,
    OptionSpec{.help = "floor of the tolerance (short bones: hands, face)", .unit = "m", .min = 0, .max = 10});
  v("min_observations", o.min_observations,
    OptionSpec{.help = "a limb is checked once its track has observed it this often (<= window)", .min = 1,
               .max = 10000});
  v("window", o.window,
    OptionSpec{.help = "observations per limb the running median is taken over", .min = 1, .max = 10000});
}

// Temporal smoothing of tracked persons (off by default until it is shown to help on real
// detections):
//   causal  = step 16 inside the pipeline: a constant-velocity Kalman filter per track and joint
//             (white-noise acceleration model; at a fixed frame rate its gains settle to those
//             of an alpha-beta filter), time-aware (dt from the timestamps), online, no lag on
//             constant velocity;
//   offline = after Triangulator::Process, frames held back by their window (OfflineSmoother,
//             offline_smoother.h): per track and joint, a Gaussian-weighted local polynomial fit
//             in time (Savitzky-Golay generalised to uneven times and missing frames), two-sided,
//             so no lag in the positions, but each frame comes out 3 offline_sigma_s late.
// Neither smooths across a gap of more than track.max_gap_s or an unknown time.
enum class SmoothMode { kOff, kCausal, kOffline };
template <>
struct EnumNames<SmoothMode> {
  static constexpr std::array<std::pair<SmoothMode, std::string_view>, 3> values = {
      {{SmoothMode::kOff, "off"}, {SmoothMode::kCausal, "causal"}, {SmoothMode::kOffline, "offline"}}};
};

struct SmoothOptions {
  SmoothMode mode = SmoothMode::kOff;
  // causal: the filter's gains grow with acceleration_m_s2 x dt^2 / measurement_noise_m: more
  // acceleration or less noise follows the input more closely, the reverse smooths more.
  double measurement_noise_m = 0.02;  // m, standard deviation of a triangulated joint's error
  double acceleration_m_s2 = 10.0;    // m/s^2, standard deviation of a joint's acceleration
  // offline
  double offline_sigma_s = 0.1;  // s, standard deviation of the Gaussian time weights (window +-3 sigma)
  int offline_degree = 2;        // degree of the local polynomial (1: exact on constant velocity,
                                 // 2: also on constant acceleration)
};

template <class Visitor, OptionsOf<SmoothOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("mode", o.mode,
    OptionSpec{.help = "smoothing of tracked persons: causal (Kalman filter, online) or offline (two-sided, frames "
                       "delayed by 3 offline_sigma_s; needs track.enabled)"});
  v("measurement_noise_m", o.measurement_noise_m,
    OptionSpec{.help = "causal: standard deviation of a triangulated joint's error", .unit = "m", .min = 1e-6,
               .max = 100});
  v("acceleration_m_s2", o.acceleration_m_s2,
    OptionSpec{.help = "causal: standard deviation of a joint's acceleration (higher: smooths less)",
               .unit = "m/s^2", .min = 1e-6, .max = 1e6});
  v("offline_sigma_s", o.offline_sigma_s,
    OptionSpec{.help = "offline: standard deviation of the Gaussian time weights (window +-3 sigma)", .unit = "s",
               .min = 1e-4, .max = 1e3});
  v("offline_degree", o.offline_degree,
    OptionSpec{.help = "offline: degree of the local polynomial (1: exact on constant velocity, 2: also on "
                       "constant acceleration)",
               .min = 1, .max = 3});
}

struct TriangulatorOptions {
  UndistortOptions undistort;
  PrefilterOptions prefilter;
  TriangulateOptions triangulate;
  RoomCheckOptions room_check;
  ScoreOptions score;
  FilterOptions filter;
  GroupOptions group;
  MergeOptions merge;
  RefineOptions refine;
  VerifyOptions verify;
  SingleViewOptions single_view;
  PostprocessOptions postprocess;
  TrackOptions track;
  ClipSpeedOptions clip_speed;
  BoneLengthOptions bone_lengths;
  SmoothOptions smooth;

  // Joints with a score at or below this are not observations for the temporal steps
  // (bone_lengths, smooth): missing ones (0) and those filled by post-processing.
  double UnobservedScore() const {
    return postprocess.enabled && postprocess.fill_missing_joints ? postprocess.filled_joint_score : 0.0;
  }

  // Empty when valid; otherwise "section.key: problem" for the first invalid value (the ranges of
  // VisitFields, then the checks between fields).
  std::string Check() const;
  // Settings that are valid but have no effect with the others ("clip_speed.enabled=true has no
  // effect with track.enabled=false ..."), one line each.
  std::vector<std::string> Warnings() const;
};

// Names each section once, in pipeline order: the config-file sections, the `section.` prefix of
// --set keys and the order of `rpt config --dump`.
template <class Visitor, OptionsOf<TriangulatorOptions> Self>
void VisitSections(Visitor& v, Self& o) {
  v("undistort", o.undistort);
  v("prefilter", o.prefilter);
  v("triangulate", o.triangulate);
  v("room_check", o.room_check);
  v("score", o.score);
  v("filter", o.filter);
  v("group", o.group);
  v("merge", o.merge);
  v("refine", o.refine);
  v("verify", o.verify);
  v("postprocess", o.postprocess);
  v("single_view", o.single_view);
  v("track", o.track);
  v("clip_speed", o.clip_speed);
  v("bone_lengths", o.bone_lengths);
  v("smooth", o.smooth);
}

}  // namespace rpt
