// SPDX-License-Identifier: MIT
// The step table: the one place that names the pipeline's steps. For every step it gives the key
// (= config section where the step has options, timing and count row, file stem, and function
// name in CamelCase), the paper's step number (Bermuth et al., CVPR 2026, section 3.1; "–" for
// our own bookkeeping), a title (the heading of the step in docs/algorithm.md), the item counted
// in FrameStats::count, the options section it reads and its source file. The timing and count
// rows (metrics/, steps.csv, `rpt bench`) and docs/algorithm.md's step table derive from it;
// step_functions.h binds each key to its function and options member (and does not compile when
// they disagree with this table); tests/pipeline/step_table_test.cc fails when the docs, the
// files or the options sections disagree.
#pragma once

#include <array>
#include <string_view>

namespace rpt {

// The steps that run per frame, in execution order; each has a slot in FrameStats.
enum class Step : int {
  kUndistort = 0,
  kMakePairs,
  kPrefilter,
  kTriangulateCore,
  kRoomCheck,
  kScore,
  kFilter,
  kGroup,
  kTriangulateFull,
  kMerge,
  kRefine,
  kVerify,
  kPostprocess,
  kSingleView,
  kTrack,
  kClipSpeed,
  kBoneLengths,
  kSmooth,
  kRemember,
  kCount
};
inline constexpr int kNumSteps = static_cast<int>(Step::kCount);

struct StepInfo {
  std::string_view key;      // snake_case name: config section, timing row, file stem
  std::string_view number;   // the paper's step number, "–" when the paper has none
  std::string_view title;    // docs/algorithm.md heading ("## <number>. <title>")
  std::string_view item;     // what FrameStats::count holds after the step ("" when not per frame)
  std::string_view section;  // options section it reads ("" when none)
  std::string_view file;     // source file, relative to the repository root
};

// Per-frame steps, indexed by Step.
inline constexpr std::array<StepInfo, kNumSteps> kSteps = {{
    {"undistort", "–", "Undistortion", "poses", "undistort", "core/pipeline/undistort.cc"},
    {"make_pairs", "1", "Pairs", "pairs", "", "core/pipeline/make_pairs.cc"},
    {"prefilter", "2", "Pre-filter with the last frame", "pairs", "prefilter", "core/pipeline/prefilter.cc"},
    {"triangulate_core", "4", "Triangulation of the core joints", "proposals", "triangulate",
     "core/pipeline/triangulate_core.cc"},
    {"room_check", "5", "Room check", "proposals", "room_check", "core/pipeline/room_check.cc"},
    {"score", "6-7", "Reprojection and scoring", "proposals", "score", "core/pipeline/score.cc"},
    {"filter", "8", "Filter", "proposals", "filter", "core/pipeline/filter.cc"},
    {"group", "9", "Grouping in 3D", "groups", "group", "core/pipeline/group.cc"},
    {"triangulate_full", "10", "Full triangulation", "proposals", "triangulate", "core/pipeline/triangulate_full.cc"},
    {"merge", "11", "Merge", "persons", "merge", "core/pipeline/merge.cc"},
    {"refine", "11a", "Multi-view refinement", "joints refined", "refine", "core/pipeline/refine.cc"},
    {"verify", "11b", "Verification against all views", "persons", "verify", "core/pipeline/verify.cc"},
    {"postprocess", "12", "Post-processing", "persons", "postprocess", "core/pipeline/postprocess.cc"},
    {"single_view", "12b", "Persons seen by one camera", "persons", "single_view", "core/pipeline/single_view.cc"},
    {"track", "13", "Tracking", "persons", "track", "core/pipeline/track.cc"},
    {"clip_speed", "14", "Speed clipping", "joints clipped", "clip_speed", "core/pipeline/clip_speed.cc"},
    {"bone_lengths", "15", "Bone lengths", "joints checked", "bone_lengths", "core/pipeline/bone_lengths.cc"},
    {"smooth", "16", "Smoothing", "joints smoothed", "smooth", "core/pipeline/smooth.cc"},
    {"remember", "–", "Remember this frame", "persons remembered", "", "core/pipeline/remember.cc"},
}};

// Step 3 runs once, when the Triangulator is built (the core joints do not change from frame to
// frame), so it has no slot in FrameStats.
inline constexpr StepInfo kChooseCoreJoints = {"choose_core_joints", "3", "Core joints", "", "triangulate",
                                               "core/pipeline/choose_core_joints.cc"};

// Every step in the paper's order (the per-frame ones and step 3).
inline constexpr std::array<StepInfo, kNumSteps + 1> kAllSteps = [] {
  std::array<StepInfo, kNumSteps + 1> all{};
  int n = 0;
  for (int s = 0; s < kNumSteps; ++s) {
    if (s == static_cast<int>(Step::kTriangulateCore)) all[n++] = kChooseCoreJoints;
    all[n++] = kSteps[s];
  }
  return all;
}();

constexpr const StepInfo& Info(Step step) { return kSteps[static_cast<int>(step)]; }

}  // namespace rpt
