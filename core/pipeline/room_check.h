// SPDX-License-Identifier: MIT
// Step 5: drop proposals whose centre (mean of their valid joints) lies outside the room (core/room.h)
// plus room_check.margin_m. Without a room (every axis unbounded) nothing is dropped.
#pragma once

#include <Eigen/Core>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/room.h"

namespace rpt {

// The one rule for where the room comes from: the user's room_check.center_m/size_m when any
// size component is set (> 0), else the dataset's room (`center_m`, `size_m`). Every caller that
// runs a Triangulator on a dataset (eval, bench) applies it.
void UseDatasetRoomIfUnset(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m, RoomCheckOptions* room);

namespace steps {

// `room`: the scene's room (the Triangulator's model). Compacts `proposals` to those inside it.
// Returns the number kept.
int RoomCheck(const RoomCheckOptions& options, const Room& room, Proposals* proposals);

}  // namespace steps

}  // namespace rpt
