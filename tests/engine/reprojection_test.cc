// SPDX-License-Identifier: MIT
// ReprojectFrame (engine/reprojection.h) on a hand-computed case: a pinhole camera with one radial
// distortion coefficient, known 3D points and the exact pixels they land on.
#include "engine/reprojection.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rpt::engine {
namespace {

using Status = JointReprojection;

// f = 1000 px, principal point (320, 240), 640 x 480, at the origin looking down +z, k1 = 0.1:
// a point (x, y, z) lands at u = 320 + 1000 (x/z)(1 + 0.1 r2), v = 240 + 1000 (y/z)(1 + 0.1 r2),
// r2 = (x/z)^2 + (y/z)^2.
Camera TestCamera() {
  Camera camera;
  camera.name = "cam0";
  camera.width = 640;
  camera.height = 480;
  camera.K << 1000, 0, 320, 0, 1000, 240, 0, 0, 1;
  camera.model = DistortionModel::kOpenCV;
  camera.dist = {0.1, 0, 0, 0, 0};
  return camera;
}

const JointNames kPredictionJoints = {"nose", "shoulder_left", "shoulder_right", "hip_middle", "wrist_left"};
const JointNames kDetectionJoints = {"nose", "shoulder_left", "shoulder_right", "wrist_left"};

void SetJoint(Eigen::Map<Eigen::Matrix4Xd> person, int j, double x, double y, double z, double score) {
  person.col(j) << x, y, z, score;
}

// Person 0 (track 7) in front of the camera; person 1 (track 8) behind it.
Poses3D TestPredictions() {
  Poses3D poses;
  poses.Clear(5);
  auto a = poses.AddPerson(7);
  SetJoint(a, 0, 0.1, -0.2, 2, 0.9);  // nose: x/z = 0.05, y/z = -0.1, r2 = 0.0125 -> (370.0625, 139.875)
  SetJoint(a, 1, 0, 0, 2, 0.8);       // shoulder_left: on the axis -> (320, 240)
  SetJoint(a, 2, 0.2, 0, 2, 0.7);     // shoulder_right: x/z = 0.1, r2 = 0.01 -> (420.1, 240)
  SetJoint(a, 3, 0, 0.2, 2, 0.6);     // hip_middle: -> (320, 340.1); the detector has no such joint
  SetJoint(a, 4, 0.3, 0.3, 2, 0.0);   // wrist_left: missing in 3D (score 0)
  auto b = poses.AddPerson(8);
  for (int j = 0; j < 5; ++j) SetJoint(b, j, 0.1 * j, 0, -2, 0.9);
  return poses;
}

// Detection 0: a person far away. Detection 1: person 0's nose 3 px right and 4 px down of its
// projection (5 px), its left shoulder exactly, its right shoulder not detected (score 0), a
// wrist where the prediction has none.
Poses2D TestDetections() {
  Poses2D view;
  view.Clear(4);
  auto far = view.AddPerson();
  for (int j = 0; j < 4; ++j) far.col(j) << 20 + j, 20, 0.9;
  auto near = view.AddPerson();
  near.col(0) << 373.0625, 143.875, 0.9;
  near.col(1) << 320, 240, 0.8;
  near.col(2) << 400, 250, 0.0;
  near.col(3) << 300, 300, 0.5;
  return view;
}

TEST(Reprojection, ProjectsWithTheLensModelAndMeasuresAgainstTheMatchedDetection) {
  const Poses3D predictions = TestPredictions();
  const std::vector<ViewReprojection> views =
      ReprojectFrame({TestCamera()}, {TestDetections()}, kDetectionJoints, {&predictions, &kPredictionJoints}, {});
  ASSERT_EQ(views.size(), 1u);
  const ViewReprojection& view = views[0];
  ASSERT_EQ(view.predictions.size(), 2u);
  EXPECT_TRUE(view.gt.empty());

  const ReprojectedPerson& a = view.predictions[0];
  EXPECT_EQ(a.person_idx, 0);
  EXPECT_EQ(a.track_id, 7);
  EXPECT_NEAR(a.uv_px(0, 0), 370.0625, 1e-9);
  EXPECT_NEAR(a.uv_px(1, 0), 139.875, 1e-9);
  EXPECT_NEAR(a.uv_px(0, 1), 320, 1e-9);
  EXPECT_NEAR(a.uv_px(1, 1), 240, 1e-9);
  EXPECT_NEAR(a.uv_px(0, 2), 420.1, 1e-9);
  EXPECT_NEAR(a.uv_px(1, 2), 240, 1e-9);
  EXPECT_NEAR(a.uv_px(0, 3), 320, 1e-9);
  EXPECT_NEAR(a.uv_px(1, 3), 340.1, 1e-9);
  EXPECT_EQ(a.detection_idx, 1);
  EXPECT_TRUE(a.in_image);
  const std::vector<Status> expected = {Status::kMeasured, Status::kMeasured, Status::kNotDetected,
                                        Status::kNotDetected, Status::kMissing3D};
  EXPECT_EQ(a.status, expected);
  EXPECT_NEAR(a.error_px[0], 5.0, 1e-9);
  EXPECT_NEAR(a.error_px[1], 0.0, 1e-9);
  for (int j = 2; j < 5; ++j) EXPECT_TRUE(std::isnan(a.error_px[j])) << j;
  EXPECT_EQ(a.num_measured, 2);
  EXPECT_NEAR(a.mean_error_px, 2.5, 1e-9);

  const ReprojectedPerson& b = view.predictions[1];
  EXPECT_EQ(b.track_id, 8);
  EXPECT_EQ(b.detection_idx, -1);
  EXPECT_FALSE(b.in_image);
  EXPECT_EQ(b.num_measured, 0);
  EXPECT_TRUE(std::isnan(b.mean_error_px));
  for (const Status s : b.status) EXPECT_EQ(s, Status::kBehindCamera);

  EXPECT_EQ(view.prediction_of_detection, (std::vector<int>{-1, 0}));
  EXPECT_EQ(view.gt_of_detection, (std::vector<int>{-1, -1}));
}

TEST(Reprojection, GtWithItsOwnJointsAndVisibilityThreshold) {
  // GT joints in another order and set; the right shoulder's visibility 0.05 is below the
  // metrics' 0.1 (absent), its nose sits 1 px left of the prediction's.
  const JointNames gt_joints = {"shoulder_left", "nose", "shoulder_right"};
  Poses3D gt;
  gt.Clear(3);
  auto g = gt.AddPerson();
  SetJoint(g, 0, 0, 0, 2, 1.0);
  SetJoint(g, 1, 0.1 - 0.002, -0.2, 2, 1.0);  // u = 320 + 1000 * 0.049 * (1 + 0.1 * (0.049^2 + 0.01))
  SetJoint(g, 2, 0.2, 0, 2, 0.05);
  const Poses3D predictions = TestPredictions();
  const std::vector<ViewReprojection> views = ReprojectFrame({TestCamera()}, {TestDetections()}, kDetectionJoints,
                                                             {&predictions, &kPredictionJoints}, {&gt, &gt_joints});
  const ViewReprojection& view = views[0];
  ASSERT_EQ(view.gt.size(), 1u);
  const ReprojectedPerson& p = view.gt[0];
  EXPECT_EQ(p.track_id, -1);
  EXPECT_EQ(p.detection_idx, 1);
  EXPECT_EQ(p.status, (std::vector<Status>{Status::kMeasured, Status::kMeasured, Status::kMissing3D}));
  const double u = 320 + 1000 * 0.049 * (1 + 0.1 * (0.049 * 0.049 + 0.01));
  const double v = 240 - 1000 * 0.1 * (1 + 0.1 * (0.049 * 0.049 + 0.01));
  EXPECT_NEAR(p.uv_px(0, 1), u, 1e-9);
  EXPECT_NEAR(p.uv_px(1, 1), v, 1e-9);
  EXPECT_NEAR(p.error_px[1], std::hypot(373.0625 - u, 143.875 - v), 1e-9);
  EXPECT_NEAR(p.error_px[0], 0.0, 1e-9);
  EXPECT_EQ(view.gt_of_detection, (std::vector<int>{-1, 0}));
  EXPECT_EQ(view.prediction_of_detection, (std::vector<int>{-1, 0}));  // predictions matched independently
}

TEST(Reprojection, OneToOneAndCamerasWithoutDetections) {
  // Two predictions at the same place compete for one detection: the closer one wins. The
  // second camera (shifted 1 m along x) has no detections: everything projected, nothing matched.
  Poses3D predictions;
  predictions.Clear(5);
  const Poses3D base = TestPredictions();
  auto first = predictions.AddPerson(1);
  first = base.Person(0);
  first(0, 0) -= 0.004;  // the nose 2 px further left (u 368.06...): further from the detection
  auto second = predictions.AddPerson(2);
  second = base.Person(0);
  Camera shifted = TestCamera();
  shifted.t << -1, 0, 0;
  const std::vector<ViewReprojection> views = ReprojectFrame({TestCamera(), shifted}, {TestDetections()},
                                                             kDetectionJoints, {&predictions, &kPredictionJoints}, {});
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0].predictions[0].detection_idx, -1);
  EXPECT_EQ(views[0].predictions[1].detection_idx, 1);
  EXPECT_EQ(views[0].prediction_of_detection, (std::vector<int>{-1, 1}));
  EXPECT_TRUE(views[1].prediction_of_detection.empty());
  for (const ReprojectedPerson& p : views[1].predictions) {
    EXPECT_EQ(p.detection_idx, -1);
    EXPECT_EQ(p.status[1], Status::kNotDetected);
    EXPECT_NEAR(p.uv_px(0, 1), 320 - 1000 * 0.5 * (1 + 0.1 * 0.25), 1e-9);  // x/z = -0.5
  }
}

// A view's mean error is over its measured joints, not over its persons: one person with one
// joint 10 px off and one with three joints 2 px off give (10 + 3 x 2) / 4 = 4 px (the mean of
// the persons' means would be 6); joints not measured do not count.
TEST(Reprojection, TheViewsMeanIsOverItsMeasuredJoints) {
  ViewReprojection view;
  const auto person = [](std::vector<double> errors, std::vector<JointReprojection> status) {
    ReprojectedPerson p;
    p.error_px = std::move(errors);
    p.status = std::move(status);
    return p;
  };
  constexpr auto kMeasured = JointReprojection::kMeasured;
  const double nan = std::nan("");
  view.predictions.push_back(person({10, nan}, {kMeasured, JointReprojection::kNotDetected}));
  view.predictions.push_back(person({2, 2, 2}, {kMeasured, kMeasured, kMeasured}));
  const ViewError error = MeanPredictionError(view);
  EXPECT_EQ(error.joints, 4);
  EXPECT_DOUBLE_EQ(error.mean_px, 4.0);
  const ViewError none = MeanPredictionError(ViewReprojection{});
  EXPECT_EQ(none.joints, 0);
  EXPECT_TRUE(std::isnan(none.mean_px));
}

}  // namespace
}  // namespace rpt::engine
