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
// allocates nothing. AssociatePafs() is the one-shot form.
//
// PAF scores are used as given: 4D-Association raises them to the power 0.2 after reading,
// a monotone transform that changes no ordering; min_paf_score applies to the values given
// (0.05 here is 0.05^0.2 = 0.55 on 4D-Association's scale).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rpt {

// The joints and the limbs PAF scores are given for.
struct PafSkeleton {
  int num_joints = 0;
  std::vector<std::pair<int, int>> limbs;  // (joint a, joint b) per PAF
};

// The candidates of one image.
struct PafCandidates {
  // Per joint: one column per candidate, rows x, y, score (any coordinate frame).
  std::vector<Eigen::Matrix3Xd> joints;
  // Per limb (a, b): a (candidates of a) x (candidates of b) matrix of PAF scores; <= 0 = no link.
  std::vector<Eigen::MatrixXd> pafs;
};

// Candidates packed for PafAssociator: per joint x of every candidate, then y, then score; per
// limb the PAF scores row by row (candidate a major); all in one block of values, located by a
// small index. A view into a PafCandidateStore.
class PackedPafCandidates {
 public:
  PackedPafCandidates(int num_joints, int num_limbs, const int* index, const double* values)
      : num_joints_(num_joints), num_limbs_(num_limbs), index_(index), values_(values) {}
  int num_joints() const { return num_joints_; }
  int num_limbs() const { return num_limbs_; }
  // Candidates of joint j.
  int count(int j) const { return index_[j]; }
  double x(int j, int i) const { return JointRow(j, 0)[i]; }
  double y(int j, int i) const { return JointRow(j, 1)[i]; }
  double score(int j, int i) const { return JointRow(j, 2)[i]; }
  // Row r (0 = x, 1 = y, 2 = score) of joint j: count(j) values.
  const double* JointRow(int j, int r) const { return values_ + index_[num_joints_ + j] + r * count(j); }
  // Limb k's PAF scores, row-major: (candidates of a) x (candidates of b).
  const double* Paf(int k) const { return values_ + index_[2 * num_joints_ + k]; }
  // The values [begin, end) (for prefetching).
  const double* begin() const { return values_; }
  const double* end() const { return values_ + index_[2 * num_joints_ + num_limbs_]; }

 private:
  int num_joints_;
  int num_limbs_;
  const int* index_;  // count per joint, then the start of each joint's block, of each limb's, the end
  const double* values_;
};

// The candidates of many images packed one after the other in one buffer (and one small index):
// a reader that keeps a whole sequence's candidates appends them image by image in the order they
// will be grouped (a frame's views side by side), so grouping an image touches memory that
// follows the previous one instead of some 50 small blocks (one per joint and limb), which out of
// cache cost more than the grouping itself. Clear() keeps the buffers: appending as much again
// allocates nothing.
class PafCandidateStore {
 public:
  // Appends a copy of `candidates`. Precondition: CheckPafCandidates(skeleton, candidates) == "".
  void Append(const PafSkeleton& skeleton, const PafCandidates& candidates);
  void Clear();
  size_t size() const { return starts_.size(); }
  // Image i (valid until the next Append).
  PackedPafCandidates operator[](size_t i) const {
    return {num_joints_, num_limbs_, index_.data() + starts_[i].first, values_.data() + starts_[i].second};
  }

 private:
  int num_joints_ = 0;
  int num_limbs_ = 0;
  std::vector<std::pair<size_t, size_t>> starts_;  // per image: its first index_ and values_ entry
  std::vector<int> index_;
  std::vector<double> values_;
};

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

// Empty string when `candidates` fits `skeleton` (joint and limb counts, PAF matrix shapes, limb
// joints in range, finite values), else what is wrong.
std::string CheckPafCandidates(const PafSkeleton& skeleton, const PafCandidates& candidates);

// The association above with reused buffers. Precondition: CheckPafCandidates() returned ""
// (asserted).
class PafAssociator {
 public:
  void Run(const PafSkeleton& skeleton, const PafCandidates& candidates, const PafAssociationOptions& options,
           PafPersons* persons);
  // The same on packed candidates (appended with `skeleton`), without the copy.
  void Run(const PafSkeleton& skeleton, const PackedPafCandidates& candidates, const PafAssociationOptions& options,
           PafPersons* persons);

  // A possible connection: limb, candidates a (of the limb's first joint) and b (second).
  struct Connection {
    int limb = 0;
    int a = 0;
    int b = 0;
  };

 private:
  // Every limb's possible connections, in (limb, a, b) order, their sort keys, and their indices
  // by decreasing score (the first `count` of a call; sized to the most PAF entries seen, never
  // shrunk).
  PafCandidateStore packed_candidates_;  // Run(PafCandidates)'s copy
  std::vector<Connection> possible_;
  std::vector<std::uint64_t> packed_;
  std::vector<std::uint32_t> sorted_;
  std::vector<int> used_offset_;      // per limb: first slot of its candidates in used_
  std::vector<unsigned char> used_;   // per limb, per candidate of either joint: used by a kept connection
  std::vector<int> offset_;  // first slot of joint j's candidates in owner_
  std::vector<int> owner_;   // person of each candidate, -1 = none
  std::vector<int> persons_;  // persons as created (merged ones emptied), num_joints each
  std::vector<int> joint_count_;  // joints of each person in persons_
  std::vector<std::uint64_t> mask_;  // the joints of each person in persons_ as a bit set
};

// One-shot form of PafAssociator::Run.
std::vector<PafPerson> AssociatePafs(const PafSkeleton& skeleton, const PafCandidates& candidates,
                                     const PafAssociationOptions& options);

}  // namespace rpt
