// SPDX-License-Identifier: MIT
// Implausible cameras and rigs (datasets/camera_plausibility.h) are counted, never refused and
// never silent: principal points far off-centre, two cameras at one spot, rigs that look like
// millimetres read as metres; ReadCalibration counts them for every format.
#include <gmock/gmock.h>
#include <cmath>
#include <gtest/gtest.h>

#include "datasets/calibration/calibration.h"
#include "datasets/camera_plausibility.h"
#include "tests/datasets/calibration_test_util.h"
#include "tests/datasets/io_test_util.h"

namespace rpt {
namespace {

using ::testing::ElementsAre;

std::vector<std::string> Lines(const InputWarnings& warnings) {
  std::vector<std::string> lines;
  for (const InputWarning& w : warnings.items()) lines.push_back(w.Line());
  return lines;
}

TEST(CameraPlausibility, APlausibleRigIsNotWarned) {
  InputWarnings warnings;
  const std::vector<Camera> rig = test::MakeRig(true);
  for (const Camera& camera : rig) CountImplausibleCamera(camera, "rig", &warnings);
  CountImplausibleRig(rig, "rig", &warnings);
  EXPECT_TRUE(warnings.empty());
}

TEST(CameraPlausibility, PrincipalPointFarOffCentreIsCounted) {
  InputWarnings warnings;
  Camera camera = test::MakeRig(false)[0];
  camera.K(0, 2) = 0.5 * camera.width + 0.25 * camera.width;  // at the bound: plausible
  CountImplausibleCamera(camera, "cams", &warnings);
  EXPECT_TRUE(warnings.empty());
  camera.K(1, 2) = 1000;  // (1000 - 540) / 1080 = 0.4259...
  CountImplausibleCamera(camera, "cams", &warnings);
  camera.K(1, 2) = 0;  // 0.5
  CountImplausibleCamera(camera, "cams", &warnings);
  EXPECT_THAT(Lines(warnings),
              ElementsAre("cams: 2 cameras with the principal point more than a quarter of the image from its centre "
                          "(max offset / image side = 0.5)"));
}

// A focal length in millimetres (4.5 "px" over 1920 px: 179.5 degrees) or corrupt (1e12 px) gave
// 0 persons, or dropped the camera, without a word; 170 and 1 degree are the bounds.
TEST(CameraPlausibility, FocalLengthsOutsideAnyLensAreCounted) {
  Camera camera = test::MakeRig(false)[0];
  const auto focal_for = [&](double fov_deg) { return 0.5 * camera.width / std::tan(0.5 * fov_deg * std::acos(-1.0) / 180.0); };
  for (const double fov : {169.9, 1.01, 60.0}) {
    InputWarnings warnings;
    camera.K(0, 0) = focal_for(fov);
    CountImplausibleCamera(camera, "cams", &warnings);
    EXPECT_TRUE(warnings.empty()) << fov << ": " << testing::PrintToString(Lines(warnings));
  }
  InputWarnings warnings;
  camera.K(0, 0) = 4.5;
  CountImplausibleCamera(camera, "cams", &warnings);
  camera.K(0, 0) = focal_for(170.5);
  CountImplausibleCamera(camera, "cams", &warnings);
  camera.K(0, 0) = 1e12;
  CountImplausibleCamera(camera, "cams", &warnings);
  ASSERT_EQ(warnings.items().size(), 2u) << testing::PrintToString(Lines(warnings));
  EXPECT_EQ(warnings.items()[0].what,
            "cameras whose focal length gives a field of view over 170 degrees (in millimetres, not pixels?)");
  EXPECT_EQ(warnings.items()[0].count, 2);
  EXPECT_NEAR(warnings.items()[0].worst, 2.0 * std::atan(0.5 * camera.width / 4.5) * 180.0 / std::acos(-1.0), 1e-9);
  EXPECT_EQ(warnings.items()[1].what, "cameras whose focal length gives a field of view under 1 degree (check the focal length)");
  EXPECT_DOUBLE_EQ(warnings.items()[1].worst, 1e12 / camera.width);
}

TEST(CameraPlausibility, CamerasAtOneSpotAndMillimetreRigsAreCounted) {
  InputWarnings warnings;
  std::vector<Camera> rig = test::MakeRig(false);
  rig[2] = test::LookingAtRoomCentre("cam_c", rig[0].Center() + Eigen::Vector3d(0.006, 0, 0));   // 6 mm from cam_a
  rig[3] = test::LookingAtRoomCentre("cam_d", rig[0].Center() + Eigen::Vector3d(0, 0.0099, 0));  // 11.6 mm from cam_c
  CountImplausibleRig(rig, "rig", &warnings);
  EXPECT_THAT(Lines(warnings), ElementsAre("rig: 2 camera pairs at the same spot (centres less than 1 cm apart)"));
  // The rig in millimetres read as metres: 8.8 km wide.
  warnings = {};
  rig = test::MakeRig(false);
  for (Camera& camera : rig) camera = test::LookingAtRoomCentre(camera.name, camera.Center() * 1000.0);
  CountImplausibleRig(rig, "rig", &warnings);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].what,
            "camera rigs spanning more than 100 m (millimetres read as metres? check the units)");
  // The farthest pair: cam_b (-3.2, 3, 2.5) and cam_d (3, -3.3, 2.6), sqrt(6.2^2 + 6.3^2 + 0.1^2) km apart.
  EXPECT_NEAR(warnings.items()[0].worst, 1000.0 * std::sqrt(6.2 * 6.2 + 6.3 * 6.3 + 0.1 * 0.1), 1e-6);
}

// Cameras side by side see the scene from nearly one direction: named with the widest angle of
// their rays where their views cross (both aim at the room centre (0, 0, 1): the angle there); a
// third camera 90 degrees around fixes it; cameras looking apart share no view (-1, not warned).
TEST(CameraPlausibility, CamerasSeeingTheSceneFromOneDirectionAreNamed) {
  const double kDeg = 180.0 / std::acos(-1.0);
  const Eigen::Vector3d target(0, 0, 1), left(4, 0, 2.5), right(4, 0.3, 2.5);
  std::vector<Camera> rig = {test::LookingAtRoomCentre("left", left), test::LookingAtRoomCentre("right", right)};
  const double expected = std::acos((left - target).normalized().dot((right - target).normalized())) * kDeg;  // 4.0
  std::vector<double> widest = WidestCrossingAnglesDeg(rig);
  ASSERT_EQ(widest.size(), 2u);
  EXPECT_NEAR(widest[0], expected, 1e-9);
  EXPECT_NEAR(widest[1], expected, 1e-9);
  InputWarnings warnings;
  CountImplausibleRig(rig, "rig", &warnings);
  EXPECT_THAT(Lines(warnings),
              ElementsAre("rig: 2 cameras that see the scene from nearly the same direction as every other camera "
                          "('left', 'right'; 4.0 degrees at the least between their rays where their views cross): "
                          "depth along their view is poorly fixed; a camera placed 30 degrees or more around the "
                          "scene from them fixes it"));
  // Parallel axes (a stereo bar, 20 cm): the point 4 m ahead, 2 atan(0.1 / 4) apart.
  Camera twin = Camera::FromCenter(rig[0].R, left + 0.2 * rig[0].R.row(0).transpose());
  twin.name = "twin";
  EXPECT_NEAR(WidestCrossingAnglesDeg({rig[0], twin})[0], 2 * std::atan(0.1 / 4.0) * kDeg, 1e-9);
  // The same rig in millimetres read as metres: the same angles (a 100 m cap on where views cross
  // read it as 180 degrees).
  std::vector<Camera> scaled;
  for (const Camera& camera : rig) scaled.push_back(Camera::FromCenter(camera.R, 1000.0 * camera.Center()));
  EXPECT_NEAR(WidestCrossingAnglesDeg(scaled)[0], widest[0], 1e-6);
  // A third camera 90 degrees around: every camera has a wide partner.
  rig.push_back(test::LookingAtRoomCentre("side", {0, 4, 2.5}));
  widest = WidestCrossingAnglesDeg(rig);
  EXPECT_GT(widest[0], 60.0);
  warnings = {};
  CountImplausibleRig(rig, "rig", &warnings);
  EXPECT_TRUE(warnings.empty()) << testing::PrintToString(Lines(warnings));
  // Looking apart (back to back): no crossing view, nothing to say.
  const Eigen::Matrix3d turned = Eigen::Vector3d(-1, 1, -1).asDiagonal() * rig[0].R;  // half a turn about its y axis
  const Camera back = Camera::FromCenter(turned, left + Eigen::Vector3d(0, 0.3, 0));
  EXPECT_THAT(WidestCrossingAnglesDeg({rig[0], back}), ElementsAre(-1.0, -1.0));
}

TEST(CameraPlausibility, ReadCalibrationCountsImplausibleRigsOfEveryFormat) {
  test::TempDir dir;
  std::vector<Camera> rig = test::MakeRig(false);
  rig[1] = test::LookingAtRoomCentre("cam_b", rig[0].Center());
  rig[2].K(0, 2) = 100;
  for (const std::string name : {"rig.json", "rig.toml", "rig.yml"}) {
    WriteCalibration(dir.path() / name, rig);
    InputWarnings warnings;
    ReadCalibration(dir.path() / name, {}, &warnings);
    const std::string source = (dir.path() / name).string();
    EXPECT_THAT(Lines(warnings),
                testing::ElementsAre(
                    source + ": 1 cameras with the principal point more than a quarter of the image from its centre "
                             "(max offset / image side = 0.447917)",
                    source + ": 1 camera pairs at the same spot (centres less than 1 cm apart)"));
  }
}

}  // namespace
}  // namespace rpt
