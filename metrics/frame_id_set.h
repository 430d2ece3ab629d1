// SPDX-License-Identifier: MIT
// FrameIdSet: the frame ids an evaluation has seen, to refuse a repeated one, in 8 bytes per frame:
// each id is kept as a 64-bit hash (two different ids collide with probability about n^2 / 2^65,
// 1e-11 for a million frames; a collision is reported as a repeated id).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace rpt::metrics {

class FrameIdSet {
 public:
  // Adds `frame_id`; false (and nothing added) when it is already in the set.
  bool Insert(std::string_view frame_id);
  // Number of ids that are in both sets.
  long CountShared(const FrameIdSet& other) const;
  // Adds every id of `other`.
  void Merge(const FrameIdSet& other);
  long size() const { return static_cast<long>(sorted_.size() + recent_.size()); }

 private:
  bool Contains(std::uint64_t hash) const;
  // Moves recent_ into sorted_ (which is reallocated to its exact size: no capacity beyond the ids).
  void Compact(const std::vector<std::uint64_t>& more = {});

  std::vector<std::uint64_t> sorted_;  // sorted hashes
  std::vector<std::uint64_t> recent_;  // sorted hashes added since the last Compact(), at most kMaxRecent
  static constexpr size_t kMaxRecent = 1024;
};

}  // namespace rpt::metrics
