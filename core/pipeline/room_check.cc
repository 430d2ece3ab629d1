// SPDX-License-Identifier: MIT
#include "core/pipeline/room_check.h"

#include <cmath>

namespace rpt {

bool InsideRoom(const Eigen::Vector3d& point, const RoomCheckOptions& room) {
  for (int axis = 0; axis < 3; ++axis) {
    if (room.size_m[axis] <= 0) continue;
    if (std::abs(point[axis] - room.center_m[axis]) > 0.5 * room.size_m[axis] + room.margin_m) return false;
  }
  return true;
}

void UseDatasetRoomIfUnset(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m, RoomCheckOptions* room) {
  if ((room->size_m.array() > 0).any()) return;
  room->center_m = center_m;
  room->size_m = size_m;
}

int steps::RoomCheck(const RoomCheckOptions& room, Proposals* proposals) {
  const bool bounded = (room.size_m.array() > 0).any();
  if (!bounded) return proposals->size();
  const int n = proposals->num_joints;
  int kept = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    int valid = 0;
    for (int i = 0; i < n; ++i) {
      const size_t idx = static_cast<size_t>(k) * n + i;
      if (proposals->score[idx] <= 0) continue;
      center += proposals->xyz[idx];
      ++valid;
    }
    if (valid == 0 || !InsideRoom(center / valid, room)) continue;
    proposals->Move(k, kept++);
  }
  proposals->Truncate(kept);
  return kept;
}

}  // namespace rpt
