// SPDX-License-Identifier: MIT
#include "datasets/calibration/rodrigues.h"

#include <Eigen/Geometry>

namespace rpt {

Eigen::Matrix3d RotationFromRodrigues(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, rotation_vector / angle).toRotationMatrix();
}

Eigen::Vector3d RodriguesFromRotation(const Eigen::Matrix3d& R) {
  // Through the quaternion: Eigen's AngleAxis(Matrix3d) is accurate near 0 and near pi alike.
  const Eigen::AngleAxisd axis_angle(Eigen::Quaterniond(R).normalized());
  return axis_angle.axis() * axis_angle.angle();
}

}  // namespace rpt
