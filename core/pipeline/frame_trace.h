// SPDX-License-Identifier: MIT
// What the association steps (1-12) did with the 2D poses of one frame: which pose pairs each
// step kept, which group each kept pair joined, the person merged from each group, and which of
// those persons verification and post-processing kept. Triangulator::Process fills it when given
// one (a diagnostic: `rpt eval --loss-table` follows every ground-truth person through it,
// engine/loss_table.h); without one nothing is recorded.
#pragma once

#include <array>
#include <vector>

#include "core/poses.h"

namespace rpt {

struct FrameTrace {
  // The steps after which the pose pairs are recorded, in pipeline order.
  enum PairStage : int { kMakePairs = 0, kPrefilter, kTriangulateCore, kRoomCheck, kFilter, kNumPairStages };

  // Per usable pose (what undistort kept; poses with too few core joints are not here): its view
  // and its index among that view's input poses.
  std::vector<int> pose_view, pose_person;
  // The pose pairs (indices into the poses above, view of a < view of b) left after each stage.
  std::array<std::vector<std::array<int, 2>>, kNumPairStages> pairs;
  // Per pair left after filter (pairs[kFilter]): the group it joined, an index into `merged`; -1
  // when grouping dropped it (its pose belongs to a stronger group, its group was a mirrored
  // duplicate or too small).
  std::vector<int> group_of_pair;
  // The person merge made of each kept group (group g -> person g), after refine, before verification.
  Poses3D merged;
  // The persons left after verify and after postprocess, as indices into `merged`.
  std::vector<int> after_verify, after_postprocess;

  // Empties every list (capacity is kept).
  void Clear() {
    pose_view.clear();
    pose_person.clear();
    for (auto& list : pairs) list.clear();
    group_of_pair.clear();
    merged.Clear(0);
    after_verify.clear();
    after_postprocess.clear();
  }
};

}  // namespace rpt
