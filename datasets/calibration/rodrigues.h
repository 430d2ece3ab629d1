// SPDX-License-Identifier: MIT
// Rodrigues rotation vectors (axis * angle in radians, cv::Rodrigues' convention), as OpenCV,
// EasyMocap, Pose2Sim / anipose and 4D-Association store rotations.
#pragma once

#include <Eigen/Core>
#include <string>

namespace rpt {

// The rotation matrix of a rotation vector (identity for the zero vector).
Eigen::Matrix3d RotationFromRodrigues(const Eigen::Vector3d& rotation_vector);
// The rotation of a rotation vector read from a file (`where`: the file and place). Throws
// InputError when its angle exceeds a full turn (2 pi): no calibration tool writes one
// (cv::Rodrigues gives angles up to pi), angles in degrees read as radians do.
Eigen::Matrix3d RotationFromStoredRodrigues(const Eigen::Vector3d& rotation_vector, const std::string& where);
// The rotation vector of a rotation matrix, angle in [0, pi]; exact to round-off for every
// angle, including 0 and pi.
Eigen::Vector3d RodriguesFromRotation(const Eigen::Matrix3d& R);

}  // namespace rpt
