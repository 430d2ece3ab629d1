// SPDX-License-Identifier: MIT
// The input of the part-affinity-field (PAF) association (openpose_paf_association.h): the
// skeleton, the bottom-up joint candidates of one image with the PAF scores between them, their
// check, and their packed form (PackedPafCandidates, kept many images at a time by a
// PafCandidateStore) that PafAssociator reads.
#pragma once

#include <Eigen/Core>
#include <cstddef>
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

// Empty string when `candidates` fits `skeleton` (joint and limb counts, PAF matrix shapes, limb
// joints in range, finite values), else what is wrong.
std::string CheckPafCandidates(const PafSkeleton& skeleton, const PafCandidates& candidates);

// The candidates of one image packed for PafAssociator, a view into a PafCandidateStore. Every
// candidate has a slot, its index among all candidates of the image joint after joint (joint j's
// candidate i is slot(j) + i). One block of values holds, in this order, the score of every slot,
// every limb's PAF scores row by row (candidate a major), then the x and the y of every slot: the
// association reads only the scores and the PAF scores, side by side at the block's start
// (association_end()); x and y are read afterwards for the few candidates it kept. A small index
// locates the parts: the count per joint, the first slot per joint (and the number of slots), the
// start of each limb's PAF scores (and their end).
class PackedPafCandidates {
 public:
  PackedPafCandidates(int num_joints, int num_limbs, const int* index, const double* values)
      : num_joints_(num_joints), num_limbs_(num_limbs), index_(index), values_(values) {}
  int num_joints() const { return num_joints_; }
  int num_limbs() const { return num_limbs_; }
  // Candidates of joint j, the first one's slot, all of them.
  int count(int j) const { return index_[j]; }
  const int* counts() const { return index_; }  // of every joint
  int slot(int j) const { return index_[num_joints_ + j]; }
  int num_slots() const { return index_[2 * num_joints_]; }
  // The first slot of every joint, and the number of slots after them (num_joints + 1 values).
  const int* slots() const { return index_ + num_joints_; }
  double x(int j, int i) const { return values_[PafEnd() + slot(j) + i]; }
  double y(int j, int i) const { return values_[PafEnd() + num_slots() + slot(j) + i]; }
  double score(int j, int i) const { return values_[slot(j) + i]; }
  // The score of every slot.
  const double* scores() const { return values_; }
  // Limb k's PAF scores, row-major: (candidates of a) x (candidates of b).
  const double* Paf(int k) const { return values_ + index_[2 * num_joints_ + 1 + k]; }
  // The PAF scores of all limbs, limb after limb: [pafs_begin(), association_end()).
  const double* pafs_begin() const { return values_ + num_slots(); }
  // The values [begin(), association_end()) are all the association reads; [begin(), end()) all.
  const double* begin() const { return values_; }
  const double* association_end() const { return values_ + PafEnd(); }
  const double* end() const { return values_ + PafEnd() + 2 * num_slots(); }
  // The index: [index_begin(), index_end()).
  const int* index_begin() const { return index_; }
  const int* index_end() const { return index_ + 2 * num_joints_ + num_limbs_ + 2; }

 private:
  int PafEnd() const { return index_[2 * num_joints_ + 1 + num_limbs_]; }

  int num_joints_;
  int num_limbs_;
  const int* index_;
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

}  // namespace rpt
