// SPDX-License-Identifier: MIT
// The Triangulator's state carried from one frame to the next: the previous frame's persons (for
// the pre-filter), the tracks, the per-track bone lengths and filters, the detection noise
// estimate of the adaptive score, and the last frame's time.
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
  Tracker tracker;                 // track, clip_speed, remember
  BoneLengthChecker bone_lengths;  // per-track running limb lengths
  TrackSmoother smoother;          // per-track joint filters
  NoiseScale noise;                // adaptive scoring: the detections' noise level
  double last_timestamp_s = std::numeric_limits<double>::quiet_NaN();

  // Forgets everything (a new sequence).
  void Reset(int num_core_joints, double noise_prior_m) {
    StartAfresh(num_core_joints);
    tracker.Reset();
    bone_lengths.Reset();
    smoother.Reset();
    noise.Reset(noise_prior_m);
    last_timestamp_s = std::numeric_limits<double>::quiet_NaN();
  }
  // A frame not continuous with the last one: no pre-filter, tracks end. The noise estimate stays.
  void StartAfresh(int num_core_joints) {
    previous.Clear(num_core_joints);
    tracker.EndTracks();
  }
};

}  // namespace rpt
