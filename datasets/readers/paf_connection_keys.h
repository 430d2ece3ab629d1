// SPDX-License-Identifier: MIT
// A possible PAF connection (limb, candidate a of the limb's first joint, candidate b of its
// second) and its PAF score as one 64-bit integer whose increasing order is the association's
// order: decreasing score, then limb, a, b. PafAssociator (openpose_paf_association.h) sorts these
// keys as plain integers and reads the limb and the two candidates back from them, so it never
// stores a connection as a struct.
//
// Candidates are named by their slot: the index among all candidates of the image, joint after
// joint (slot = first slot of the joint + candidate index), so within a limb the slots order like
// the candidate indices. Layout of a key: the highest bits are the score's bits inverted (a
// positive double's bits order like its value); the lowest bits hold (limb, slot a, slot b) as
// fixed-width fields, which order like the tuple. The score bits those fields overwrite are lost,
// so two scores that differ only there would be ordered by (limb, a, b) instead of by score:
// SortPafConnectionKeys() checks for that after the sort and then sorts again by the exact scores
// (never needed by real scores, which carry a few significant digits; tested with scores one ulp
// apart).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "datasets/readers/paf_candidates.h"

namespace rpt::paf_internal {

class PafConnectionKeys {
 public:
  // For `num_limbs` limbs and `num_slots` candidates in all. Throws std::length_error when the
  // fields do not fit 64 bits (hundreds of millions of candidates in one image).
  PafConnectionKeys(int num_limbs, int num_slots);

  // The key of the connection with PAF score `score` (> 0) and `code` = Code(limb, slot_a, slot_b).
  std::uint64_t Key(double score, std::uint64_t code) const {
    return (~std::bit_cast<std::uint64_t>(score) & ~code_mask_) | code;
  }
  // The (limb, slot a, slot b) fields alone. Code(limb, slot_a, 0) + slot_b is the same.
  std::uint64_t Code(int limb, int slot_a, int slot_b) const {
    return (static_cast<std::uint64_t>(limb) << limb_shift_) | (static_cast<std::uint64_t>(slot_a) << slot_bits_) |
           static_cast<std::uint64_t>(slot_b);
  }
  int Limb(std::uint64_t key) const { return static_cast<int>((key & code_mask_) >> limb_shift_); }
  int SlotA(std::uint64_t key) const { return static_cast<int>((key >> slot_bits_) & slot_mask_); }
  int SlotB(std::uint64_t key) const { return static_cast<int>(key & slot_mask_); }
  // Bits of a key that hold the fields; all of them (no score bits) when the fields need more than
  // kMaxCodeBits, which leaves every ordering to the exact re-sort (slow, but only for images with
  // some 500+ candidates).
  std::uint64_t code_mask() const { return code_mask_; }

  static constexpr int kMaxCodeBits = 24;  // leaves 40 bits of the score: 28 of its mantissa

 private:
  int slot_bits_ = 0;   // width of each slot field
  int limb_shift_ = 0;  // 2 * slot_bits_
  std::uint64_t slot_mask_ = 0;
  std::uint64_t code_mask_ = 0;
};

// Sorts keys[0, count) increasingly, i.e. by decreasing score, equal scores by (limb, a, b).
// `candidates` and `skeleton` give the exact scores for the check (and the rare re-sort).
void SortPafConnectionKeys(PafConnectionKeys coding, const PafSkeleton& skeleton, const PackedPafCandidates& candidates,
                           std::uint64_t* keys, size_t count);

}  // namespace rpt::paf_internal
