// SPDX-License-Identifier: MIT
#include "datasets/readers/openpose_paf_association.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>

namespace rpt {
namespace {

using Connection = PafAssociator::Connection;

// The bits of a positive double, inverted: they order like the values, decreasing.
std::uint64_t DecreasingKey(double score) {
  std::uint64_t bits;
  std::memcpy(&bits, &score, sizeof bits);
  return ~bits;
}

// Fills sorted[0, count) with the indices of possible[0, count) by decreasing score, equal scores
// by index (= limb, a, b). packed[n] holds DecreasingKey(score of n) with its lowest `low` bits
// replaced by n: one std::sort of plain integers does it, unless two different scores agree in all
// other bits (then they would be ordered by index): checked after, and then sorted again by score
// and index, which real scores (a few significant digits each) never need.
template <class Score>
void SortByScore(const Score& score, size_t count, std::uint64_t low, std::uint64_t* packed, std::uint32_t* sorted) {
  std::sort(packed, packed + count);
  bool exact = true;
  for (size_t n = 1; n < count && exact; ++n) {
    exact = ((packed[n] ^ packed[n - 1]) & ~low) != 0 || score(packed[n] & low) == score(packed[n - 1] & low);
  }
  if (exact) {
    for (size_t n = 0; n < count; ++n) sorted[n] = static_cast<std::uint32_t>(packed[n] & low);
    return;
  }
  for (size_t n = 0; n < count; ++n) sorted[n] = static_cast<std::uint32_t>(n);
  std::sort(sorted, sorted + count, [&](std::uint32_t x, std::uint32_t y) {
    const double sx = score(x), sy = score(y);
    return sx != sy ? sx > sy : x < y;
  });
}

// Asks for the cache lines of `values` (a hint; no effect on the result).
void Prefetch(const double* values, size_t count) {
  const char* first = reinterpret_cast<const char*>(values);
  const char* last = reinterpret_cast<const char*>(values + count);
  for (const char* line = first; line < last; line += 64) __builtin_prefetch(line);
}

}  // namespace

std::string CheckPafCandidates(const PafSkeleton& skeleton, const PafCandidates& candidates) {
  if (static_cast<int>(candidates.joints.size()) != skeleton.num_joints) {
    return std::to_string(candidates.joints.size()) + " joints, the skeleton has " + std::to_string(skeleton.num_joints);
  }
  if (candidates.pafs.size() != skeleton.limbs.size()) {
    return std::to_string(candidates.pafs.size()) + " PAF matrices, the skeleton has " +
           std::to_string(skeleton.limbs.size()) + " limbs";
  }
  for (size_t j = 0; j < candidates.joints.size(); ++j) {
    if (!candidates.joints[j].allFinite()) return "joint " + std::to_string(j) + ": non-finite candidate values";
  }
  for (size_t k = 0; k < skeleton.limbs.size(); ++k) {
    const auto [a, b] = skeleton.limbs[k];
    if (a < 0 || b < 0 || a >= skeleton.num_joints || b >= skeleton.num_joints || a == b) {
      return "limb " + std::to_string(k) + ": joints (" + std::to_string(a) + ", " + std::to_string(b) +
             ") are not two different joints of the skeleton";
    }
    const Eigen::MatrixXd& paf = candidates.pafs[k];
    const auto rows = candidates.joints[static_cast<size_t>(a)].cols();
    const auto cols = candidates.joints[static_cast<size_t>(b)].cols();
    if (paf.rows() != rows || paf.cols() != cols) {
      return "limb " + std::to_string(k) + ": PAF matrix is " + std::to_string(paf.rows()) + "x" +
             std::to_string(paf.cols()) + ", the joints have " + std::to_string(rows) + " and " + std::to_string(cols) +
             " candidates";
    }
    if (!paf.allFinite()) return "limb " + std::to_string(k) + ": non-finite PAF scores";
  }
  return {};
}

void PafCandidateStore::Append(const PafSkeleton& skeleton, const PafCandidates& candidates) {
  assert(CheckPafCandidates(skeleton, candidates).empty());
  assert(starts_.empty() || (num_joints_ == skeleton.num_joints && num_limbs_ == static_cast<int>(skeleton.limbs.size())));
  num_joints_ = skeleton.num_joints;
  num_limbs_ = static_cast<int>(skeleton.limbs.size());
  const size_t nj = static_cast<size_t>(num_joints_);
  const size_t first_index = index_.size();
  const size_t first_value = values_.size();
  starts_.emplace_back(first_index, first_value);
  index_.resize(first_index + 2 * nj + static_cast<size_t>(num_limbs_) + 1);
  int* index = index_.data() + first_index;
  size_t size = 0;
  for (size_t j = 0; j < nj; ++j) {
    index[j] = static_cast<int>(candidates.joints[j].cols());
    index[nj + j] = static_cast<int>(size);
    size += static_cast<size_t>(candidates.joints[j].size());
  }
  for (size_t k = 0; k < static_cast<size_t>(num_limbs_); ++k) {
    index[2 * nj + k] = static_cast<int>(size);
    size += static_cast<size_t>(candidates.pafs[k].size());
  }
  index[2 * nj + static_cast<size_t>(num_limbs_)] = static_cast<int>(size);
  values_.resize(first_value + size);
  double* out = values_.data() + first_value;
  for (const Eigen::Matrix3Xd& joint : candidates.joints) {
    for (Eigen::Index r = 0; r < 3; ++r) {
      for (Eigen::Index i = 0; i < joint.cols(); ++i) *out++ = joint(r, i);
    }
  }
  for (const Eigen::MatrixXd& paf : candidates.pafs) {
    for (Eigen::Index r = 0; r < paf.rows(); ++r) {
      for (Eigen::Index c = 0; c < paf.cols(); ++c) *out++ = paf(r, c);
    }
  }
}

void PafCandidateStore::Clear() {
  starts_.clear();
  index_.clear();
  values_.clear();
}

void PafAssociator::Run(const PafSkeleton& skeleton, const PafCandidates& candidates,
                        const PafAssociationOptions& options, PafPersons* persons) {
  packed_candidates_.Clear();
  packed_candidates_.Append(skeleton, candidates);
  Run(skeleton, packed_candidates_[0], options, persons);
}

void PafAssociator::Run(const PafSkeleton& skeleton, const PackedPafCandidates& candidates,
                        const PafAssociationOptions& options, PafPersons* persons) {
  assert(candidates.num_joints() == skeleton.num_joints);
  assert(candidates.num_limbs() == static_cast<int>(skeleton.limbs.size()));
  const int num_joints = skeleton.num_joints;
  const size_t nj = static_cast<size_t>(num_joints);
  const size_t num_limbs = skeleton.limbs.size();

  // Every possible connection of every limb, generated in (limb, a, b) order, with its sort key.
  // Steps 1 and 2 then run in one pass over them by decreasing score: per limb the greedy
  // one-to-one matching sees its connections in the same order as on its own, and its kept
  // connections reach step 2 in the order step 2 sorts them (score, then limb, a, b).
  // The candidates are often not in cache (a reader converts frames parsed long before): asking
  // for their whole block first lets the memory fetch its lines side by side.
  Prefetch(candidates.begin(), static_cast<size_t>(candidates.end() - candidates.begin()));
  size_t entries = 0;
  for (size_t k = 0; k < num_limbs; ++k) {
    entries += static_cast<size_t>(candidates.count(skeleton.limbs[k].first)) *
               static_cast<size_t>(candidates.count(skeleton.limbs[k].second));
  }
  if (possible_.size() < entries) {  // grown only, never shrunk: allocation-free once warm
    possible_.resize(entries);
    packed_.resize(entries);
    sorted_.resize(entries);
  }
  // Indices up to `entries` fit in the lowest bits of a packed key (SortByScore); more than 2^20
  // possible connections in one image (never seen) are taken as one big sort.
  const int index_bits = std::max(1, static_cast<int>(std::bit_width(entries)));
  const std::uint64_t low = index_bits <= 20 ? (std::uint64_t{1} << index_bits) - 1 : ~std::uint64_t{0};
  used_offset_.resize(num_limbs + 1);
  used_offset_[0] = 0;
  size_t count = 0;
  for (size_t k = 0; k < num_limbs; ++k) {
    const int rows = candidates.count(skeleton.limbs[k].first);
    const int cols = candidates.count(skeleton.limbs[k].second);
    used_offset_[k + 1] = used_offset_[k] + rows + cols;
    if (rows == 0 || cols == 0) continue;
    const double* score_a = candidates.JointRow(skeleton.limbs[k].first, 2);
    const double* score_b = candidates.JointRow(skeleton.limbs[k].second, 2);
    const double* paf = candidates.Paf(static_cast<int>(k));
    for (int i = 0; i < rows; ++i) {
      if (!(score_a[i] > 0)) continue;
      const double* row = paf + static_cast<size_t>(i) * static_cast<size_t>(cols);
      for (int j = 0; j < cols; ++j) {
        // Written always, counted when possible: no branch on the scores.
        const double score = row[j];
        packed_[count] = (DecreasingKey(score) & ~low) | count;
        possible_[count] = {static_cast<int>(k), i, j};
        count += static_cast<size_t>((score > 0) & (score >= options.min_paf_score) & (score_b[j] > 0));
      }
    }
  }
  const auto score = [&](std::uint64_t n) {
    const Connection& c = possible_[n];
    const int cols = candidates.count(skeleton.limbs[static_cast<size_t>(c.limb)].second);
    return candidates.Paf(c.limb)[static_cast<size_t>(c.a) * static_cast<size_t>(cols) + static_cast<size_t>(c.b)];
  };
  SortByScore(score, count, low, packed_.data(), sorted_.data());
  used_.assign(static_cast<size_t>(used_offset_[num_limbs]), 0);

  // Step 2. owner_ holds the person of every candidate (-1 = none), joint j's from offset_[j];
  // merged persons are emptied, not erased, so indices stay valid and the output order is the
  // order of creation.
  offset_.resize(nj + 1);
  offset_[0] = 0;
  for (size_t j = 0; j < nj; ++j) offset_[j + 1] = offset_[j] + candidates.count(static_cast<int>(j));
  owner_.assign(static_cast<size_t>(offset_[nj]), -1);
  persons_.clear();
  joint_count_.clear();
  mask_.clear();
  const size_t words = (nj + 63) / 64;  // a person's joints as a bit set (1 word for BODY_25)
  for (size_t n = 0; n < count; ++n) {
    const Connection& c = possible_[sorted_[n]];
    // Step 1: the limb's greedy matching keeps the connection when neither end is used yet.
    unsigned char* used = used_.data() + used_offset_[static_cast<size_t>(c.limb)];
    unsigned char& used_a = used[c.a];
    unsigned char& used_b = used[candidates.count(skeleton.limbs[static_cast<size_t>(c.limb)].first) + c.b];
    if (used_a | used_b) continue;
    used_a = used_b = 1;
    // Step 2.
    const auto [joint_a, joint_b] = skeleton.limbs[static_cast<size_t>(c.limb)];
    int& owner_a = owner_[static_cast<size_t>(offset_[static_cast<size_t>(joint_a)] + c.a)];
    int& owner_b = owner_[static_cast<size_t>(offset_[static_cast<size_t>(joint_b)] + c.b)];
    if (owner_a < 0 && owner_b < 0) {
      const int p = static_cast<int>(joint_count_.size());
      persons_.resize(persons_.size() + nj, -1);
      mask_.resize(mask_.size() + words, 0);
      int* person = persons_.data() + static_cast<size_t>(p) * nj;
      std::uint64_t* mask = mask_.data() + static_cast<size_t>(p) * words;
      person[joint_a] = c.a;
      person[joint_b] = c.b;
      mask[joint_a / 64] |= std::uint64_t{1} << (joint_a % 64);
      mask[joint_b / 64] |= std::uint64_t{1} << (joint_b % 64);
      joint_count_.push_back(2);
      owner_a = owner_b = p;
    } else if (owner_a < 0 || owner_b < 0) {
      const int p = std::max(owner_a, owner_b);
      const int joint = owner_a < 0 ? joint_a : joint_b;
      int* person = persons_.data() + static_cast<size_t>(p) * nj;
      if (person[joint] >= 0) continue;  // it has another candidate of this joint
      person[joint] = owner_a < 0 ? c.a : c.b;
      mask_[static_cast<size_t>(p) * words + static_cast<size_t>(joint / 64)] |= std::uint64_t{1} << (joint % 64);
      ++joint_count_[static_cast<size_t>(p)];
      (owner_a < 0 ? owner_a : owner_b) = p;
    } else if (owner_a != owner_b) {
      const int keep = std::min(owner_a, owner_b);
      const int drop = std::max(owner_a, owner_b);
      std::uint64_t* keep_mask = mask_.data() + static_cast<size_t>(keep) * words;
      std::uint64_t* drop_mask = mask_.data() + static_cast<size_t>(drop) * words;
      std::uint64_t shared = 0;
      for (size_t w = 0; w < words; ++w) shared |= keep_mask[w] & drop_mask[w];
      if (shared != 0) continue;  // they share a joint
      int* first = persons_.data() + static_cast<size_t>(keep) * nj;
      int* second = persons_.data() + static_cast<size_t>(drop) * nj;
      for (size_t w = 0; w < words; ++w) {
        for (std::uint64_t bits = drop_mask[w]; bits != 0; bits &= bits - 1) {
          const size_t j = w * 64 + static_cast<size_t>(std::countr_zero(bits));
          first[j] = second[j];
          owner_[static_cast<size_t>(offset_[j] + second[j])] = keep;
          second[j] = -1;
        }
        keep_mask[w] |= drop_mask[w];
        drop_mask[w] = 0;
      }
      joint_count_[static_cast<size_t>(keep)] += joint_count_[static_cast<size_t>(drop)];
      joint_count_[static_cast<size_t>(drop)] = 0;
    }
    // else: both ends already in the same person (a redundant limb).
  }

  // Step 3.
  persons->num_joints = num_joints;
  persons->candidate.clear();
  for (size_t p = 0; p < joint_count_.size(); ++p) {
    const int joints = joint_count_[p];
    if (joints > 0 && joints >= options.min_joints) {
      const int* person = persons_.data() + p * nj;
      persons->candidate.insert(persons->candidate.end(), person, person + nj);
    }
  }
}

std::vector<PafPerson> AssociatePafs(const PafSkeleton& skeleton, const PafCandidates& candidates,
                                     const PafAssociationOptions& options) {
  PafAssociator associator;
  PafPersons persons;
  associator.Run(skeleton, candidates, options, &persons);
  std::vector<PafPerson> out;
  for (int p = 0; p < persons.size(); ++p) out.emplace_back(persons.Person(p), persons.Person(p) + persons.num_joints);
  return out;
}

}  // namespace rpt
