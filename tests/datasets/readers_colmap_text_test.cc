// SPDX-License-Identifier: MIT
#include "datasets/readers/colmap_text.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <sstream>

#include "core/errors.h"
#include "tests/datasets/readers_h36m_ego_test_util.h"
#include "tests/datasets/tolerance_test_util.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;
using test::InputErrorOf;

constexpr const char* kCameras =
    "# Camera list with one line of data per camera:\n"
    "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
    "# Number of cameras: 3\n"
    "1 OPENCV_FISHEYE 3840 2160 1800.5 1801.25 1920.1 1080.2 0.01 -0.002 0.0003 -0.00004\n"
    "2 PINHOLE 1408 1408 600 600 704 704\n"
    "\n"
    "3 SIMPLE_RADIAL 640 480 500 320 240 0.1\n";

constexpr const char* kImages =
    "# Image list with two lines of data per image:\n"
    "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
    "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
    "# Number of images: 2, mean observations per image: 1\n"
    "7 0.5 0.5 0.5 0.5 1 2 3 1 cam01/00001.jpg\n"
    "10.5 20.25 -1\n"
    "9 1 0 0 0 0 0 0 2 aria01/my image.jpg\n"
    "\n";

TEST(ColmapText, ParsesCamerasAndImages) {
  std::istringstream cameras_in(kCameras);
  const auto cameras = ParseColmapCamerasText(cameras_in, "cameras.txt");
  ASSERT_EQ(cameras.size(), 3u);
  EXPECT_EQ(cameras[0].camera_id, 1);
  EXPECT_EQ(cameras[0].model, "OPENCV_FISHEYE");
  EXPECT_EQ(cameras[0].width, 3840);
  EXPECT_EQ(cameras[0].line, 4);
  ASSERT_EQ(cameras[0].params.size(), 8u);
  EXPECT_DOUBLE_EQ(cameras[0].params[7], -0.00004);
  EXPECT_EQ(cameras[2].line, 7);

  const Camera fisheye = ColmapCameraToCamera(cameras[0], "cameras.txt");
  EXPECT_EQ(fisheye.model, DistortionModel::kFisheye);
  EXPECT_DOUBLE_EQ(fisheye.K(0, 0), 1800.5);
  EXPECT_DOUBLE_EQ(fisheye.K(1, 1), 1801.25);
  EXPECT_DOUBLE_EQ(fisheye.K(0, 2), 1920.1);
  EXPECT_DOUBLE_EQ(fisheye.dist[3], -0.00004);
  EXPECT_EQ(fisheye.height, 2160);
  EXPECT_EQ(ColmapCameraToCamera(cameras[1], "c").model, DistortionModel::kNone);
  const Camera radial = ColmapCameraToCamera(cameras[2], "c");
  EXPECT_EQ(radial.model, DistortionModel::kOpenCV);
  EXPECT_DOUBLE_EQ(radial.dist[0], 0.1);

  std::istringstream images_in(kImages);
  const auto images = ParseColmapImagesText(images_in, "images.txt");
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[0].image_id, 7);
  EXPECT_EQ(images[0].camera_id, 1);
  EXPECT_EQ(images[0].name, "cam01/00001.jpg");
  EXPECT_EQ(images[0].tvec, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(images[1].name, "aria01/my image.jpg");
  EXPECT_EQ(images[1].line, 7);
  // COLMAP's quaternion convention equals Eigen's (w, x, y, z).
  const Eigen::Matrix3d R = ColmapQuaternionToRotation(images[0].qvec_wxyz);
  const Eigen::Matrix3d expected = Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5).toRotationMatrix();
  EXPECT_LT((R - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(ColmapText, MalformedInputNamesFileAndLine) {
  auto cameras = [](const std::string& text) {
    std::istringstream in(text);
    return ParseColmapCamerasText(in, "cameras.txt");
  };
  auto images = [](const std::string& text) {
    std::istringstream in(text);
    return ParseColmapImagesText(in, "images.txt");
  };
  EXPECT_THAT(InputErrorOf([&] { cameras("# c\n1 PINHOLE 10\n"); }), HasSubstr("cameras.txt:2: expected CAMERA_ID MODEL WIDTH HEIGHT"));
  EXPECT_THAT(InputErrorOf([&] { cameras("1 PINHOLE 10 10 1 x 3 4\n"); }), HasSubstr("cameras.txt:1: parameter 1 'x' is not a number"));
  EXPECT_THAT(InputErrorOf([&] { cameras("1 PINHOLE 10 10 1 nan 3 4\n"); }), HasSubstr("cameras.txt:1: parameter 1 is NaN or infinite"));
  EXPECT_THAT(InputErrorOf([&] { cameras("1 PINHOLE 10 10 1 1 3 4\n1 PINHOLE 10 10 1 1 3 4\n"); }), HasSubstr("cameras.txt:2: duplicate CAMERA_ID 1"));
  EXPECT_THAT(InputErrorOf([&] { cameras("1 PINHOLE 0 10 1 1 3 4\n"); }), HasSubstr("image size must be positive"));
  EXPECT_THAT(InputErrorOf([&] { ColmapCameraToCamera(cameras("\n5 FOV 10 10 1 1 3 4 0.1\n")[0], "cameras.txt"); }),
              HasSubstr("cameras.txt:2: camera 5 (FOV): unsupported camera model"));
  EXPECT_THAT(InputErrorOf([&] { ColmapCameraToCamera(cameras("5 OPENCV_FISHEYE 10 10 1 1 3 4\n")[0], "cameras.txt"); }),
              HasSubstr("expected 8 parameters, got 4"));

  EXPECT_THAT(InputErrorOf([&] { images("# h\n1 0.9 0 0 0 0 0 0 1 cam01/00001.jpg\n\n"); }),
              HasSubstr("images.txt:2: quaternion (0.9, 0, 0, 0) has norm 0.9, expected a unit quaternion"));
  EXPECT_THAT(InputErrorOf([&] { images("1 0 0 0 0 0 0 0 1 cam01/00001.jpg\n\n"); }), HasSubstr("has norm 0"));
  EXPECT_THAT(InputErrorOf([&] { images("1 1 0 0 0 0 0 0 1\n"); }), HasSubstr("images.txt:1: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME"));
  EXPECT_THAT(InputErrorOf([&] { images("1 1 0 0 0 0 0 inf 1 a/1.jpg\n\n"); }), HasSubstr("images.txt:1: translation is NaN or infinite"));
  // A missing POINTS2D line swallows the next image line, which is caught.
  EXPECT_THAT(InputErrorOf([&] { images("1 1 0 0 0 0 0 0 1 a/1.jpg\n2 1 0 0 0 0 0 0 1 a/2.jpg\n\n"); }),
              HasSubstr("images.txt:2: expected the POINTS2D line of image 1"));
  EXPECT_THAT(InputErrorOf([&] { images("1 1 0 0 0 0 0 0 1 a/1.jpg\n\n1 1 0 0 0 0 0 0 1 a/2.jpg\n\n"); }), HasSubstr("images.txt:3: duplicate IMAGE_ID 1"));
  EXPECT_THAT(InputErrorOf([] { ReadColmapImagesText("/nonexistent/images.txt"); }), HasSubstr("/nonexistent/images.txt: file not found"));
  // A slightly unnormalised quaternion is accepted and normalised.
  const auto ok = images("1 1.0004 0 0 0 0 0 0 1 a/1.jpg\n\n");
  EXPECT_DOUBLE_EQ(ok[0].qvec_wxyz.norm(), 1.0);
  // 1e-2 off is not rounding.
  EXPECT_THAT(InputErrorOf([&] { images("# a\n# b\n# c\n2 0.505 0.505 0.505 0.505 0 0 0 1 a/1.jpg\n\n"); }),
              HasSubstr("images.txt:4: quaternion (0.505, 0.505, 0.505, 0.505) has norm 1.01, expected a unit quaternion"));
}

TEST(ColmapText, RoundedQuaternionsAreNormalisedAndCounted) {
  std::istringstream in(
      "# 6 significant digits\n"
      "1 0.500001 0.5 0.499999 0.500002 0 0 0 1 a/1.jpg\n\n"
      "2 0.707107 0.707107 0 0 0 0 0 1 a/2.jpg\n\n"
      "3 1 0 0 0 0 0 0 1 a/3.jpg\n\n");  // exact: not counted
  InputWarnings warnings;
  const auto images = ParseColmapImagesText(in, "images.txt", &warnings);
  ASSERT_EQ(images.size(), 3u);
  for (const ColmapImage& image : images) EXPECT_NEAR(image.qvec_wxyz.norm(), 1.0, 1e-15);
  EXPECT_EQ(images[2].qvec_wxyz, Eigen::Vector4d(1, 0, 0, 0));
  test::ExpectOneWarning(warnings, "images.txt", test::kQuaternionsFixed, 2);
  const Eigen::Matrix3d R = ColmapQuaternionToRotation(images[1].qvec_wxyz);
  EXPECT_LT(test::OrthonormalityError(R), 1e-15);
}

}  // namespace
}  // namespace rpt
