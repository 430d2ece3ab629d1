// SPDX-License-Identifier: MIT
// Step 13: assign persistent track ids over time.
//
// Each person is compared with the last pose of every live track (mean distance over the
// joints valid in both, at least 3). Pairs below max_distance_m are assigned greedily by
// increasing distance; unassigned persons start new tracks. A track that finds no person is
// kept for max_missing_frames frames, during which its last pose is returned ("coasting"), then
// it ends. Tracking does not smooth.
#pragma once

#include <span>
#include <tuple>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

class Tracker {
 public:
  void Reset();
  // Ends every track (continuity broken: unknown time or a large gap); ids keep counting up.
  void EndTracks();

  // Sets persons->track_ids and appends coasting persons. `match_joints` are the joints used
  // for the distance. Returns the number of persons that were detected this frame (the
  // coasting ones follow them).
  int Assign(const TrackOptions& options, std::span<const int> match_joints, Poses3D* persons, FrameStats* stats);

  // The stored pose (num_joints x 4, column-major) and time of a track, or nullptr.
  const double* LastPose(int track_id, double* timestamp_s) const;

  // Stores the poses of the first `num_detected` persons as their tracks' last poses.
  void Commit(const Poses3D& persons, int num_detected, double timestamp_s);

 private:
  struct Track {
    int id = -1;  // -1 = free slot
    int missing = 0;
    double timestamp_s = 0;
    std::vector<double> pose;  // num_joints * 4
  };
  int FindSlot(int track_id) const;

  std::vector<Track> tracks_;
  int next_id_ = 0;
  std::vector<std::tuple<double, int, int>> candidates_;  // (distance, person, slot)
  std::vector<int> person_slot_;
  std::vector<char> slot_used_;
};

}  // namespace rpt
