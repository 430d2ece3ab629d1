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

// The one rule for where the room comes from: the user's room_check.center_m/size_m when any
// size component is set (> 0), else the dataset's room (`center_m`, `size_m`). Every caller that
// runs a Triangulator on a dataset (eval, bench) applies it.
void UseDatasetRoomIfUnset(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m, RoomCheckOptions* room);

namespace steps {

// Compacts `proposals` to those inside the room. Returns the number kept.
int RoomCheck(const RoomCheckOptions& room, Proposals* proposals);

}  // namespace steps

}  // namespace rpt
