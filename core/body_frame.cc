// SPDX-License-Identifier: MIT
#include "core/body_frame.h"

#include <cmath>

namespace rpt {

BodyFrameJoints BodyFrameJoints::Find(const JointNames& names) {
  BodyFrameJoints joints;
  joints.hip_left = FindJoint(names, "hip_left");
  joints.hip_right = FindJoint(names, "hip_right");
  joints.shoulder_left = FindJoint(names, "shoulder_left");
  joints.shoulder_right = FindJoint(names, "shoulder_right");
  return joints;
}

std::optional<BodyFrame> MakeBodyFrame(const Eigen::Ref<const Eigen::Matrix4Xd>& person, const BodyFrameJoints& joints) {
  if (!joints.complete()) return std::nullopt;
  for (const int j : {joints.hip_left, joints.hip_right, joints.shoulder_left, joints.shoulder_right}) {
    if (j >= person.cols() || !(person(3, j) > 0.0) || !person.col(j).head<3>().allFinite()) return std::nullopt;
  }
  const Eigen::Vector3d hip_left = person.col(joints.hip_left).head<3>();
  const Eigen::Vector3d hip_right = person.col(joints.hip_right).head<3>();
  const Eigen::Vector3d shoulder_left = person.col(joints.shoulder_left).head<3>();
  const Eigen::Vector3d shoulder_right = person.col(joints.shoulder_right).head<3>();
  const Eigen::Vector3d lateral = (hip_right - hip_left) + (shoulder_right - shoulder_left);
  const double width = lateral.norm();
  if (!(width >= kMinBodyWidthM)) return std::nullopt;
  const Eigen::Vector3d x = lateral / width;
  const Eigen::Vector3d mid_hip = 0.5 * (hip_left + hip_right);
  const Eigen::Vector3d spine = 0.5 * (shoulder_left + shoulder_right) - mid_hip;
  const double spine_length = spine.norm();
  if (!(spine_length >= kMinSpineM)) return std::nullopt;
  const Eigen::Vector3d up = spine - spine.dot(x) * x;
  const double up_length = up.norm();
  if (!(up_length >= kMinSpineOrthogonal * spine_length)) return std::nullopt;
  BodyFrame frame;
  frame.origin = mid_hip;
  frame.axes.col(0) = x;
  frame.axes.col(2) = up / up_length;
  frame.axes.col(1) = frame.axes.col(2).cross(x);
  return frame;
}

}  // namespace rpt
