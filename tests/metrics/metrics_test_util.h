// SPDX-License-Identifier: MIT
// Hand-built skeletons for the metrics tests. Coordinates in metres, z up, x = person's left.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"

namespace rpt::metrics::test {

// A standing COCO-17 person (CocoBodyJoints() order), metres, centred at x = y = 0.
inline Eigen::Matrix3Xd CocoBodyTemplate() {
  Eigen::Matrix3Xd xyz(3, 17);
  xyz.col(0) << 0.00, 0.10, 1.60;    // nose
  xyz.col(1) << 0.03, 0.08, 1.64;    // eye_left
  xyz.col(2) << -0.03, 0.08, 1.64;   // eye_right
  xyz.col(3) << 0.07, 0.00, 1.62;    // ear_left
  xyz.col(4) << -0.07, 0.00, 1.62;   // ear_right
  xyz.col(5) << 0.18, 0.00, 1.40;    // shoulder_left
  xyz.col(6) << -0.18, 0.00, 1.40;   // shoulder_right
  xyz.col(7) << 0.20, 0.00, 1.10;    // elbow_left
  xyz.col(8) << -0.20, 0.00, 1.10;   // elbow_right
  xyz.col(9) << 0.22, 0.05, 0.85;    // wrist_left
  xyz.col(10) << -0.22, 0.05, 0.85;  // wrist_right
  xyz.col(11) << 0.10, 0.00, 0.95;   // hip_left
  xyz.col(12) << -0.10, 0.00, 0.95;  // hip_right
  xyz.col(13) << 0.11, 0.02, 0.50;   // knee_left
  xyz.col(14) << -0.11, 0.02, 0.50;  // knee_right
  xyz.col(15) << 0.12, 0.00, 0.08;   // ankle_left
  xyz.col(16) << -0.12, 0.00, 0.08;  // ankle_right
  return xyz;
}

// A COCO-WholeBody-133 person: body from CocoBodyTemplate(), the other joints spread deterministically
// around the head (face), feet and wrists (hands). Exact positions do not matter for the tests.
inline Eigen::Matrix3Xd WholeBodyTemplate() {
  Eigen::Matrix3Xd xyz(3, 133);
  xyz.leftCols(17) = CocoBodyTemplate();
  for (int i = 17; i < 23; ++i) xyz.col(i) << (i < 20 ? 0.12 : -0.12), 0.01 * (i - 17), 0.02;
  for (int i = 23; i < 91; ++i) xyz.col(i) << 0.001 * (i - 57), 0.09, 1.60 + 0.001 * (i % 7);
  for (int i = 91; i < 133; ++i) xyz.col(i) << (i < 112 ? 0.23 : -0.23), 0.06, 0.83 - 0.003 * ((i - 91) % 21);
  return xyz;
}

// Returns `xyz` with its columns reordered from `from` joint order to `to` joint order (by name).
inline Eigen::Matrix3Xd Reorder(const Eigen::Matrix3Xd& xyz, const JointNames& from, const JointNames& to) {
  Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(to.size()));
  for (size_t j = 0; j < to.size(); ++j) out.col(j) = xyz.col(FindJoint(from, to[j]));
  return out;
}

// Appends a person with all joints at `xyz_m` and score `score`; returns its index.
inline int AddPerson(Poses3D* poses, const Eigen::Matrix3Xd& xyz_m, double score = 1.0, int track_id = -1) {
  if (poses->num_persons() == 0) poses->num_joints = static_cast<int>(xyz_m.cols());
  auto person = poses->AddPerson(track_id);
  person.topRows<3>() = xyz_m;
  person.row(3).setConstant(score);
  return poses->num_persons() - 1;
}

// An empty Poses3D for `num_joints` joints.
inline Poses3D EmptyPoses(int num_joints) {
  Poses3D poses;
  poses.Clear(num_joints);
  return poses;
}

// `xyz` translated by `offset_m`.
inline Eigen::Matrix3Xd Shifted(const Eigen::Matrix3Xd& xyz, const Eigen::Vector3d& offset_m) {
  return xyz.colwise() + offset_m;
}

}  // namespace rpt::metrics::test
