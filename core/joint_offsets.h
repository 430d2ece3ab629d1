// SPDX-License-Identifier: MIT
// Joint-definition offsets: per joint, a displacement in the person's own body frame
// (core/body_frame.h) that moves a detector's joint to where a dataset defines it (a detector's hip
// sits several centimetres from a motion-capture hip). Fitted from matched (prediction, GT)
// pairs as the mean or the per-axis median of the GT-minus-prediction residuals in the body frame;
// applied after triangulation. docs/joint_adapter.md.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/body_frame.h"
#include "core/poses.h"

namespace rpt {

// Moves every present joint j (score > 0) of every person with a body frame by
// frame.axes * offsets_m[j] (offsets_m has one entry per joint of `persons`; zero = unchanged).
// The frame is the person's before any joint moves. Persons without a body frame are left as
// they are. Returns the number of persons moved. Allocates nothing.
int ApplyJointOffsets(const std::vector<Eigen::Vector3d>& offsets_m, const BodyFrameJoints& frame_joints,
                      Poses3D* persons);

// How the residuals of a joint become its offset.
enum class OffsetStatistic {
  kMean,    // the mean residual (least squares)
  kMedian,  // the median of each body axis separately (robust to mismatched persons)
};

// Collects the residuals of matched persons, joint by joint, in their body frames.
class JointOffsetFit {
 public:
  explicit JointOffsetFit(int num_joints) : residuals_(static_cast<size_t>(num_joints)) {}

  // One matched person: `predicted` (4 x joints) and per joint the GT position (3 x joints,
  // metres; a column with a NaN = no GT for that joint). Joint j counts when predicted present
  // (score > 0, finite) and its GT finite. Returns false (and adds nothing) when the predicted
  // person has no body frame.
  bool Add(const Eigen::Ref<const Eigen::Matrix4Xd>& predicted, const Eigen::Ref<const Eigen::Matrix3Xd>& gt,
           const BodyFrameJoints& frame_joints);
  // Appends the residuals of `other` (same joint count) after this one's.
  void Merge(const JointOffsetFit& other);

  struct Result {
    std::vector<Eigen::Vector3d> offset_m;  // per joint; zero where samples < min_samples
    std::vector<long> samples;              // residuals per joint
    // Per joint, the median distance of the residuals from the offset (metres, NaN without
    // samples): how well one offset describes the joint.
    std::vector<double> spread_m;
  };
  // The offsets; joints with fewer than `min_samples` residuals get none (zero).
  Result Finish(OffsetStatistic statistic, long min_samples) const;

  int num_joints() const { return static_cast<int>(residuals_.size()); }

 private:
  std::vector<std::vector<Eigen::Vector3d>> residuals_;  // per joint, body frame, metres
};

}  // namespace rpt
