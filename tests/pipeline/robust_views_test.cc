// SPDX-License-Identifier: MIT
// triangulate.robust_views (step 10): a joint that one view gets wrong is re-triangulated from the
// views that agree; where all views agree nothing changes.
#include <gtest/gtest.h>

#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

constexpr int kWristLeft = 9;

// Errors above about 0.2 m at the joint already score below merge.min_joint_score (the frame's
// kernels), so the cases here plant errors of 0.1-0.2 m, which the merge would average in, and
// drop views from 0.05 m.
Poses3D Triangulate(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views, bool robust) {
  TriangulatorOptions options;
  options.triangulate.robust_views = robust;
  options.triangulate.robust_min_m = 0.05;
  options.track.enabled = false;
  options.clip_speed.enabled = false;
  return test::ProcessOneFrame(cameras, views, options);
}

// Three views see the left wrist; one reports it 30 px off (about 0.16 m at the person's 4.3 m).
TEST(RobustViews, JointOneViewGetsWrongIsTriangulatedFromTheAgreeingViews) {
  const auto cameras = test::RingCameras(3);
  const Eigen::Matrix4Xd body = test::StandingPerson(0.2, -0.1, 0.7);
  auto views = test::ProjectPersons(cameras, {body});
  views[1].Person(0)(0, kWristLeft) += 30.0;  // pixels
  const Eigen::Vector3d truth = body.col(kWristLeft).head<3>();

  const Poses3D robust = Triangulate(cameras, views, true);
  ASSERT_EQ(robust.num_persons(), 1);
  EXPECT_LT((robust.Person(0).col(kWristLeft).head<3>() - truth).norm(), 1e-9);
  // The other joints are exact with or without the option.
  const Poses3D plain = Triangulate(cameras, views, false);
  ASSERT_EQ(plain.num_persons(), 1);
  const double plain_error = (plain.Person(0).col(kWristLeft).head<3>() - truth).norm();
  EXPECT_GT(plain_error, 0.02) << "without the option the wrong view is averaged in";
  for (int j = 0; j < 17; ++j) {
    if (j == kWristLeft) continue;
    EXPECT_LT((robust.Person(0).col(j).head<3>() - body.col(j).head<3>()).norm(), 1e-9) << j;
  }
}

// Four views; the wrong one is dropped and the joint is the merge of the three agreeing pairs.
TEST(RobustViews, FourViewsOneWrongRecoversThePoint) {
  const auto cameras = test::RingCameras(4);
  const Eigen::Matrix4Xd body = test::StandingPerson(-0.3, 0.4, 2.0);
  auto views = test::ProjectPersons(cameras, {body});
  views[2].Person(0)(1, kWristLeft) -= 25.0;
  const Eigen::Vector3d truth = body.col(kWristLeft).head<3>();
  const Poses3D robust = Triangulate(cameras, views, true);
  ASSERT_EQ(robust.num_persons(), 1);
  EXPECT_LT((robust.Person(0).col(kWristLeft).head<3>() - truth).norm(), 1e-9);
  const Poses3D plain = Triangulate(cameras, views, false);
  ASSERT_EQ(plain.num_persons(), 1);
  EXPECT_GT((plain.Person(0).col(kWristLeft).head<3>() - truth).norm(), 0.01);
}

// All views agree (small detection noise below robust_min_m): bit for bit the result without it.
TEST(RobustViews, AgreeingViewsGiveTheResultWithoutTheOptionBitForBit) {
  const auto cameras = test::RingCameras(5);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-1, 0.2, 0.5), test::StandingPerson(1, -0.3, 2.5)};
  auto views = test::ProjectPersons(cameras, bodies);
  // Deterministic pixel noise of up to 2 px.
  int k = 0;
  for (Poses2D& view : views)
    for (int p = 0; p < view.num_persons(); ++p)
      for (int j = 0; j < 17; ++j, ++k) {
        view.Person(p)(0, j) += 2.0 * std::sin(1.7 * k);
        view.Person(p)(1, j) += 2.0 * std::cos(2.3 * k);
      }
  const Poses3D robust = Triangulate(cameras, views, true);
  const Poses3D plain = Triangulate(cameras, views, false);
  ASSERT_EQ(robust.num_persons(), 2);
  ASSERT_EQ(plain.num_persons(), 2);
  for (int p = 0; p < 2; ++p) EXPECT_TRUE((robust.Person(p).array() == plain.Person(p).array()).all()) << p;
}

}  // namespace
}  // namespace rpt
