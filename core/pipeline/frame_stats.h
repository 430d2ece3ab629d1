// SPDX-License-Identifier: MIT
// Per-frame statistics: what each step produced and how long it took.
#pragma once

#include <array>
#include <iterator>
#include <string_view>

namespace rpt {

// The pipeline steps in execution order. Names match code, config sections and docs.
enum class Step : int {
  kUndistort = 0,    // undistort 2D poses, add derived joints
  kPairs,            // (1) all cross-view pose pairs
  kPrefilter,        // (2) filter pairs with last frame's poses
  kTriangulateCore,  // (3-4) triangulate core joints of each pair
  kRoomCheck,        // (5) drop proposals outside the room
  kScore,            // (6-7) reproject, score joints, prune limbs
  kFilter,           // (8) drop pairs under min_match_score
  kGroup,            // (9) group proposals in 3D
  kTriangulateFull,  // (10) re-triangulate grouped pairs with all joints
  kMerge,            // (11) robust per-joint merge per group
  kVerify,           // (11b) re-score persons against all views
  kPostprocess,      // (12) drop invalid persons, fill joints
  kSingleView,       // (12b) persons seen by one camera only (off by default)
  kTrack,            // (13) track ids over time
  kClipSpeed,        // (14) clip joint speed
  kBoneLengths,      // (15) per-track bone-length consistency (optional)
  kSmooth,           // (16) causal temporal smoothing (optional)
  kCount
};
inline constexpr int kNumSteps = static_cast<int>(Step::kCount);

inline constexpr std::array<std::string_view, kNumSteps> kStepNames = {
    "undistort", "pairs", "prefilter", "triangulate_core", "room_check", "score", "filter",
    "group", "triangulate_full", "merge", "verify", "postprocess", "single_view", "track", "clip_speed",
    "bone_lengths", "smooth"};

// What FrameStats::count holds after each step (kStepNames order).
inline constexpr std::string_view kStepItems[] = {
    "poses",     "pairs",   "pairs",   "proposals", "proposals", "proposals",      "proposals",
    "groups",    "proposals", "persons", "persons", "persons",   "persons",        "persons",
    "joints clipped", "joints checked", "joints smoothed"};
static_assert(std::size(kStepItems) == kNumSteps, "one item name per step");

struct FrameStats {
  // Steady-clock time of each step (microseconds) and of the whole frame.
  std::array<double, kNumSteps> time_us{};
  double total_us = 0;
  // Items after each step: kStepItems.
  std::array<int, kNumSteps> count{};
  // Extra counters.
  int pruned_limbs = 0;       // joints invalidated by limb pruning (steps 7 and 10)
  int small_groups = 0;       // groups dropped by min_group_size
  int conflicting_proposals = 0;  // proposals removed because their 2D poses belong to another person
  int mirrored_groups = 0;    // groups dropped as left/right-swapped duplicates of another group
  int unsupported_persons = 0;  // verify: persons dropped because more views see nobody there than see them
  int single_view_persons = 0;  // single_view: persons placed from one view
  int replaced_joints = 0;    // post-processing: implausible joints replaced by a neighbour
  int filled_joints = 0;      // missing joints filled from a neighbour (post-processing, and
                              // joints marked missing by bone_lengths)
  int new_tracks = 0;         // tracking: tracks started this frame
  int coasting_tracks = 0;    // tracking: lost persons returned with their last pose
  int bone_length_corrections = 0;  // bone_lengths: joints marked missing (bones disagree with their track)
  double noise_m = 0;         // adaptive scoring: the estimated detection noise (m), 0 with a fixed scale

  void Reset() { *this = FrameStats{}; }
};

}  // namespace rpt
