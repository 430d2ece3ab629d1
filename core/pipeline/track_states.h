// SPDX-License-Identifier: MIT
// Per-track state of the temporal steps (step 15 on), in reusable slots keyed by
// track id. A track that is no longer among a frame's output persons (detected or coasting) has
// ended (ids are never reused), so its slot is freed and later reused with its buffers: once warm,
// nothing is allocated.
#pragma once

#include <algorithm>
#include <vector>

#include "core/poses.h"

namespace rpt {

template <class State>
class TrackStates {
 public:
  void Clear() {
    for (Slot& slot : slots_) slot.id = -1;
  }

  // Call once per frame with every output person: forgets the tracks that ended.
  void BeginFrame(const Poses3D& persons) {
    for (Slot& slot : slots_) {
      const auto& ids = persons.track_ids;
      if (slot.id >= 0 && std::find(ids.begin(), ids.end(), slot.id) == ids.end()) slot.id = -1;
    }
  }

  // The state of track `track_id` (>= 0). `*created` is true when the track had no state yet: the
  // caller initialises it (a reused slot keeps its old contents and capacity).
  State& Get(int track_id, bool* created) {
    Slot* free_slot = nullptr;
    for (Slot& slot : slots_) {
      if (slot.id == track_id) {
        *created = false;
        return slot.state;
      }
      if (slot.id < 0 && free_slot == nullptr) free_slot = &slot;
    }
    if (free_slot == nullptr) free_slot = &slots_.emplace_back();
    free_slot->id = track_id;
    *created = true;
    return free_slot->state;
  }

 private:
  struct Slot {
    int id = -1;  // -1 = free
    State state;
  };
  std::vector<Slot> slots_;
};

}  // namespace rpt
