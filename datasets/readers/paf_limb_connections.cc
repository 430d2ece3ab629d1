// SPDX-License-Identifier: MIT
// Two ways through a limb's (candidates of a) x (candidates of b) block of PAF scores, both
// without a branch per entry on the scores (about two in three PAF entries of real images are 0):
//  * Sparse (blocks of at most 64 entries, every candidate score of the image > 0: all real
//    images): one vectorised pass over the PAF scores of all limbs (MarkAtLeast,
//    paf_score_mask.h) marks those >= min_score, the limb's marks are cut out as a 64-bit mask,
//    and only the marked entries (about a third) get a key, their row and column from the
//    entry's index by a multiplication with a reciprocal; two of them in one row share
//    candidate a, two in one column share b.
//  * Dense (any block): row by row, every entry's key written and counted when possible, the
//    sharing noted per row.
// Only limbs with a shared candidate go through the greedy matching (MatchLimbGreedily, with a
// sort); in the others, about 9 limbs in 10 on the 4D-Association Shelf files, every possible
// connection is kept.
//
// (Writing the keys with Highway too, a row per vector, was slower: rows have 2 to 4 entries,
// fewer than the lanes, and Highway 1.0.3's AVX2 CompressStore of 64-bit lanes rebuilds its
// permutation table on every call.)
#include "datasets/readers/paf_limb_connections.h"

#include <array>
#include <bit>
#include <utility>

#include "datasets/readers/paf_score_mask.h"

namespace rpt::paf_internal {
namespace {

// kReciprocal[c] = ceil(2^16 / c): for entries e < 64 of rows of c <= 64 entries, the row is
// (e * kReciprocal[c]) >> 16 exactly (the error e * (c * kReciprocal[c] - 2^16) / 2^16 < e * c /
// 2^16 < 1/16 never reaches the next multiple of c).
constexpr std::array<std::uint32_t, 65> kReciprocal = [] {
  std::array<std::uint32_t, 65> r{};
  for (std::uint32_t c = 1; c <= 64; ++c) r[c] = ((std::uint32_t{1} << 16) + c - 1) / c;
  return r;
}();

// Whether every value of [first, last) (finite) is > 0: a double is > 0 exactly when its bits,
// as an unsigned integer, are neither 0 nor have the sign bit, i.e. when neither `bits` nor
// `bits - 1` has the sign bit. Branch-free and integer-only, so the loop vectorises.
bool AllPositive(const double* first, const double* last) {
  std::uint64_t sign = 0;
  for (; first < last; ++first) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(*first);
    sign |= bits | (bits - 1);
  }
  return (sign >> 63) == 0;
}

// Step 1 for one limb whose possible connections keys[0, count) may share candidates: keeps those
// the greedy one-to-one matching keeps (by decreasing score, each candidate at most once), moved
// to the front, and returns how many. `used` has a zero flag per slot, and has it again on return.
size_t MatchLimbGreedily(const PafConnectionKeys coding, const PafSkeleton& skeleton,
                         const PackedPafCandidates& candidates, std::uint64_t* keys, size_t count,
                         unsigned char* used) {
  SortPafConnectionKeys(coding, skeleton, candidates, keys, count);
  size_t kept = 0;
  for (size_t n = 0; n < count; ++n) {
    unsigned char& used_a = used[coding.SlotA(keys[n])];
    unsigned char& used_b = used[coding.SlotB(keys[n])];
    if (used_a | used_b) continue;
    used_a = used_b = 1;
    keys[kept++] = keys[n];
  }
  for (size_t n = 0; n < kept; ++n) used[coding.SlotA(keys[n])] = used[coding.SlotB(keys[n])] = 0;
  return kept;
}

}  // namespace

size_t KeptLimbConnections(const PafSkeleton& skeleton, const PackedPafCandidates& candidates,
                           const PafConnectionKeys coding, double min_score, std::vector<std::uint64_t>* keys,
                           std::vector<std::uint64_t>* above_min, unsigned char* used) {
  const std::pair<int, int>* limbs = skeleton.limbs.data();
  const size_t num_limbs = skeleton.limbs.size();
  const int* counts = candidates.counts();               // per joint
  const int* slots = candidates.slots();                 // per joint
  const double* scores = candidates.scores();            // per slot
  const std::uint64_t limb_step = coding.Code(1, 0, 0);  // to the next limb
  const std::uint64_t row_step = coding.Code(0, 1, 0);   // to the next candidate a
  // A finite double is >= min_score (> 0) exactly when its bits are, compared as signed integers.
  const std::int64_t min_score_bits = std::bit_cast<std::int64_t>(min_score);
  // Every candidate score > 0: the sparse way needs no look at them. Its one pass over the PAF
  // scores of all limbs (side by side in `candidates`) marks those >= min_score, bit e of
  // (*above_min)[e / 64] for the e-th score (one more word of zeros after the last).
  const bool sparse = AllPositive(scores, scores + candidates.num_slots());
  const double* pafs = candidates.pafs_begin();
  if (sparse) {
    const size_t num_pafs = static_cast<size_t>(candidates.association_end() - pafs);
    if (above_min->size() < num_pafs / 64 + 2) above_min->resize(num_pafs / 64 + 2);  // grown only
    std::uint64_t* bitmap = above_min->data();
    MarkAtLeast(pafs, num_pafs, min_score, candidates.end(), bitmap);
    bitmap[(num_pafs + 63) / 64] = 0;
  }
  std::uint64_t* out = keys->data();
  size_t room = keys->size();
  size_t count = 0;
  for (size_t k = 0; k < num_limbs; ++k) {
    const auto [joint_a, joint_b] = limbs[k];
    const int rows = counts[joint_a];
    const int cols = counts[joint_b];
    const size_t entries = static_cast<size_t>(rows) * static_cast<size_t>(cols);
    if (entries == 0) continue;
    if (room < count + entries) {  // grown only: allocation-free once warm
      keys->resize(count + entries);
      out = keys->data();
      room = keys->size();
    }
    const double* paf = candidates.Paf(static_cast<int>(k));
    const std::uint64_t first_code = k * limb_step + static_cast<std::uint64_t>(slots[joint_a]) * row_step +
                                     static_cast<std::uint64_t>(slots[joint_b]);  // of (a, b) = (0, 0)
    const size_t first = count;
    if (sparse && entries <= 64) {
      // The limb's bits of above_min: entries bits from bit `start`, maybe across two words.
      const size_t start = static_cast<size_t>(paf - pafs);
      const std::uint64_t* word = above_min->data() + start / 64;
      const unsigned shift = start % 64;
      std::uint64_t mask = (word[0] >> shift) | ((word[1] << 1) << (63 - shift));
      if (entries < 64) mask &= (std::uint64_t{1} << entries) - 1;
      const std::uint64_t reciprocal = kReciprocal[static_cast<size_t>(cols)];
      std::uint64_t seen_a = 0, seen_b = 0, shared = 0;  // the rows and columns with a possible connection
      for (std::uint64_t m = mask; m != 0; m &= m - 1) {
        const std::uint64_t e = static_cast<std::uint64_t>(std::countr_zero(m));
        const std::uint64_t i = (e * reciprocal) >> 16;
        const std::uint64_t j = e - i * static_cast<std::uint64_t>(cols);
        out[count++] = coding.Key(paf[e], first_code + i * row_step + j);
        shared |= (seen_a & (std::uint64_t{1} << i)) | (seen_b & (std::uint64_t{1} << j));
        seen_a |= std::uint64_t{1} << i;
        seen_b |= std::uint64_t{1} << j;
      }
      if (shared != 0) {
        count = first + MatchLimbGreedily(coding, skeleton, candidates, out + first, count - first, used);
      }
      continue;
    }
    const double* score_a = scores + slots[joint_a];
    const double* score_b = scores + slots[joint_b];
    const double* row = paf;
    std::uint64_t code = first_code;
    std::uint64_t seen_b = 0;  // the columns (mod 64) with a possible connection so far
    bool shared = cols > 64;   // two possible connections share a candidate (assumed beyond 64 columns)
    for (int i = 0; i < rows; ++i, row += cols, code += row_step) {
      if (!(score_a[i] > 0)) continue;
      const size_t row_first = count;
      std::uint64_t row_b = 0;
      for (int j = 0; j < cols; ++j) {
        out[count] = coding.Key(row[j], code + static_cast<std::uint64_t>(j));  // written always, counted if possible
        const std::uint64_t possible = (std::bit_cast<std::int64_t>(row[j]) >= min_score_bits) & (score_b[j] > 0);
        count += possible;
        row_b |= possible << (j & 63);
      }
      shared |= (count - row_first > 1) | ((seen_b & row_b) != 0);
      seen_b |= row_b;
    }
    if (shared && count - first > 1) {
      count = first + MatchLimbGreedily(coding, skeleton, candidates, out + first, count - first, used);
    }
  }
  return count;
}

}  // namespace rpt::paf_internal
