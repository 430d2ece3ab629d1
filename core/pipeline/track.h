// SPDX-License-Identifier: MIT
// Step 13: assign persistent track ids over time.
//
// Each person is compared with the last pose of every live track (mean distance over the
// joints valid in both, at least 3). Pairs below max_distance_m are assigned greedily by
// increasing distance; unassigned persons start new tracks. A track that finds no person is
// kept for max_missing_frames frames, during which its last pose is returned ("coasting"), then
// it ends. Tracking does not smooth.
#pragma once

#include <limits>
#include <span>
#include <tuple>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

// The live tracks, carried from frame to frame: step 13 assigns persons to them, speed clipping
// (step 14) reads their last poses, and remember commits each frame's output to them.
struct Tracks {
  struct Slot {
    int id = -1;  // -1 = free slot
    int missing = 0;
    double timestamp_s = 0;
    // Time of the last output with a joint seen by two views (triangulated or smoothed, none
    // lifted from one view); -infinity until then. single_view's track_assist reads it.
    double supported_s = -std::numeric_limits<double>::infinity();
    std::vector<double> pose;  // num_joints * 4, the track's last output
  };
  std::vector<Slot> slots;
  int next_id = 0;

  // Forgets every track; ids start again from 0 (a new sequence).
  void Reset();
  // Ends every track (continuity broken: unknown time or a large gap); ids keep counting up.
  void EndTracks();
  // The slot of track `track_id`, -1 when it has none.
  int FindSlot(int track_id) const;
  // The stored pose (num_joints x 4, column-major) and time of a track, or nullptr (no such track,
  // or one started this frame).
  const double* LastPose(int track_id, double* timestamp_s) const;
  // Stores the poses of the first `num_detected` persons as their tracks' last poses (and the time
  // as supported_s when the person has a multi-view joint and no joint lifted from one view).
  void Commit(const Poses3D& persons, int num_detected, double timestamp_s);
};

// Reused buffers of the track step.
struct TrackScratch {
  std::vector<std::tuple<double, int, int>> candidates;  // (distance, person, slot)
  std::vector<int> person_slot;
  std::vector<char> slot_used;
};

namespace steps {

// Sets persons->track_ids of the frame's persons (post-processing's output) and appends the
// coasting persons after them. `match_joints` (the core joints) are the joints compared.
// Counts stats->new_tracks and stats->coasting_tracks. Returns the number of persons (detected
// and coasting).
int Track(const TrackOptions& options, std::span<const int> match_joints, Tracks* tracks, TrackScratch* scratch,
          Poses3D* persons, FrameStats* stats);

}  // namespace steps

}  // namespace rpt
