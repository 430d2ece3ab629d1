// SPDX-License-Identifier: MIT
// A person's own body frame, built from its hips and shoulders: where a joint-definition adapter
// (core/joint_offsets.h, docs/joint_adapter.md) expresses its per-joint offsets, so an offset
// turns and moves with the person.
//
//   origin  the mid-hip, mean(hip_left, hip_right)
//   x       toward the person's right: (hip_right - hip_left) + (shoulder_right - shoulder_left), normalised
//   z       up the spine: mid-shoulder - mid-hip, made orthogonal to x, normalised
//   y       z x x: the way the person faces (right-handed: right, forward, up)
//
// Degenerate (no frame): a hip or shoulder missing (score 0) or not finite, the summed hip and
// shoulder widths under kMinBodyWidthM, the spine under kMinSpineM, or the spine within 30 degrees
// of the lateral axis (its part orthogonal to x under kMinSpineOrthogonal of its length).
#pragma once

#include <Eigen/Core>
#include <optional>

#include "core/joints.h"

namespace rpt {

inline constexpr double kMinBodyWidthM = 0.10;       // hip width + shoulder width
inline constexpr double kMinSpineM = 0.10;           // mid-hip to mid-shoulder
inline constexpr double kMinSpineOrthogonal = 0.5;   // sin of the smallest spine-to-lateral angle (30 deg)

// The joints a body frame is built from, as indices into one joint list (-1 = absent).
struct BodyFrameJoints {
  int hip_left = -1, hip_right = -1, shoulder_left = -1, shoulder_right = -1;

  static BodyFrameJoints Find(const JointNames& names);
  bool complete() const { return hip_left >= 0 && hip_right >= 0 && shoulder_left >= 0 && shoulder_right >= 0; }
};

struct BodyFrame {
  Eigen::Vector3d origin;  // metres, world frame
  Eigen::Matrix3d axes;    // columns x (right), y (forward), z (up), world frame; orthonormal, det +1

  // A point given in the body frame, in world coordinates.
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& body) const { return origin + axes * body; }
  // A world displacement expressed in the body frame.
  Eigen::Vector3d DirectionToBody(const Eigen::Vector3d& world) const { return axes.transpose() * world; }
};

// The body frame of `person` (4 x joints: x, y, z in metres, score), nullopt when degenerate or
// when `joints` is not complete.
std::optional<BodyFrame> MakeBodyFrame(const Eigen::Ref<const Eigen::Matrix4Xd>& person, const BodyFrameJoints& joints);

}  // namespace rpt
