// SPDX-License-Identifier: MIT
// Per-frame statistics: what each step produced and how long it took (steps.h), and the extra
// counters. Every step reports into this one struct.
#pragma once

#include <array>

#include "core/pipeline/steps.h"

namespace rpt {

struct FrameStats {
  // Steady-clock time of each step (microseconds) and of the whole frame. With smooth.mode =
  // offline, the OfflineSmoother (offline_smoother.h) adds its time for the frame to
  // time_us[smooth] and total_us when it hands the frame back.
  std::array<double, kNumSteps> time_us{};
  double total_us = 0;
  // Items after each step: kSteps[s].item. The tracking steps (track .. smooth) record 0 here and
  // in time_us when they do not run; a disabled filtering step counts the items it passes on.
  std::array<int, kNumSteps> count{};
  // Extra counters.
  int pruned_limbs = 0;       // joints invalidated by limb pruning (steps 7 and 10)
  int small_groups = 0;       // groups dropped by min_group_size
  int conflicting_proposals = 0;  // proposals removed because their 2D poses belong to another person
  int mirrored_groups = 0;    // groups dropped as left/right-swapped duplicates of another group
  int unsupported_persons = 0;  // verify: persons dropped because more views see nobody there than see them
  int duplicate_persons = 0;    // verify: persons dropped as another, stronger person made from other views
  int single_view_persons = 0;  // single_view: persons placed from one view
  int single_view_tracked = 0;      // single_view: of the persons placed, those at their track's depth
  int single_view_implausible = 0;  // single_view with ground_prior: poses not lifted (no floor point,
                                    // body size, posture or outside the room)
  int replaced_joints = 0;    // post-processing: implausible joints replaced by a neighbour
  int filled_joints = 0;      // missing joints filled from a neighbour (post-processing, and
                              // joints marked missing by bone_lengths)
  int new_tracks = 0;         // tracking: tracks started this frame
  int coasting_tracks = 0;    // tracking: lost persons returned with their last pose
  int one_view_joints = 0;    // refine (one_view_joints): joints placed from the one view that saw them
  int held_joints = 0;        // tracking (hold_missing_joints): filled joints the track step placed at
                              // their track's offset (bone_lengths' refills are held too, not counted)
  int bone_length_corrections = 0;  // bone_lengths: joints marked missing (bones disagree with their track)
  double noise_m = 0;         // adaptive scoring: the estimated detection noise (m), 0 with a fixed scale

  void Reset() { *this = FrameStats{}; }
};

}  // namespace rpt
