// SPDX-License-Identifier: MIT
#include "datasets/readers/paf_connection_keys.h"

#include <hwy/contrib/sort/vqsort.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rpt::paf_internal {
namespace {

// Up to this many keys std::sort (an insertion sort then) is faster than a sorting network.
constexpr size_t kMaxKeysForStdSort = 8;

}  // namespace

PafConnectionKeys::PafConnectionKeys(int num_limbs, int num_slots) {
  slot_bits_ = static_cast<int>(std::bit_width(static_cast<unsigned>(std::max(num_slots - 1, 0))));
  limb_shift_ = 2 * slot_bits_;
  const int code_bits =
      limb_shift_ + static_cast<int>(std::bit_width(static_cast<unsigned>(std::max(num_limbs - 1, 0))));
  if (code_bits > 64) {
    throw std::length_error("PAF association: " + std::to_string(num_limbs) + " limbs and " +
                            std::to_string(num_slots) + " candidates do not fit a 64-bit key");
  }
  slot_mask_ = (std::uint64_t{1} << slot_bits_) - 1;
  code_mask_ = code_bits <= kMaxCodeBits ? (std::uint64_t{1} << code_bits) - 1 : ~std::uint64_t{0};
}

void SortPafConnectionKeys(const PafConnectionKeys coding, const PafSkeleton& skeleton,
                           const PackedPafCandidates& candidates, std::uint64_t* keys, size_t count) {
  if (count > kMaxKeysForStdSort) {
    // Highway's vectorised quicksort (sorting networks, runtime dispatch): no data-dependent
    // branches, where std::sort mispredicts about every other comparison of such keys. Its
    // buffer is allocated once per thread.
    thread_local const hwy::Sorter sorter;
    sorter(keys, count, hwy::SortAscending());
  } else {
    std::sort(keys, keys + count);
  }
  const std::uint64_t code_mask = coding.code_mask();
  const auto score = [&](std::uint64_t key) {
    const int limb = coding.Limb(key);
    const auto [joint_a, joint_b] = skeleton.limbs[static_cast<size_t>(limb)];
    const size_t a = static_cast<size_t>(coding.SlotA(key) - candidates.slot(joint_a));
    const size_t b = static_cast<size_t>(coding.SlotB(key) - candidates.slot(joint_b));
    return candidates.Paf(limb)[a * static_cast<size_t>(candidates.count(joint_b)) + b];
  };
  // Keys whose score bits agree are ordered by (limb, a, b): right only when their scores are equal.
  // Such neighbours are looked for without a branch first (real scores have none).
  std::uint64_t same_score_bits = 0;
  for (size_t n = 1; n < count; ++n) same_score_bits |= ((keys[n] ^ keys[n - 1]) & ~code_mask) == 0;
  if (same_score_bits == 0) return;
  size_t n = 1;
  while (n < count && (((keys[n] ^ keys[n - 1]) & ~code_mask) != 0 || score(keys[n]) == score(keys[n - 1]))) ++n;
  if (n >= count) return;
  std::sort(keys, keys + count, [&](std::uint64_t x, std::uint64_t y) {
    const double sx = score(x), sy = score(y);
    return sx != sy ? sx > sy : (x & code_mask) < (y & code_mask);
  });
}

}  // namespace rpt::paf_internal
