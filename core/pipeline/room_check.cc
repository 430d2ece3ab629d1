// SPDX-License-Identifier: MIT
#include "core/pipeline/room_check.h"

namespace rpt {

void UseDatasetRoomIfUnset(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m, RoomCheckOptions* room) {
  if ((room->size_m.array() > 0).any()) return;
  room->center_m = center_m;
  room->size_m = size_m;
}

int steps::RoomCheck(const RoomCheckOptions& options, const Room& room, Proposals* proposals) {
  if (!room.bounded()) return proposals->size();
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
    if (valid == 0 || !room.Contains(center / valid, options.margin_m)) continue;
    proposals->Move(k, kept++);
  }
  proposals->Truncate(kept);
  return kept;
}

}  // namespace rpt
