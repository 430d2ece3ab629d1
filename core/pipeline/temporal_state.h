// SPDX-License-Identifier: MIT
// The Triangulator's state carried from one frame to the next, each part owned by the step that
// keeps it: the previous frame's persons (remember, for the pre-filter), the tracks (track), the
// per-track bone lengths (bone_lengths) and joint filters (smooth), the detection noise estimate
// (score, adaptive scale), and the last frame's time.
#pragma once

#include <limits>

#include "core/pipeline/bone_lengths.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/prefilter.h"
#include "core/pipeline/smooth.h"
#include "core/pipeline/track.h"

namespace rpt {

struct TemporalState {
  PreviousPersons previous;        // remember -> prefilter
  Tracks tracks;                   // track, clip_speed, remember
  BoneLengthHistory bone_lengths;  // per-track running limb lengths
  JointFilters joint_filters;      // per-track joint filters (smooth)
  NoiseScale noise;                // adaptive scoring: the detections' noise level
  double last_timestamp_s = std::numeric_limits<double>::quiet_NaN();

  // Forgets everything (a new sequence).
  void Reset(int num_core_joints, double noise_prior_m) {
    StartAfresh(num_core_joints);
    tracks.Reset();
    bone_lengths.Reset();
    joint_filters.Reset();
    noise.Reset(noise_prior_m);
    last_timestamp_s = std::numeric_limits<double>::quiet_NaN();
  }
  // A frame not continuous with the last one: no pre-filter, tracks end. The noise estimate stays.
  void StartAfresh(int num_core_joints) {
    previous.Clear(num_core_joints);
    tracks.EndTracks();
  }
};

}  // namespace rpt
