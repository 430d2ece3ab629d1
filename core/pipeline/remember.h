// SPDX-License-Identifier: MIT
// Bookkeeping after the last step (not a paper step): keep this frame's output for the next frame.
// The pre-filter (step 2) compares the next frame's poses with these persons' core joints, and
// the tracks store each track's output pose, which speed clipping (step 14) and coasting refer
// to.
#pragma once

#include <span>

#include "core/pipeline/prefilter.h"
#include "core/pipeline/track.h"
#include "core/poses.h"

namespace rpt {
namespace steps {

struct RememberInput {
  std::span<const int> core_joints;  // output-joint indices of the core joints
  const Poses3D& persons;            // the frame's output
  int first_lifted;                  // the single-view persons [first_lifted, first_lifted + num_lifted):
  int num_lifted;                    // their depth is a guess, the pre-filter does not use them
  int num_detected;                  // the persons detected this frame (the coasting ones follow them)
  double timestamp_s;                // this frame's time
};

// Stores the core joints of the persons (but the single-view ones) in `previous` and, when
// `tracks` is not null (tracking on), commits the detected persons as their tracks' last poses.
// Returns the number of persons remembered for the pre-filter.
int Remember(const RememberInput& in, PreviousPersons* previous, Tracks* tracks);

}  // namespace steps
}  // namespace rpt
