// SPDX-License-Identifier: MIT
// Camera model: intrinsics K, lens distortion, and the world-to-camera transform.
//
// Convention: X_cam = R * X_world + t (metres), x = X_cam / Z_cam, distorted with the lens
// model, then pixel = K * [x_d, y_d, 1]. Readers convert other conventions (camera centre,
// camera-to-world) at the edge with the factory functions below.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

namespace rpt {

enum class DistortionModel {
  kNone,     // pinhole
  kOpenCV,   // radial-tangential, coefficients (k1, k2, p1, p2, k3) as in OpenCV
  kH36M,     // Human3.6M variant: like kOpenCV but tangential term without the factor 2
  kFisheye,  // OpenCV fisheye / COLMAP OPENCV_FISHEYE, coefficients (k1, k2, k3, k4)
};

const char* DistortionModelName(DistortionModel model);

struct Camera {
  std::string name;
  int width = 0;   // image size in pixels
  int height = 0;
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  DistortionModel model = DistortionModel::kNone;
  // kOpenCV / kH36M: k1 k2 p1 p2 k3. kFisheye: k1 k2 k3 k4 (fifth entry unused).
  std::array<double, 5> dist{0, 0, 0, 0, 0};
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // cam_from_world rotation
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // cam_from_world translation (m)

  // Builds t from a camera centre in world coordinates: t = -R * C.
  static Camera FromCenter(const Eigen::Matrix3d& R_cam_from_world, const Eigen::Vector3d& center_in_world);
  // Builds R, t from a camera-to-world rotation and the camera centre.
  static Camera FromCamToWorld(const Eigen::Matrix3d& R_world_from_cam, const Eigen::Vector3d& center_in_world);

  Eigen::Vector3d Center() const { return -R.transpose() * t; }
  bool HasDistortion() const;

  // Applies the lens model to normalised undistorted coordinates (x/z, y/z).
  Eigen::Vector2d Distort(const Eigen::Vector2d& xy) const;
  // Inverts Distort() iteratively (Newton); exact to ~1e-12 for well-posed inputs.
  Eigen::Vector2d UndistortNormalized(const Eigen::Vector2d& xy_distorted) const;

  // Distorted pixel -> normalised undistorted camera coordinates.
  Eigen::Vector2d PixelToNormalized(const Eigen::Vector2d& uv_px) const;
  // Distorted pixel -> undistorted pixel (same K, no distortion).
  Eigen::Vector2d UndistortPixel(const Eigen::Vector2d& uv_px) const;

  // World point -> distorted pixel. Returns false when the point is not in front of the camera
  // (the output is still written for z != 0).
  bool Project(const Eigen::Vector3d& point_in_world, Eigen::Vector2d* uv_px) const;

  // Empty string when valid, otherwise a description (R orthonormal, K invertible, finite
  // values, positive image size).
  std::string Validate() const;
};

}  // namespace rpt
