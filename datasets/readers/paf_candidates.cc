// SPDX-License-Identifier: MIT
#include "datasets/readers/paf_candidates.h"

#include <cassert>

namespace rpt {

std::string CheckPafCandidates(const PafSkeleton& skeleton, const PafCandidates& candidates) {
  if (static_cast<int>(candidates.joints.size()) != skeleton.num_joints) {
    return std::to_string(candidates.joints.size()) + " joints, the skeleton has " +
           std::to_string(skeleton.num_joints);
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
  assert(starts_.empty() ||
         (num_joints_ == skeleton.num_joints && num_limbs_ == static_cast<int>(skeleton.limbs.size())));
  num_joints_ = skeleton.num_joints;
  num_limbs_ = static_cast<int>(skeleton.limbs.size());
  const size_t nj = static_cast<size_t>(num_joints_);
  const size_t nl = static_cast<size_t>(num_limbs_);
  const size_t first_index = index_.size();
  const size_t first_value = values_.size();
  starts_.emplace_back(first_index, first_value);
  index_.resize(first_index + 2 * nj + nl + 2);
  int* index = index_.data() + first_index;
  int slots = 0;
  for (size_t j = 0; j < nj; ++j) {
    index[j] = static_cast<int>(candidates.joints[j].cols());
    index[nj + j] = slots;
    slots += index[j];
  }
  index[2 * nj] = slots;
  size_t size = static_cast<size_t>(slots);  // the scores come first
  for (size_t k = 0; k < nl; ++k) {
    index[2 * nj + 1 + k] = static_cast<int>(size);
    size += static_cast<size_t>(candidates.pafs[k].size());
  }
  index[2 * nj + 1 + nl] = static_cast<int>(size);
  size += 2 * static_cast<size_t>(slots);  // x, y
  values_.resize(first_value + size);
  double* score = values_.data() + first_value;
  double* paf = score + slots;
  double* x = score + index[2 * nj + 1 + nl];
  double* y = x + slots;
  for (const Eigen::Matrix3Xd& joint : candidates.joints) {
    for (Eigen::Index i = 0; i < joint.cols(); ++i) {
      *x++ = joint(0, i);
      *y++ = joint(1, i);
      *score++ = joint(2, i);
    }
  }
  for (const Eigen::MatrixXd& matrix : candidates.pafs) {
    for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
      for (Eigen::Index c = 0; c < matrix.cols(); ++c) *paf++ = matrix(r, c);
    }
  }
}

void PafCandidateStore::Clear() {
  starts_.clear();
  index_.clear();
  values_.clear();
}

}  // namespace rpt
