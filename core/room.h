// SPDX-License-Identifier: MIT
// The room a scene happens in: an axis-aligned box, a property of the scene (datasets give it with
// their sequences, datasets/sequence.h). The Triangulator resolves it once into its model
// (core/pipeline/model.h) from room_check.center_m and room_check.size_m (callers fill those from
// the dataset unless the user set them, UseDatasetRoomIfUnset in core/pipeline/room_check.h).
// Step 5 (room_check) drops proposals outside it and step 12 (postprocess, drop_outside_room)
// persons, each with the margin of its own options.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace rpt {

struct Room {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // per axis; <= 0 leaves the axis unbounded

  // False when every axis is unbounded (no room known).
  bool bounded() const { return (size_m.array() > 0).any(); }
  // True when `point` lies inside the box grown by `margin_m` on every bounded axis.
  bool Contains(const Eigen::Vector3d& point, double margin_m) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (size_m[axis] <= 0) continue;
      if (std::abs(point[axis] - center_m[axis]) > 0.5 * size_m[axis] + margin_m) return false;
    }
    return true;
  }
};

}  // namespace rpt
