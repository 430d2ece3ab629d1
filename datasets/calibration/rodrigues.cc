// SPDX-License-Identifier: MIT
#include "datasets/calibration/rodrigues.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.h"

namespace rpt {

Eigen::Matrix3d RotationFromRodrigues(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, rotation_vector / angle).toRotationMatrix();
}

Eigen::Matrix3d RotationFromStoredRodrigues(const Eigen::Vector3d& rotation_vector, const std::string& where) {
  const double angle = rotation_vector.norm();
  if (!rotation_vector.allFinite()) throw InputError(where + ": the rotation vector has a number that is not finite");
  if (angle > 2 * std::numbers::pi) {
    std::ostringstream message;
    message << where << ": a rotation vector of length " << angle
            << " (its angle in radians) turns more than a full turn (2 pi = 6.283): angles in degrees? "
               "Rotation vectors are axis * angle in radians";
    throw InputError(message.str());
  }
  return RotationFromRodrigues(rotation_vector);
}

Eigen::Vector3d RodriguesFromRotation(const Eigen::Matrix3d& R) {
  // Through the quaternion: Eigen's AngleAxis(Matrix3d) is accurate near 0 and near pi alike.
  const Eigen::AngleAxisd axis_angle(Eigen::Quaterniond(R).normalized());
  return axis_angle.axis() * axis_angle.angle();
}

}  // namespace rpt
