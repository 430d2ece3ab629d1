// SPDX-License-Identifier: MIT
#include "core/joint_offsets.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace rpt {
namespace {

// The median of `values` (reordered); the mean of the two middle ones for an even count.
double MedianOf(std::vector<double>* values) {
  const size_t n = values->size();
  const auto middle = values->begin() + static_cast<long>(n / 2);
  std::nth_element(values->begin(), middle, values->end());
  const double upper = *middle;
  if (n % 2 == 1) return upper;
  const double lower = *std::max_element(values->begin(), middle);
  return 0.5 * (lower + upper);
}

}  // namespace

int ApplyJointOffsets(const std::vector<Eigen::Vector3d>& offsets_m, const BodyFrameJoints& frame_joints,
                      Poses3D* persons) {
  assert(static_cast<int>(offsets_m.size()) == persons->num_joints);
  int moved = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    Eigen::Map<Eigen::Matrix4Xd> person = persons->Person(p);
    const std::optional<BodyFrame> frame = MakeBodyFrame(person, frame_joints);
    if (!frame) continue;
    for (int j = 0; j < persons->num_joints; ++j) {
      if (person(3, j) > 0.0) person.col(j).head<3>() += frame->axes * offsets_m[static_cast<size_t>(j)];
    }
    ++moved;
  }
  return moved;
}

bool JointOffsetFit::Add(const Eigen::Ref<const Eigen::Matrix4Xd>& predicted, const Eigen::Ref<const Eigen::Matrix3Xd>& gt,
                         const BodyFrameJoints& frame_joints) {
  assert(predicted.cols() == num_joints() && gt.cols() == num_joints());
  const std::optional<BodyFrame> frame = MakeBodyFrame(predicted, frame_joints);
  if (!frame) return false;
  for (int j = 0; j < num_joints(); ++j) {
    const Eigen::Vector3d position = predicted.col(j).head<3>();
    if (!(predicted(3, j) > 0.0) || !position.allFinite() || !gt.col(j).allFinite()) continue;
    residuals_[static_cast<size_t>(j)].push_back(frame->DirectionToBody(gt.col(j) - position));
  }
  return true;
}

void JointOffsetFit::Merge(const JointOffsetFit& other) {
  assert(other.num_joints() == num_joints());
  for (size_t j = 0; j < residuals_.size(); ++j) {
    residuals_[j].insert(residuals_[j].end(), other.residuals_[j].begin(), other.residuals_[j].end());
  }
}

JointOffsetFit::Result JointOffsetFit::Finish(OffsetStatistic statistic, long min_samples) const {
  Result result;
  const size_t n_joints = residuals_.size();
  result.offset_m.assign(n_joints, Eigen::Vector3d::Zero());
  result.samples.assign(n_joints, 0);
  result.spread_m.assign(n_joints, std::numeric_limits<double>::quiet_NaN());
  std::vector<double> values;
  for (size_t j = 0; j < n_joints; ++j) {
    const std::vector<Eigen::Vector3d>& r = residuals_[j];
    result.samples[j] = static_cast<long>(r.size());
    if (r.empty()) continue;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    if (statistic == OffsetStatistic::kMean) {
      for (const Eigen::Vector3d& v : r) offset += v;
      offset /= static_cast<double>(r.size());
    } else {
      for (int axis = 0; axis < 3; ++axis) {
        values.clear();
        for (const Eigen::Vector3d& v : r) values.push_back(v(axis));
        offset(axis) = MedianOf(&values);
      }
    }
    values.clear();
    for (const Eigen::Vector3d& v : r) values.push_back((v - offset).norm());
    result.spread_m[j] = MedianOf(&values);
    if (result.samples[j] >= min_samples) result.offset_m[j] = offset;
  }
  return result;
}

}  // namespace rpt
