// SPDX-License-Identifier: MIT
// Greedy part-affinity-field (PAF) association: turns bottom-up joint candidates of one image
// (OpenPose's heatmap peaks and the PAF scores between them) into per-person skeletons.
// Independent of any file format and of the skeleton (BODY_25 is one PafSkeleton).
//
// Algorithm (deterministic):
//  1. Per limb (a PAF between joints a and b), every candidate pair (i of a, j of b) with both
//     candidate scores > 0 and PAF score >= min_paf_score is a possible connection. Within the
//     limb the connections are taken by decreasing PAF score and kept when neither i nor j is
//     already used by a kept connection of this limb: each candidate is used at most once per
//     limb (a greedy one-to-one matching, as OpenPose does per limb).
//  2. The kept connections of all limbs are processed by decreasing PAF score (ties: limb, i, j
//     in increasing order). A connection between candidates that belong to no person yet starts
//     a new person; one whose other end belongs to a person joins it unless that person already
//     has a different candidate of that joint; one joining two different persons merges them
//     when they share no joint (OpenPose-style subset merging), else it is dropped. Redundant
//     limbs (closing a cycle within a person) change nothing.
//  3. Persons with fewer than min_joints joints are dropped. Candidates that end up in no kept
//     connection belong to no person.
// Persons come out in the order their first (highest-scoring) connection was processed.
//
// PafAssociator runs it with buffers it keeps: once warm (candidate counts seen before) a call
// allocates nothing. AssociatePafs() is the one-shot form. How: every connection is one 64-bit
// key that sorts in the order above (paf_connection_keys.h); step 1 writes keys for the PAF
// scores a vectorised pass marks as >= min_paf_score and matches only the limbs where two
// possible connections share a candidate (paf_limb_connections.h, paf_score_mask.h); the kept
// connections of all limbs are sorted once and step 2 assembles the persons in that order.
//
// PAF scores are used as given: 4D-Association raises them to the power 0.2 after reading,
// a monotone transform that changes no ordering; min_paf_score applies to the values given
// (0.05 here is 0.05^0.2 = 0.55 on 4D-Association's scale).
#pragma once

#include <cstdint>
#include <vector>

#include "datasets/readers/paf_candidates.h"

namespace rpt {

struct PafAssociationOptions {
  // Connections with a lower PAF score are ignored. 0.05 is the smallest non-zero score stored in
  // 4D-Association's Shelf files (weaker links were already zeroed), so it keeps every stored link.
  double min_paf_score = 0.05;
  // Persons with fewer joints are dropped. On the 4D-Association Shelf files, 5 instead of 3 cuts
  // the assembled persons without a neck (fragments: a lone leg or arm) from 12 % to 5 % of all
  // persons and finds the same ground-truth persons (tests/datasets/readers_shelf_4da_test.cc).
  int min_joints = 5;
};

// One assembled person: per joint the index of its candidate, -1 = none.
using PafPerson = std::vector<int>;

// The assembled persons of one image, flat: person p's candidate of joint j is
// candidate[p * num_joints + j] (-1 = none).
struct PafPersons {
  int num_joints = 0;
  std::vector<int> candidate;
  int size() const { return num_joints == 0 ? 0 : static_cast<int>(candidate.size()) / num_joints; }
  const int* Person(int p) const { return candidate.data() + static_cast<size_t>(p) * static_cast<size_t>(num_joints); }
};

// The association above with reused buffers. Precondition: CheckPafCandidates() returned ""
// (asserted).
class PafAssociator {
 public:
  void Run(const PafSkeleton& skeleton, const PafCandidates& candidates, const PafAssociationOptions& options,
           PafPersons* persons);
  // The same on packed candidates (appended with `skeleton`), without the copy.
  void Run(const PafSkeleton& skeleton, const PackedPafCandidates& candidates, const PafAssociationOptions& options,
           PafPersons* persons);

 private:
  PafCandidateStore packed_candidates_;  // Run(PafCandidates)'s copy
  // Sized to the most seen, never shrunk (allocation-free once warm):
  std::vector<std::uint64_t> keys_;       // the possible, then the kept connections (paf_connection_keys.h)
  std::vector<std::uint64_t> above_min_;  // step 1's scratch (paf_limb_connections.h)
  std::vector<unsigned char> used_;  // per slot: used by a kept connection of the limb being matched (0 between limbs)
  std::vector<int> owner_;           // per slot: its person, -1 = none
  // Step 2's persons as created (merged ones emptied), room for one per kept connection: per
  // joint a candidate (-1 = none), the joints as a bit set, their count.
  std::vector<int> person_candidates_;
  std::vector<std::uint64_t> person_joints_;
  std::vector<int> joint_count_;
};

// One-shot form of PafAssociator::Run.
std::vector<PafPerson> AssociatePafs(const PafSkeleton& skeleton, const PafCandidates& candidates,
                                     const PafAssociationOptions& options);

}  // namespace rpt
