// SPDX-License-Identifier: MIT
// Step 15 (optional, bone_lengths.enabled): per-track bone-length consistency.
//
// A person's limbs keep their length; a joint whose bones suddenly disagree with the lengths its
// track has shown so far is most likely a wrong triangulation (a wrist of the wrong person, a
// left/right mix-up in some views). Per track and limb (the limbs of core/joints.h LimbsFor), the
// lengths of the last `window` frames in which both joints were observed are kept; their median
// is the running length once there are `min_observations`. In a frame, a limb disagrees when its
// length differs from the running length by more than max(tolerance_rel x length,
// min_tolerance_m). Then, repeatedly, the joint with the most disagreeing limbs (ties: the larger
// share of its checked limbs disagreeing, then the distal joint of a disagreeing limb) is marked
// missing (score 0) and its limbs are no longer considered, until no disagreeing limb is left: a
// wrist moved 30 cm disagrees with its forearm only, while the elbow still agrees with its upper
// arm, so the wrist is marked. Marked joints are then filled from their neighbour like in
// post-processing (when it fills), so every output person keeps a complete skeleton.
//
// Joints at or below the unobserved score (missing, or filled by post-processing: a filled wrist
// sits on its elbow) are not observations: their limbs are neither checked nor recorded. Every
// observed length is recorded, also those of disagreeing limbs; the median ignores them while they
// are a minority, and adapts if the first lengths of a track were the wrong ones. Coasting persons
// (after the first num_detected) and untracked persons are left as is.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/track.h"
#include "core/pipeline/track_states.h"
#include "core/poses.h"

namespace rpt {

// Per track: the lengths of each limb over its last `window` observations, carried from frame to
// frame in reusable slots (track_states.h).
struct BoneLengthHistory {
  struct Track {
    std::vector<double> lengths;  // per limb: ring buffer of `window` observed lengths (m)
    std::vector<int> observed;    // per limb: observations recorded so far
  };
  void Reset() { tracks.Clear(); }
  TrackStates<Track> tracks;
};

// Reused per-frame buffers of the step.
struct BoneLengthsScratch {
  std::vector<double> length;    // per limb: this frame's length, < 0 = not observed
  std::vector<double> expected;  // per limb: the track's running length, < 0 = not known yet
  std::vector<char> disagrees;   // per limb
  std::vector<char> active;      // per limb: both joints still unmarked
  std::vector<int> num_checked;  // per joint: active checkable limbs
  std::vector<int> num_bad;      // per joint: active disagreeing limbs
  std::vector<char> distal_bad;  // per joint: distal joint of an active disagreeing limb
  std::vector<double> median;    // scratch for the median
  std::vector<char> settled;     // per joint: HoldFilledJoints' scratch
};

namespace steps {

struct BoneLengthsInput {
  std::span<const ResolvedLimb> limbs;  // limbs between the persons' joints
  std::span<const int> neighbour;       // per joint: the joint filling it, -1 = none
  double unobserved_score;              // joints at or below are not observations; marked joints are
                                        // filled with this score when > 0 (post-processing's fill)
  int num_detected;                     // the persons detected this frame (the coasting ones follow them)
  const Tracks* tracks = nullptr;       // with track.hold_missing_joints: marked joints are held (track.h)
};

// Checks the detected persons of `persons` (the frame's output so far). Adds marked joints to
// stats->bone_length_corrections and their fills to stats->filled_joints. Returns the number of
// joints checked (with at least one limb whose running length is known). Does nothing unless
// options.enabled.
int BoneLengths(const BoneLengthOptions& options, const BoneLengthsInput& in, BoneLengthHistory* history,
                BoneLengthsScratch* scratch, Poses3D* persons, FrameStats* stats);

}  // namespace steps

}  // namespace rpt
