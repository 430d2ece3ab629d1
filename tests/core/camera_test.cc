// SPDX-License-Identifier: MIT
// Tests of the camera model: lens models against hand-computed values and against OpenCV,
// Newton inversion accuracy and robustness, pose conventions, and validation messages.
// Newton inversion accuracy and robustness, pose conventions, and validation messages.
// Over 500 lines on purpose: one file for the one camera model.
#include "core/camera.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace rpt {
namespace {

// Realistic 1920x1080 camera with OpenCV radial-tangential distortion. The focal length matters:
// with these coefficients r_d(r) peaks at r_d = 1.088 (r = 1.60), so with f = 1000 px the image
// corners (r_d = 1.107) would have no undistorted preimage at all. f = 1400 px (70 deg horizontal
// field of view) keeps the whole image inside the invertible region, as a real calibration does.
Camera MakeOpenCVCamera() {
  Camera camera;
  camera.name = "opencv_cam";
  camera.width = 1920;
  camera.height = 1080;
  camera.K << 1400.0, 0.0, 955.0, 0.0, 1405.0, 545.0, 0.0, 0.0, 1.0;
  camera.model = DistortionModel::kOpenCV;
  camera.dist = {-0.25, 0.1, 1e-3, -5e-4, -0.02};
  return camera;
}

// Human3.6M-like camera (coefficients of subject S1, camera 54138969).
Camera MakeH36MCamera() {
  Camera camera;
  camera.name = "h36m_cam";
  camera.width = 1000;
  camera.height = 1002;
  camera.K << 1145.04940459, 0.0, 512.54150496, 0.0, 1143.78109572, 515.45148698, 0.0, 0.0, 1.0;
  camera.model = DistortionModel::kH36M;
  // (k1, k2, p1, p2, k3)
  camera.dist = {-0.207099, 0.247775, -0.001424, -0.000976, -0.003075};
  return camera;
}

// 4K-ish fisheye camera; the corners are at ~62 degrees from the optical axis.
Camera MakeFisheyeCamera() {
  Camera camera;
  camera.name = "fisheye_cam";
  camera.width = 3840;
  camera.height = 2160;
  camera.K << 1800.0, 0.0, 1915.0, 0.0, 1795.0, 1085.0, 0.0, 0.0, 1.0;
  camera.model = DistortionModel::kFisheye;
  camera.dist = {0.05, -0.01, 0.002, -0.0005, 0.0};
  return camera;
}

Camera MakePinholeCamera() {
  Camera camera;
  camera.name = "pinhole_cam";
  camera.width = 1920;
  camera.height = 1080;
  camera.K << 1000.0, 0.0, 960.0, 0.0, 1100.0, 540.0, 0.0, 0.0, 1.0;
  return camera;
}

// Grid of pixels covering the whole image, corners and borders included.
std::vector<Eigen::Vector2d> PixelGrid(const Camera& camera, int steps_x = 25, int steps_y = 15) {
  std::vector<Eigen::Vector2d> grid;
  for (int i = 0; i < steps_x; ++i) {
    for (int j = 0; j < steps_y; ++j) {
      grid.emplace_back(camera.width * static_cast<double>(i) / (steps_x - 1),
                        camera.height * static_cast<double>(j) / (steps_y - 1));
    }
  }
  return grid;
}

Eigen::Vector2d ApplyK(const Camera& camera, const Eigen::Vector2d& xy) {
  return (camera.K * Eigen::Vector3d(xy.x(), xy.y(), 1.0)).head<2>();
}

cv::Mat ToCv(const Eigen::Matrix3d& m) {
  cv::Mat out(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.at<double>(r, c) = m(r, c);
  return out;
}

const cv::TermCriteria kCvCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-14);

std::vector<Camera> AllModelCameras() {
  return {MakePinholeCamera(), MakeOpenCVCamera(), MakeH36MCamera(), MakeFisheyeCamera()};
}

// ---------------------------------------------------------------------------------------------
// Names and flags

TEST(CameraTest, DistortionModelNames) {
  EXPECT_STREQ(DistortionModelName(DistortionModel::kNone), "none");
  EXPECT_STREQ(DistortionModelName(DistortionModel::kOpenCV), "opencv");
  EXPECT_STREQ(DistortionModelName(DistortionModel::kH36M), "h36m");
  EXPECT_STREQ(DistortionModelName(DistortionModel::kFisheye), "fisheye");
}

TEST(CameraTest, HasDistortion) {
  EXPECT_FALSE(MakePinholeCamera().HasDistortion());
  EXPECT_TRUE(MakeOpenCVCamera().HasDistortion());
  EXPECT_TRUE(MakeH36MCamera().HasDistortion());
  EXPECT_TRUE(MakeFisheyeCamera().HasDistortion());

  Camera zero_coefficients = MakeOpenCVCamera();
  zero_coefficients.dist = {0, 0, 0, 0, 0};
  EXPECT_FALSE(zero_coefficients.HasDistortion());
  // Fisheye with k = 0 is still the equidistant projection, not the pinhole one.
  Camera equidistant = MakeFisheyeCamera();
  equidistant.dist = {0, 0, 0, 0, 0};
  EXPECT_TRUE(equidistant.HasDistortion());
  // Coefficients are ignored by the pinhole model.
  Camera pinhole = MakePinholeCamera();
  pinhole.dist = {0.1, 0, 0, 0, 0};
  EXPECT_FALSE(pinhole.HasDistortion());
}

// ---------------------------------------------------------------------------------------------
// Round trips

// Distorted pixel -> normalised undistorted -> Distort -> pixel must give back the pixel.
TEST(CameraTest, PixelRoundTripAllModels) {
  for (const Camera& camera : AllModelCameras()) {
    SCOPED_TRACE(camera.name);
    double max_error = 0.0;
    for (const Eigen::Vector2d& uv : PixelGrid(camera)) {
      const Eigen::Vector2d xy = camera.PixelToNormalized(uv);
      ASSERT_TRUE(xy.allFinite()) << uv.transpose();
      const Eigen::Vector2d back = ApplyK(camera, camera.Distort(xy));
      max_error = std::max(max_error, (back - uv).norm());
    }
    EXPECT_LT(max_error, 1e-6) << "max round-trip error in pixels";
  }
}

// Undistorted normalised point -> Distort -> UndistortNormalized must give back the point,
// measured in (undistorted) pixels.
TEST(CameraTest, NormalizedRoundTripAllModels) {
  for (const Camera& camera : AllModelCameras()) {
    SCOPED_TRACE(camera.name);
    double max_error_px = 0.0;
    for (const Eigen::Vector2d& uv : PixelGrid(camera)) {
      // Take the undistorted position of each grid pixel, so the test points cover exactly the
      // field of view of the image.
      const Eigen::Vector2d xy = camera.PixelToNormalized(uv);
      const Eigen::Vector2d again = camera.UndistortNormalized(camera.Distort(xy));
      max_error_px = std::max(max_error_px, (ApplyK(camera, again) - ApplyK(camera, xy)).norm());
    }
    EXPECT_LT(max_error_px, 1e-6);
  }
}

TEST(CameraTest, RandomRoundTripWithSkew) {
  std::mt19937 rng(12345);
  for (Camera camera : AllModelCameras()) {
    SCOPED_TRACE(camera.name);
    camera.K(0, 1) = 2.5;  // skew
    std::uniform_real_distribution<double> u(0.0, camera.width), v(0.0, camera.height);
    double max_error = 0.0;
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector2d uv(u(rng), v(rng));
      const Eigen::Vector2d back = ApplyK(camera, camera.Distort(camera.PixelToNormalized(uv)));
      max_error = std::max(max_error, (back - uv).norm());
    }
    EXPECT_LT(max_error, 1e-6);
  }
}

TEST(CameraTest, UndistortPixelIsIdentityWithoutDistortion) {
  Camera camera = MakePinholeCamera();
  camera.K(0, 1) = 3.0;
  for (const Eigen::Vector2d& uv : PixelGrid(camera, 5, 5)) {
    EXPECT_LT((camera.UndistortPixel(uv) - uv).norm(), 1e-9);
  }
  // The principal point is a fixed point of every model.
  for (const Camera& distorted : AllModelCameras()) {
    const Eigen::Vector2d c(distorted.K(0, 2), distorted.K(1, 2));
    EXPECT_LT((distorted.UndistortPixel(c) - c).norm(), 1e-9) << distorted.name;
  }
}

// Robustness: far outside the calibrated field of view the polynomial folds back and there is
// no (unique) inverse; the solver must still terminate with a finite answer.
TEST(CameraTest, UndistortNeverReturnsNaNForFiniteInput) {
  std::vector<Camera> cameras = AllModelCameras();
  Camera strong = MakeOpenCVCamera();
  strong.dist = {-0.9, 0.8, 0.05, -0.05, -0.7};
  cameras.push_back(strong);
  Camera strong_fisheye = MakeFisheyeCamera();
  strong_fisheye.dist = {-0.8, 0.5, -0.3, 0.1, 0.0};
  cameras.push_back(strong_fisheye);
  const double values[] = {0.0, 1e-12, -1e-9, 0.3, -0.7, 1.5, -3.0, 10.0, 1e3, -1e6, 1e10, 1e150, -1e300};
  for (const Camera& camera : cameras) {
    for (double x : values) {
      for (double y : values) {
        const Eigen::Vector2d out = camera.UndistortNormalized(Eigen::Vector2d(x, y));
        EXPECT_TRUE(out.allFinite()) << camera.name << " " << x << " " << y;
        // The fisheye inverse only rescales the radius, so it keeps the direction even when the
        // radius is beyond 90 degrees (clamped) or would overflow a naive norm.
        if (camera.model == DistortionModel::kFisheye) {
          EXPECT_GE(out.x() * x, 0.0) << camera.name << " " << x << " " << y;
          EXPECT_GE(out.y() * y, 0.0) << camera.name << " " << x << " " << y;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Agreement with OpenCV

TEST(CameraTest, OpenCVUndistortPointsAgrees) {
  const Camera camera = MakeOpenCVCamera();
  const std::vector<Eigen::Vector2d> grid = PixelGrid(camera);
  std::vector<cv::Point2d> src, dst;
  for (const auto& uv : grid) src.emplace_back(uv.x(), uv.y());
  const cv::Mat K = ToCv(camera.K);
  const cv::Mat D = (cv::Mat_<double>(1, 5) << camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3],
                     camera.dist[4]);
  cv::undistortPoints(src, dst, K, D, cv::noArray(), K, kCvCriteria);
  ASSERT_EQ(dst.size(), grid.size());
  double max_error = 0.0;
  for (size_t i = 0; i < grid.size(); ++i) {
    const Eigen::Vector2d ours = camera.UndistortPixel(grid[i]);
    max_error = std::max(max_error, (ours - Eigen::Vector2d(dst[i].x, dst[i].y)).norm());
  }
  ASSERT_LT(max_error, 0.01);
}

TEST(CameraTest, OpenCVFisheyeUndistortPointsAgrees) {
  const Camera camera = MakeFisheyeCamera();
  const std::vector<Eigen::Vector2d> grid = PixelGrid(camera);
  std::vector<cv::Point2d> src, dst;
  for (const auto& uv : grid) src.emplace_back(uv.x(), uv.y());
  const cv::Mat K = ToCv(camera.K);
  const cv::Mat D = (cv::Mat_<double>(1, 4) << camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3]);
  cv::fisheye::undistortPoints(src, dst, K, D, cv::noArray(), K, kCvCriteria);
  ASSERT_EQ(dst.size(), grid.size());
  double max_error = 0.0;
  for (size_t i = 0; i < grid.size(); ++i) {
    const Eigen::Vector2d ours = camera.UndistortPixel(grid[i]);
    max_error = std::max(max_error, (ours - Eigen::Vector2d(dst[i].x, dst[i].y)).norm());
  }
  ASSERT_LT(max_error, 0.01);
}

// Random 3D points in front of a posed camera, spread over (and a bit beyond) the image.
std::vector<Eigen::Vector3d> RandomWorldPoints(const Camera& camera, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.1 * camera.width, 1.1 * camera.width);
  std::uniform_real_distribution<double> v(-0.1 * camera.height, 1.1 * camera.height);
  std::uniform_real_distribution<double> depth(0.5, 12.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double z = depth(rng);
    const Eigen::Vector3d cam((u(rng) - camera.K(0, 2)) / camera.K(0, 0) * z,
                              (v(rng) - camera.K(1, 2)) / camera.K(1, 1) * z, z);
    points.push_back(camera.R.transpose() * (cam - camera.t));
  }
  return points;
}

void PoseForOpenCV(Camera* camera, cv::Mat* rvec, cv::Mat* tvec) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -1.0, 0.4).normalized()).toRotationMatrix();
  *camera = Camera{camera->name, camera->width, camera->height, camera->K, camera->model, camera->dist,
                   R, Eigen::Vector3d(0.4, -1.2, 3.5)};
  cv::Rodrigues(ToCv(camera->R), *rvec);
  *tvec = (cv::Mat_<double>(3, 1) << camera->t.x(), camera->t.y(), camera->t.z());
}

TEST(CameraTest, OpenCVProjectPointsAgrees) {
  Camera camera = MakeOpenCVCamera();
  cv::Mat rvec, tvec;
  PoseForOpenCV(&camera, &rvec, &tvec);
  const std::vector<Eigen::Vector3d> points = RandomWorldPoints(camera, 500, 7);
  std::vector<cv::Point3d> object;
  for (const auto& p : points) object.emplace_back(p.x(), p.y(), p.z());
  std::vector<cv::Point2d> image;
  const cv::Mat D = (cv::Mat_<double>(1, 5) << camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3],
                     camera.dist[4]);
  cv::projectPoints(object, rvec, tvec, ToCv(camera.K), D, image);
  double max_error = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(camera.Project(points[i], &uv));
    max_error = std::max(max_error, (uv - Eigen::Vector2d(image[i].x, image[i].y)).norm());
  }
  EXPECT_LT(max_error, 1e-6);
}

TEST(CameraTest, OpenCVFisheyeProjectPointsAgrees) {
  Camera camera = MakeFisheyeCamera();
  cv::Mat rvec, tvec;
  PoseForOpenCV(&camera, &rvec, &tvec);
  const std::vector<Eigen::Vector3d> points = RandomWorldPoints(camera, 500, 11);
  std::vector<cv::Point3d> object;
  for (const auto& p : points) object.emplace_back(p.x(), p.y(), p.z());
  std::vector<cv::Point2d> image;
  const cv::Mat D = (cv::Mat_<double>(1, 4) << camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3]);
  cv::fisheye::projectPoints(object, image, rvec, tvec, ToCv(camera.K), D);
  double max_error = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(camera.Project(points[i], &uv));
    max_error = std::max(max_error, (uv - Eigen::Vector2d(image[i].x, image[i].y)).norm());
  }
  EXPECT_LT(max_error, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Human3.6M variant

TEST(CameraTest, H36MDistortHandComputedValue) {
  const Camera h36m = MakeH36MCamera();
  // x = 0.3, y = -0.2: r2 = 0.13, radial = 1 + k1 r2 + k2 r2^2 + k3 r2^3 = 0.977257698...,
  // tan = p1 y + p2 x = -7.48e-6; x_d = x (radial + tan) + p2 r2, y_d = y (radial + tan) + p1 r2.
  const Eigen::Vector2d d = h36m.Distort(Eigen::Vector2d(0.3, -0.2));
  EXPECT_NEAR(d.x(), 0.2930480515175, 1e-13);
  EXPECT_NEAR(d.y(), -0.195635074345, 1e-13);

  // The OpenCV model with the same coefficients differs by exactly the missing half of the
  // tangential term: (p1 x y + p2 x^2, p1 y^2 + p2 x y) = (-2.4e-6, 1.6e-6).
  Camera opencv = h36m;
  opencv.model = DistortionModel::kOpenCV;
  const Eigen::Vector2d o = opencv.Distort(Eigen::Vector2d(0.3, -0.2));
  EXPECT_NEAR(o.x(), 0.2930456515175, 1e-13);
  EXPECT_NEAR(o.y(), -0.195633474345, 1e-13);
  EXPECT_NEAR(o.x() - d.x(), -2.4e-6, 1e-15);
  EXPECT_NEAR(o.y() - d.y(), 1.6e-6, 1e-15);
}

TEST(CameraTest, H36MMatchesOpenCVWithoutTangentialTerms) {
  // With p1 = p2 = 0 the two models coincide.
  Camera h36m = MakeH36MCamera();
  h36m.dist[2] = h36m.dist[3] = 0.0;
  Camera opencv = h36m;
  opencv.model = DistortionModel::kOpenCV;
  for (const Eigen::Vector2d& uv : PixelGrid(h36m, 7, 7)) {
    const Eigen::Vector2d xy = h36m.PixelToNormalized(uv);
    EXPECT_LT((h36m.Distort(xy) - opencv.Distort(xy)).norm(), 1e-15);
    EXPECT_LT((h36m.UndistortPixel(uv) - opencv.UndistortPixel(uv)).norm(), 1e-9);
  }
}

TEST(CameraTest, H36MProjectRoundTrip) {
  Camera camera = MakeH36MCamera();
  // H36M stores R (cam_from_world) and the camera centre T, X_cam = R (X - T), in millimetres;
  // here in metres.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2.0, Eigen::Vector3d(0.1, 0.9, -0.3).normalized()).toRotationMatrix();
  const Eigen::Vector3d center(1.84, 4.95, 1.57);
  Camera posed = Camera::FromCenter(R, center);
  posed.name = camera.name;
  posed.width = camera.width;
  posed.height = camera.height;
  posed.K = camera.K;
  posed.model = camera.model;
  posed.dist = camera.dist;
  for (const Eigen::Vector3d& p : RandomWorldPoints(posed, 300, 3)) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(posed.Project(p, &uv));
    // Back-project: the pixel's ray must pass through the point.
    const Eigen::Vector2d xy = posed.PixelToNormalized(uv);
    const Eigen::Vector3d cam = posed.R * p + posed.t;
    EXPECT_LT((xy - cam.head<2>() / cam.z()).norm() * camera.K(0, 0), 1e-6);
  }
}

// ---------------------------------------------------------------------------------------------
// Pose conventions

// Camera looking along world +X with world Z up: camera x = -Y_world, y = -Z_world, z = +X_world.
Eigen::Matrix3d WorldFromCamLookingAlongX() {
  Eigen::Matrix3d R_wc;
  R_wc.col(0) = Eigen::Vector3d(0, -1, 0);
  R_wc.col(1) = Eigen::Vector3d(0, 0, -1);
  R_wc.col(2) = Eigen::Vector3d(1, 0, 0);
  return R_wc;
}

TEST(CameraTest, FromCenterConvention) {
  const Eigen::Vector3d center(1.0, 2.0, 3.0);
  const Eigen::Matrix3d R_cw = WorldFromCamLookingAlongX().transpose();
  Camera camera = Camera::FromCenter(R_cw, center);
  EXPECT_TRUE(camera.R.isApprox(R_cw));
  EXPECT_LT((camera.t + R_cw * center).norm(), 1e-15);
  EXPECT_LT((camera.Center() - center).norm(), 1e-12);
}

TEST(CameraTest, FromCamToWorldConvention) {
  const Eigen::Vector3d center(1.0, 2.0, 3.0);
  const Eigen::Matrix3d R_wc = WorldFromCamLookingAlongX();
  Camera camera = Camera::FromCamToWorld(R_wc, center);
  camera.K = MakePinholeCamera().K;
  camera.width = 1920;
  camera.height = 1080;
  EXPECT_TRUE(camera.R.isApprox(R_wc.transpose()));
  EXPECT_LT((camera.Center() - center).norm(), 1e-12);
  EXPECT_EQ(camera.Validate(), "");

  // A point straight ahead (centre + forward axis) lands on the principal point.
  Eigen::Vector2d uv;
  ASSERT_TRUE(camera.Project(center + 5.0 * R_wc.col(2), &uv));
  EXPECT_NEAR(uv.x(), 960.0, 1e-9);
  EXPECT_NEAR(uv.y(), 540.0, 1e-9);

  // Hand-computed: offset (4, -1, 0.5) in the world is (1, -0.5, 4) in the camera, so
  // u = 960 + 1000 * 1/4 = 1210, v = 540 + 1100 * (-0.5/4) = 402.5.
  ASSERT_TRUE(camera.Project(center + Eigen::Vector3d(4.0, -1.0, 0.5), &uv));
  EXPECT_NEAR(uv.x(), 1210.0, 1e-9);
  EXPECT_NEAR(uv.y(), 402.5, 1e-9);

  // Both factories describe the same camera.
  const Camera same = Camera::FromCenter(R_wc.transpose(), center);
  EXPECT_TRUE(same.R.isApprox(camera.R));
  EXPECT_TRUE(same.t.isApprox(camera.t));
}

TEST(CameraTest, ProjectReturnsFalseBehindCamera) {
  Camera camera = Camera::FromCamToWorld(WorldFromCamLookingAlongX(), Eigen::Vector3d(1, 2, 3));
  camera.K = MakePinholeCamera().K;
  Eigen::Vector2d uv(-1.0, -1.0);
  // Behind: written but reported as invalid.
  EXPECT_FALSE(camera.Project(Eigen::Vector3d(-4.0, 2.0, 3.0), &uv));
  EXPECT_TRUE(uv.allFinite());
  // In the camera plane (z = 0): no projection, output untouched.
  uv = Eigen::Vector2d(-7.0, -7.0);
  EXPECT_FALSE(camera.Project(Eigen::Vector3d(1.0, 5.0, 3.0), &uv));
  EXPECT_EQ(uv, Eigen::Vector2d(-7.0, -7.0));
  // In front.
  EXPECT_TRUE(camera.Project(Eigen::Vector3d(2.0, 2.0, 3.0), &uv));
}

TEST(CameraTest, PixelToNormalizedHandlesSkew) {
  Camera camera = MakePinholeCamera();
  camera.K(0, 1) = 10.0;
  // Normalised (0.2, -0.1): u = 1000*0.2 + 10*(-0.1) + 960 = 1159, v = 1100*(-0.1) + 540 = 430.
  const Eigen::Vector2d xy = camera.PixelToNormalized(Eigen::Vector2d(1159.0, 430.0));
  EXPECT_NEAR(xy.x(), 0.2, 1e-15);
  EXPECT_NEAR(xy.y(), -0.1, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Validation

TEST(CameraTest, ValidateAcceptsGoodCameras) {
  for (const Camera& camera : AllModelCameras()) EXPECT_EQ(camera.Validate(), "") << camera.name;
}

TEST(CameraTest, ValidateReportsNonOrthonormalR) {
  Camera camera = MakeOpenCVCamera();
  camera.R *= 1.01;
  const std::string message = camera.Validate();
  EXPECT_NE(message.find("opencv_cam"), std::string::npos) << message;
  EXPECT_NE(message.find("orthonormal"), std::string::npos) << message;

  Camera reflection = MakeOpenCVCamera();
  reflection.R(2, 2) = -1.0;
  EXPECT_NE(reflection.Validate().find("det"), std::string::npos) << reflection.Validate();

  // A tiny numerical error (1e-9) is tolerated.
  Camera almost = MakeOpenCVCamera();
  almost.R(0, 1) = 1e-9;
  EXPECT_EQ(almost.Validate(), "");
}

TEST(CameraTest, ValidateReportsSingularK) {
  Camera camera = MakeOpenCVCamera();
  camera.K(1, 1) = 0.0;
  const std::string message = camera.Validate();
  EXPECT_NE(message.find("opencv_cam"), std::string::npos) << message;
  EXPECT_NE(message.find("singular"), std::string::npos) << message;

  Camera bad_row = MakeOpenCVCamera();
  bad_row.K(2, 2) = 2.0;
  EXPECT_NE(bad_row.Validate().find("last row"), std::string::npos) << bad_row.Validate();
}

TEST(CameraTest, ValidateReportsNaNCoefficient) {
  Camera camera = MakeFisheyeCamera();
  camera.dist[1] = std::numeric_limits<double>::quiet_NaN();
  const std::string message = camera.Validate();
  EXPECT_NE(message.find("fisheye_cam"), std::string::npos) << message;
  EXPECT_NE(message.find("coefficient 1"), std::string::npos) << message;

  Camera nan_k = MakeOpenCVCamera();
  nan_k.K(0, 2) = std::numeric_limits<double>::infinity();
  EXPECT_NE(nan_k.Validate().find("K has non-finite"), std::string::npos) << nan_k.Validate();
}

TEST(CameraTest, ValidateReportsZeroImageSize) {
  Camera camera = MakeH36MCamera();
  camera.width = 0;
  const std::string message = camera.Validate();
  EXPECT_NE(message.find("h36m_cam"), std::string::npos) << message;
  EXPECT_NE(message.find("image size"), std::string::npos) << message;
  EXPECT_NE(message.find("0x1002"), std::string::npos) << message;
}

TEST(CameraTest, ValidateListsEveryProblem) {
  Camera camera = MakeOpenCVCamera();
  camera.height = -5;
  camera.K(0, 0) = 0.0;
  camera.dist[4] = std::numeric_limits<double>::infinity();
  const std::string message = camera.Validate();
  EXPECT_NE(message.find("image size"), std::string::npos) << message;
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
  EXPECT_NE(message.find("coefficient 4"), std::string::npos) << message;
}

}  // namespace
}  // namespace rpt
