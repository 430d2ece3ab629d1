// SPDX-License-Identifier: MIT
// Step 14: clip each tracked joint's movement to max_speed_m_s since its track's last update.
// Unlike a smoothing filter this adds no latency: a joint moving plausibly is untouched.
#pragma once

#include "core/pipeline/options.h"
#include "core/pipeline/track.h"
#include "core/poses.h"

namespace rpt {

namespace steps {

struct ClipSpeedInput {
  const Tracks& tracks;  // the tracks' last poses and times (remember committed them)
  double timestamp_s;    // this frame's time
  int num_detected;      // the persons detected this frame (the coasting ones follow them)
};

// Clips the detected persons of `persons` (track's output) against their tracks' last poses.
// Returns the number of joints clipped.
int ClipSpeed(const ClipSpeedOptions& options, const ClipSpeedInput& in, Poses3D* persons);

}  // namespace steps

}  // namespace rpt
