// SPDX-License-Identifier: MIT
// Step 13: assign persistent track ids over time.
//
// Each person is compared with the last pose of every live track: the mean distance over the
// match joints observed in both (score above the unobserved score: not filled); when fewer than
// 3 are, over those observed in the person and valid in the last pose; then over those valid in
// both (at least 3). Pairs below max_distance_m are assigned greedily by increasing distance;
// unassigned persons start new tracks. A track that finds no person is kept for
// max_missing_frames frames, during which its last pose is returned ("coasting"), then it ends.
// Tracking does not smooth.
//
// With hold_missing_joints, a joint of a continued track that post-processing filled from its
// neighbour (provenance kFilled) is placed at the neighbour's current position plus the offset
// between the two in the track's last output, when both were present there; otherwise it stays
// on its neighbour. Chains (a filled elbow and wrist) are placed from the torso outwards.
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
  std::vector<char> settled;  // per joint of a person: placed (observed, or held / refilled)
};

namespace steps {

struct TrackInput {
  std::span<const int> match_joints = {};  // the joints compared (the core joints)
  std::span<const int> neighbour = {};     // per joint: the joint post-processing fills it from,
                                           // -1 = none; empty: no joint is held
  double unobserved_score = 0;             // joints scored at or below this were filled, not observed
  double timestamp_s = 0;                  // the frame's time (finite: tracking runs on timed frames)
};

// Sets persons->track_ids of the frame's persons (post-processing's output), holds the missing
// joints of continued tracks (above) and appends the coasting persons. Counts stats->new_tracks,
// stats->coasting_tracks and stats->held_joints. Returns the number of persons (detected and
// coasting).
int Track(const TrackOptions& options, const TrackInput& in, Tracks* tracks, TrackScratch* scratch, Poses3D* persons,
          FrameStats* stats);

}  // namespace steps

}  // namespace rpt
