// SPDX-License-Identifier: MIT
// Bookkeeping after the last step (not a paper step): keep this frame's output for the next frame.
// The pre-filter (step 2) compares the next frame's poses with these persons' core joints, and
// the tracker stores each track's output pose, which speed clipping (step 14) and coasting refer
// to.
#pragma once

#include <span>

#include "core/pipeline/prefilter.h"
#include "core/pipeline/track.h"
#include "core/poses.h"

namespace rpt {
namespace steps {

// Stores the core joints of `persons` in `previous`, except the single-view persons
// [first_lifted, first_lifted + num_lifted) (their depth is a guess), and, when `tracker` is not
// null, commits the first `num_detected` persons as their tracks' last poses. Returns the number
// of persons remembered for the pre-filter.
int Remember(std::span<const int> core_joints, const Poses3D& persons, int first_lifted, int num_lifted,
             int num_detected, double timestamp_s, PreviousPersons* previous, Tracker* tracker);

}  // namespace steps
}  // namespace rpt
