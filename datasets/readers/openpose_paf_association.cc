// SPDX-License-Identifier: MIT
#include "datasets/readers/openpose_paf_association.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

#include "datasets/readers/paf_connection_keys.h"
#include "datasets/readers/paf_limb_connections.h"

namespace rpt {
namespace {

using paf_internal::PafConnectionKeys;

// Asks for the cache lines of [first, last) (a hint; no effect on the result).
template <class T>
void Prefetch(const T* first, const T* last) {
  const char* line = reinterpret_cast<const char*>(first);
  for (; line < reinterpret_cast<const char*>(last); line += 64) __builtin_prefetch(line);
}

// Step 2's persons while they are assembled, in buffers the caller sized for `count` persons:
// person p's candidate of joint j is candidate[p * num_joints + j] (-1 = none), its joints as a
// bit set of words() 64-bit words from joints[p * words()], their number joint_count[p]. kWords
// fixes words() at compile time (1: skeletons of up to 64 joints); 0 takes num_words.
template <size_t kWords>
struct AssembledPersons {
  size_t num_joints;
  size_t num_words;
  int* candidate;
  std::uint64_t* joints;
  int* joint_count;
  int size = 0;

  size_t words() const { return kWords != 0 ? kWords : num_words; }
  int* Candidates(int p) const { return candidate + static_cast<size_t>(p) * num_joints; }
  std::uint64_t* Joints(int p) const { return joints + static_cast<size_t>(p) * words(); }
  // The word of `joint` in person p's joint set (the only one when kWords is 1).
  std::uint64_t& Word(int p, unsigned joint) const { return Joints(p)[kWords == 1 ? 0 : joint / 64]; }
  static std::uint64_t Bit(unsigned joint) { return std::uint64_t{1} << (joint % 64); }
  int New() {
    std::fill_n(Candidates(size), num_joints, -1);
    std::fill_n(Joints(size), words(), std::uint64_t{0});
    joint_count[size] = 0;
    return size++;
  }
  void Add(int p, unsigned joint, int candidate_of_joint) {
    Candidates(p)[joint] = candidate_of_joint;
    Word(p, joint) |= Bit(joint);
    ++joint_count[p];
  }
  bool ShareAJoint(int p, int q) const {
    std::uint64_t shared = 0;
    for (size_t w = 0; w < words(); ++w) shared |= Joints(p)[w] & Joints(q)[w];
    return shared != 0;
  }
};

// Step 2 on the kept connections keys[0, count), in order. owner[slot] is the person of each
// candidate (-1 = none, all on entry); slot[j] joint j's first slot. Merged persons are emptied,
// not erased, so indices stay valid and the output order is the order of creation.
template <size_t kWords>
void AssemblePersons(const PafSkeleton& skeleton, const PafConnectionKeys coding, const int* slot,
                     const std::uint64_t* keys, size_t count, int* owner, AssembledPersons<kWords>* persons) {
  const std::pair<int, int>* limbs = skeleton.limbs.data();
  for (size_t n = 0; n < count; ++n) {
    const std::uint64_t key = keys[n];
    const auto [a, b] = limbs[coding.Limb(key)];
    const unsigned joint_a = static_cast<unsigned>(a);
    const unsigned joint_b = static_cast<unsigned>(b);
    const int slot_a = coding.SlotA(key);
    const int slot_b = coding.SlotB(key);
    const int owner_a = owner[slot_a];
    const int owner_b = owner[slot_b];
    if ((owner_a & owner_b) < 0) {  // both -1: a new person
      const int p = persons->New();
      persons->Add(p, joint_a, slot_a - slot[joint_a]);
      persons->Add(p, joint_b, slot_b - slot[joint_b]);
      owner[slot_a] = owner[slot_b] = p;
    } else if ((owner_a | owner_b) < 0) {  // one -1: the other end joins the person
      const bool a_joins = owner_a < 0;
      const int p = a_joins ? owner_b : owner_a;
      const unsigned joint = a_joins ? joint_a : joint_b;
      if (persons->Candidates(p)[joint] >= 0) continue;  // it has another candidate of this joint
      const int joining = a_joins ? slot_a : slot_b;
      persons->Add(p, joint, joining - slot[joint]);
      owner[joining] = p;
    } else if (owner_a != owner_b) {
      const int keep = std::min(owner_a, owner_b);
      const int drop = std::max(owner_a, owner_b);
      if (persons->ShareAJoint(keep, drop)) continue;
      std::uint64_t* drop_joints = persons->Joints(drop);
      int* drop_candidates = persons->Candidates(drop);
      for (size_t w = 0; w < persons->words(); ++w) {
        for (std::uint64_t bits = drop_joints[w]; bits != 0; bits &= bits - 1) {
          const unsigned j = static_cast<unsigned>(w * 64) + static_cast<unsigned>(std::countr_zero(bits));
          persons->Add(keep, j, drop_candidates[j]);
          owner[slot[j] + drop_candidates[j]] = keep;
          drop_candidates[j] = -1;
        }
        drop_joints[w] = 0;
      }
      persons->joint_count[drop] = 0;
    }
    // else: both ends already in the same person (a redundant limb).
  }
}

// Steps 2 and 3 with joint sets of kWords words (0: `words`): the persons with at least
// min_joints joints (and one) into `persons`.
template <size_t kWords>
void AssembleAndKeepPersons(const PafSkeleton& skeleton, const PafConnectionKeys coding, const int* slot,
                            const std::uint64_t* keys, size_t count, int* owner, int min_joints, size_t words,
                            int* person_candidates, std::uint64_t* person_joints, int* joint_count,
                            PafPersons* persons) {
  const size_t nj = static_cast<size_t>(skeleton.num_joints);
  AssembledPersons<kWords> assembled{nj, words, person_candidates, person_joints, joint_count};
  AssemblePersons(skeleton, coding, slot, keys, count, owner, &assembled);
  const int at_least = std::max(min_joints, 1);
  size_t kept = 0;
  for (int p = 0; p < assembled.size; ++p) kept += static_cast<size_t>(joint_count[p] >= at_least);
  persons->num_joints = skeleton.num_joints;
  persons->candidate.resize(kept * nj);  // allocation-free once warm (resize keeps the capacity)
  int* out = persons->candidate.data();
  for (int p = 0; p < assembled.size; ++p) {
    if (joint_count[p] < at_least) continue;
    std::memcpy(out, assembled.Candidates(p), nj * sizeof(int));
    out += nj;
  }
}

}  // namespace

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
  const size_t nj = static_cast<size_t>(skeleton.num_joints);
  const size_t num_limbs = skeleton.limbs.size();

  // The candidates are often not in cache (a reader converts frames parsed long before): asking
  // for all the association reads first (the index, the scores and the PAF scores) lets the
  // memory fetch its lines side by side.
  Prefetch(candidates.index_begin(), candidates.index_end());
  Prefetch(candidates.begin(), candidates.association_end());
  const int* slot = candidates.slots();  // joint j's candidate i is slot[j] + i
  const int num_slots = candidates.num_slots();
  if (used_.size() < static_cast<size_t>(num_slots)) used_.resize(static_cast<size_t>(num_slots), 0);
  const PafConnectionKeys coding(static_cast<int>(num_limbs), num_slots);

  // Step 1 (paf_limb_connections.h): possible connections have both candidate scores > 0 and a
  // PAF score > 0 and >= min_paf_score (none when that is NaN).
  const double min_score = std::isnan(options.min_paf_score)
                               ? std::numeric_limits<double>::infinity()
                               : std::max(options.min_paf_score, std::numeric_limits<double>::denorm_min());
  const size_t count =
      paf_internal::KeptLimbConnections(skeleton, candidates, coding, min_score, &keys_, &above_min_, used_.data());
  // Step 2 takes the kept connections of all limbs by decreasing score (ties: limb, a, b).
  paf_internal::SortPafConnectionKeys(coding, skeleton, candidates, keys_.data(), count);

  // Steps 2 and 3, with room for one new person per kept connection.
  owner_.assign(static_cast<size_t>(num_slots), -1);
  const size_t words = (nj + 63) / 64;
  if (person_candidates_.size() < count * nj) {  // grown only: allocation-free once warm
    person_candidates_.resize(count * nj);
    person_joints_.resize(count * words);
    joint_count_.resize(count);
  }
  if (words == 1) {
    AssembleAndKeepPersons<1>(skeleton, coding, slot, keys_.data(), count, owner_.data(), options.min_joints, words,
                              person_candidates_.data(), person_joints_.data(), joint_count_.data(), persons);
  } else {
    AssembleAndKeepPersons<0>(skeleton, coding, slot, keys_.data(), count, owner_.data(), options.min_joints, words,
                              person_candidates_.data(), person_joints_.data(), joint_count_.data(), persons);
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
