// SPDX-License-Identifier: MIT
// Helpers of the calibration tests (tests/datasets/calibration_*_test.cc): a hand-built camera
// whose projection of one point is known, a rig with every lens model, and the comparison of two
// camera lists by their projections.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/camera.h"

namespace rpt::test {

inline std::filesystem::path WriteCalibrationText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The hand-built camera every format's example file holds: 1920 x 1080, fx = fy = 1000, principal
// point (960, 540), no distortion, centre (0, -4, 1.5) m looking along +y (world z up):
// R = Rx(90 deg) = [[1, 0, 0], [0, 0, -1], [0, 1, 0]] world -> camera, t = -R C = (0, 1.5, 4).
// The world point (0.5, 1, 2) is at (0.5, -0.5, 5) in the camera, so at pixel (1060, 440).
inline const Eigen::Vector3d kKnownPoint(0.5, 1.0, 2.0);
inline const Eigen::Vector2d kKnownPixel(1060.0, 440.0);

// Checks that `camera` is the hand-built camera: the known point at the known pixel (1e-9 px),
// the centre at (0, -4, 1.5) m.
inline void ExpectHandBuiltCamera(const Camera& camera) {
  Eigen::Vector2d uv;
  ASSERT_TRUE(camera.Project(kKnownPoint, &uv)) << camera.name;
  EXPECT_NEAR(uv.x(), kKnownPixel.x(), 1e-9) << camera.name;
  EXPECT_NEAR(uv.y(), kKnownPixel.y(), 1e-9) << camera.name;
  EXPECT_NEAR((camera.Center() - Eigen::Vector3d(0, -4, 1.5)).norm(), 0.0, 1e-12) << camera.name;
  EXPECT_EQ(camera.width, 1920);
  EXPECT_EQ(camera.height, 1080);
}

// A camera at `center` looking at the point (0, 0, 1), x right, y down (world z up).
inline Camera LookingAtRoomCentre(const std::string& name, const Eigen::Vector3d& center) {
  const Eigen::Vector3d z = (Eigen::Vector3d(0, 0, 1) - center).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R << x.transpose(), y.transpose(), z.transpose();
  Camera camera = Camera::FromCenter(R, center);
  camera.name = name;
  camera.width = 1920;
  camera.height = 1080;
  camera.K << 1000.25, 0.5, 955.5, 0, 1001.75, 541.25, 0, 0, 1;
  return camera;
}

// Four cameras around a 6 x 6 m room: pinhole, OpenCV radial-tangential (with k3), OpenCV
// without k3, and fisheye when `with_fisheye` (the formats that have no fisheye model get a
// second OpenCV camera instead).
inline std::vector<Camera> MakeRig(bool with_fisheye) {
  std::vector<Camera> rig = {
      LookingAtRoomCentre("cam_a", {3.1, 2.9, 2.4}), LookingAtRoomCentre("cam_b", {-3.2, 3.0, 2.5}),
      LookingAtRoomCentre("cam_c", {-2.9, -3.1, 2.3}), LookingAtRoomCentre("cam_d", {3.0, -3.3, 2.6})};
  rig[1].model = DistortionModel::kOpenCV;
  rig[1].dist = {-0.21, 0.07, 0.0011, -0.0007, -0.012};
  rig[2].model = DistortionModel::kOpenCV;
  rig[2].dist = {0.05, -0.01, -0.0004, 0.0009, 0.0};
  if (with_fisheye) {
    rig[3].model = DistortionModel::kFisheye;
    rig[3].dist = {0.1, -0.02, 0.003, -0.0004, 0.0};
  } else {
    rig[3].model = DistortionModel::kOpenCV;
    rig[3].dist = {-0.1, 0.02, 0.0, 0.0, 0.001};
  }
  return rig;
}

// Points in front of `camera`: a grid over its view at depths 1.5 to 9 m.
inline std::vector<Eigen::Vector3d> PointsInView(const Camera& camera) {
  std::vector<Eigen::Vector3d> points;
  for (double depth : {1.5, 4.0, 9.0}) {
    for (double x : {-0.5, -0.1, 0.0, 0.3, 0.55}) {
      for (double y : {-0.3, 0.0, 0.25}) {
        points.push_back(camera.R.transpose() * (Eigen::Vector3d(x, y, 1.0) * depth - camera.t));
      }
    }
  }
  return points;
}

// The two lists hold the same cameras (names, sizes, lens models) and project points in view to
// the same pixels within `tolerance_px`.
inline void ExpectSameProjections(const std::vector<Camera>& expected, const std::vector<Camera>& actual,
                                  double tolerance_px = 1e-9) {
  ASSERT_EQ(expected.size(), actual.size());
  double worst = 0;
  for (std::size_t c = 0; c < expected.size(); ++c) {
    const Camera& a = expected[c];
    const Camera& b = actual[c];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.width, b.width) << a.name;
    EXPECT_EQ(a.height, b.height) << a.name;
    EXPECT_EQ(a.HasDistortion() ? a.model : DistortionModel::kNone,
              b.HasDistortion() ? b.model : DistortionModel::kNone)
        << a.name;
    for (const Eigen::Vector3d& point : PointsInView(a)) {
      Eigen::Vector2d uv_a, uv_b;
      a.Project(point, &uv_a);
      b.Project(point, &uv_b);
      worst = std::max(worst, (uv_a - uv_b).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LE(worst, tolerance_px);
}

}  // namespace rpt::test
