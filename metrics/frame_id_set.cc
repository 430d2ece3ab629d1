// SPDX-License-Identifier: MIT
#include "metrics/frame_id_set.h"

#include <algorithm>
#include <iterator>

namespace rpt::metrics {
namespace {

// FNV-1a over the bytes, then the SplitMix64 finaliser to spread the bits.
std::uint64_t Hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

}  // namespace

bool FrameIdSet::Contains(std::uint64_t hash) const {
  return std::binary_search(sorted_.begin(), sorted_.end(), hash) ||
         std::binary_search(recent_.begin(), recent_.end(), hash);
}

bool FrameIdSet::Insert(std::string_view frame_id) {
  const std::uint64_t hash = Hash(frame_id);
  if (Contains(hash)) return false;
  if (recent_.capacity() < kMaxRecent) recent_.reserve(kMaxRecent);
  recent_.insert(std::upper_bound(recent_.begin(), recent_.end(), hash), hash);
  if (recent_.size() == kMaxRecent) Compact();
  return true;
}

long FrameIdSet::CountShared(const FrameIdSet& other) const {
  long shared = 0;
  for (const std::uint64_t hash : other.sorted_) shared += Contains(hash) ? 1 : 0;
  for (const std::uint64_t hash : other.recent_) shared += Contains(hash) ? 1 : 0;
  return shared;
}

void FrameIdSet::Merge(const FrameIdSet& other) {
  std::vector<std::uint64_t> more;
  more.reserve(other.sorted_.size() + other.recent_.size());
  std::merge(other.sorted_.begin(), other.sorted_.end(), other.recent_.begin(), other.recent_.end(),
             std::back_inserter(more));
  Compact(more);
}

void FrameIdSet::Compact(const std::vector<std::uint64_t>& more) {
  std::vector<std::uint64_t> recent_and_more;
  recent_and_more.reserve(recent_.size() + more.size());
  std::merge(recent_.begin(), recent_.end(), more.begin(), more.end(), std::back_inserter(recent_and_more));
  std::vector<std::uint64_t> all;
  all.reserve(sorted_.size() + recent_and_more.size());
  std::merge(sorted_.begin(), sorted_.end(), recent_and_more.begin(), recent_and_more.end(), std::back_inserter(all));
  sorted_.swap(all);
  recent_.clear();
}

}  // namespace rpt::metrics
