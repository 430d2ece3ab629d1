// SPDX-License-Identifier: MIT
// Step 14: clip each tracked joint's movement to max_speed_m_s since its track's last update.
// Unlike a smoothing filter this adds no latency: a joint moving plausibly is untouched.
#pragma once

#include "core/pipeline/options.h"
#include "core/pipeline/track.h"
#include "core/poses.h"

namespace rpt {

namespace steps {

// Clips the first `num_detected` persons against their tracks' last poses. Returns the number
// of joints clipped.
int ClipSpeed(const ClipSpeedOptions& options, const Tracker& tracker, double timestamp_s, int num_detected,
              Poses3D* persons);

}  // namespace steps

}  // namespace rpt
