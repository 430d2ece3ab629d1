// SPDX-License-Identifier: MIT
// Step 5: drop proposals whose centre (mean of their valid joints) lies outside the room box
// (plus margin). Axes with size <= 0 are unbounded.
#pragma once

#include <Eigen/Core>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// True when `point` lies inside the room (+ margin) on every bounded axis.
bool InsideRoom(const Eigen::Vector3d& point, const RoomCheckOptions& room);

// Compacts `proposals` to those inside the room. Returns the number kept.
int RoomCheck(const RoomCheckOptions& room, Proposals* proposals);

}  // namespace rpt
