// SPDX-License-Identifier: MIT
// The body frame (core/body_frame.h) and the joint-definition offsets (core/joint_offsets.h):
// hand-computed frames and moves, the degenerate cases, and the fit recovering offsets planted in
// the body frame of noise-free persons.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/body_frame.h"
#include "core/joint_offsets.h"
#include "core/joints.h"

namespace rpt {
namespace {

// nose, shoulder_left, shoulder_right, hip_left, hip_right: a person facing +y (its right is +x).
const JointNames kJoints = {"nose", "shoulder_left", "shoulder_right", "hip_left", "hip_right"};

Eigen::Matrix4Xd UprightPerson() {
  Eigen::Matrix4Xd p(4, 5);
  p.col(0) << 0.0, 0.1, 1.7, 1.0;   // nose
  p.col(1) << -0.2, 0.0, 1.5, 1.0;  // shoulder_left
  p.col(2) << 0.2, 0.0, 1.5, 1.0;   // shoulder_right
  p.col(3) << -0.1, 0.0, 1.0, 1.0;  // hip_left
  p.col(4) << 0.1, 0.0, 1.0, 1.0;   // hip_right
  return p;
}

// The person turned by `rotation` about the origin and moved by `shift`.
Eigen::Matrix4Xd Moved(const Eigen::Matrix4Xd& person, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift) {
  Eigen::Matrix4Xd out = person;
  for (int j = 0; j < person.cols(); ++j) out.col(j).head<3>() = rotation * person.col(j).head<3>() + shift;
  return out;
}

TEST(BodyFrameTest, UprightPersonFacingPlusYHasTheWorldAxes) {
  const BodyFrameJoints joints = BodyFrameJoints::Find(kJoints);
  ASSERT_TRUE(joints.complete());
  const auto frame = MakeBodyFrame(UprightPerson(), joints);
  ASSERT_TRUE(frame.has_value());
  EXPECT_TRUE(frame->origin.isApprox(Eigen::Vector3d(0, 0, 1.0), 1e-15));
  EXPECT_TRUE(frame->axes.isApprox(Eigen::Matrix3d::Identity(), 1e-15)) << frame->axes;
}

TEST(BodyFrameTest, TurnsWithThePersonAndIsRightHanded) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1.0).normalized()).toRotationMatrix();
  const auto frame = MakeBodyFrame(Moved(UprightPerson(), turn, Eigen::Vector3d(3, -2, 0.5)), BodyFrameJoints::Find(kJoints));
  ASSERT_TRUE(frame.has_value());
  EXPECT_LT((frame->axes - turn).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(frame->axes.determinant(), 1.0, 1e-14);
  EXPECT_TRUE(frame->origin.isApprox(turn * Eigen::Vector3d(0, 0, 1.0) + Eigen::Vector3d(3, -2, 0.5), 1e-14));
}

TEST(BodyFrameTest, SpineIsMadeOrthogonalToTheLateralAxis) {
  // Shoulders shifted 0.1 m to the right: the spine leans, z stays orthogonal to x.
  Eigen::Matrix4Xd p = UprightPerson();
  p(0, 1) += 0.1;
  p(0, 2) += 0.1;
  const auto frame = MakeBodyFrame(p, BodyFrameJoints::Find(kJoints));
  ASSERT_TRUE(frame.has_value());
  EXPECT_TRUE(frame->axes.isApprox(Eigen::Matrix3d::Identity(), 1e-15)) << frame->axes;
}

TEST(BodyFrameTest, DegenerateBodiesHaveNoFrame) {
  const BodyFrameJoints joints = BodyFrameJoints::Find(kJoints);
  Eigen::Matrix4Xd missing = UprightPerson();
  missing(3, 2) = 0.0;  // shoulder_right missing
  EXPECT_FALSE(MakeBodyFrame(missing, joints).has_value());
  Eigen::Matrix4Xd not_finite = UprightPerson();
  not_finite(1, 3) = std::nan("");
  EXPECT_FALSE(MakeBodyFrame(not_finite, joints).has_value());
  Eigen::Matrix4Xd narrow = UprightPerson();  // hip + shoulder width 0.098 m < 0.1
  narrow.block(0, 1, 1, 4) << -0.025, 0.025, -0.0245, 0.0245;
  EXPECT_FALSE(MakeBodyFrame(narrow, joints).has_value());
  narrow.block(0, 1, 1, 4) << -0.025, 0.025, -0.025, 0.025;  // exactly 0.1: a frame
  EXPECT_TRUE(MakeBodyFrame(narrow, joints).has_value());
  Eigen::Matrix4Xd short_spine = UprightPerson();  // shoulders 0.09 m above the hips
  short_spine(2, 1) = short_spine(2, 2) = 1.09;
  EXPECT_FALSE(MakeBodyFrame(short_spine, joints).has_value());
  Eigen::Matrix4Xd lying = UprightPerson();  // spine along the lateral axis (shoulders to the right)
  lying.col(1).head<3>() << 0.4, 0.0, 1.0;
  lying.col(2).head<3>() << 0.8, 0.0, 1.0;
  EXPECT_FALSE(MakeBodyFrame(lying, joints).has_value());
  EXPECT_FALSE(MakeBodyFrame(UprightPerson(), BodyFrameJoints::Find({"nose", "hip_left", "hip_right"})).has_value());
}

TEST(JointOffsetsTest, ApplyMovesEachPresentJointByItsOffsetInTheBodyFrame) {
  // The person turned 90 degrees about z: right = +y, forward = -x, up = +z.
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Poses3D persons;
  persons.Clear(5);
  persons.AddPerson() = Moved(UprightPerson(), quarter, Eigen::Vector3d::Zero());
  persons.Person(0)(3, 0) = 0.0;  // nose missing: not moved
  persons.AddPerson() = UprightPerson();
  persons.Person(1)(3, 3) = 0.0;  // hip_left missing: no body frame, nothing moves
  const Poses3D before = persons;
  std::vector<Eigen::Vector3d> offsets(5, Eigen::Vector3d::Zero());
  offsets[0] << 0.5, 0.5, 0.5;
  offsets[3] << 0.01, 0.02, 0.03;   // hip_left: 1 cm right, 2 cm forward, 3 cm up
  offsets[4] << -0.04, 0.0, 0.0;    // hip_right: 4 cm left
  EXPECT_EQ(ApplyJointOffsets(offsets, BodyFrameJoints::Find(kJoints), &persons), 1);
  // Hand-computed: right (+0.01) is +y, forward (+0.02) is -x, up (+0.03) is +z.
  const Eigen::Matrix4Xd expected_before = Moved(UprightPerson(), quarter, Eigen::Vector3d::Zero());
  EXPECT_NEAR(persons.Person(0)(0, 3), expected_before(0, 3) - 0.02, 1e-15);
  EXPECT_NEAR(persons.Person(0)(1, 3), expected_before(1, 3) + 0.01, 1e-15);
  EXPECT_NEAR(persons.Person(0)(2, 3), expected_before(2, 3) + 0.03, 1e-15);
  EXPECT_NEAR(persons.Person(0)(0, 4), expected_before(0, 4), 1e-15);
  EXPECT_NEAR(persons.Person(0)(1, 4), expected_before(1, 4) - 0.04, 1e-15);
  EXPECT_NEAR(persons.Person(0)(2, 4), expected_before(2, 4), 1e-15);
  EXPECT_EQ(persons.Person(0).col(0), before.Person(0).col(0));  // missing joint
  EXPECT_EQ(persons.Person(0).rightCols(2).row(3), before.Person(0).rightCols(2).row(3));  // scores kept
  EXPECT_EQ(persons.Person(1), before.Person(1));  // no body frame
}

// Noise-free persons (random poses, sizes, turns and places) with GT = prediction + R_body * d_j:
// the fit gives d_j back, by the mean and by the median.
TEST(JointOffsetsTest, FitRecoversOffsetsPlantedInTheBodyFrame) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const BodyFrameJoints joints = BodyFrameJoints::Find(kJoints);
  std::vector<Eigen::Vector3d> planted = {{0.0, 0.05, -0.02}, {0.01, -0.03, 0.0}, {-0.01, -0.03, 0.0},
                                          {0.06, 0.02, -0.09}, {-0.06, 0.02, -0.09}};
  JointOffsetFit fit(5), second_half(5);
  for (int n = 0; n < 200; ++n) {
    Eigen::Matrix4Xd person = UprightPerson();
    person.topRows<3>() += 0.05 * Eigen::Matrix3Xd::NullaryExpr(3, 5, [&] { return unit(random); });
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(std::numbers::pi * unit(random), Eigen::Vector3d(0.1 * unit(random), 0.1 * unit(random), 1).normalized())
            .toRotationMatrix();
    person = Moved(person, turn, Eigen::Vector3d(3 * unit(random), 3 * unit(random), 0));
    const auto frame = MakeBodyFrame(person, joints);
    ASSERT_TRUE(frame.has_value());
    Eigen::Matrix3Xd gt(3, 5);
    for (int j = 0; j < 5; ++j) gt.col(j) = person.col(j).head<3>() + frame->axes * planted[j];
    if (n == 3) gt.col(0).setConstant(std::nan(""));  // a joint without GT: not counted
    ASSERT_TRUE((n < 100 ? fit : second_half).Add(person, gt, joints));
  }
  fit.Merge(second_half);
  for (const OffsetStatistic statistic : {OffsetStatistic::kMean, OffsetStatistic::kMedian}) {
    const JointOffsetFit::Result result = fit.Finish(statistic, 20);
    for (int j = 0; j < 5; ++j) {
      EXPECT_LT((result.offset_m[j] - planted[j]).cwiseAbs().maxCoeff(), 1e-9) << kJoints[j];
      EXPECT_LT(result.spread_m[j], 1e-9);
    }
    EXPECT_EQ(result.samples, (std::vector<long>{199, 200, 200, 200, 200}));
  }
  // Fewer residuals than min_samples: no offset.
  const JointOffsetFit::Result strict = fit.Finish(OffsetStatistic::kMean, 200);
  EXPECT_EQ(strict.offset_m[0], Eigen::Vector3d::Zero());
  EXPECT_LT((strict.offset_m[1] - planted[1]).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(JointOffsetsTest, MedianIgnoresAMinorityOfMismatchedPersonsAndMeanDoesNot) {
  const BodyFrameJoints joints = BodyFrameJoints::Find(kJoints);
  JointOffsetFit fit(5);
  const Eigen::Matrix4Xd person = UprightPerson();  // body frame = world axes, origin (0, 0, 1)
  for (int n = 0; n < 7; ++n) {
    Eigen::Matrix3Xd gt = person.topRows<3>();
    gt(2, 3) += n < 5 ? 0.02 : 0.5;  // hip_left 2 cm higher; two persons 50 cm (mismatched)
    EXPECT_TRUE(fit.Add(person, gt, joints));
  }
  Eigen::Matrix4Xd no_frame = person;
  no_frame(3, 1) = 0.0;
  EXPECT_FALSE(fit.Add(no_frame, person.topRows<3>(), joints));
  const JointOffsetFit::Result median = fit.Finish(OffsetStatistic::kMedian, 1);
  EXPECT_LT((median.offset_m[3] - Eigen::Vector3d(0, 0, 0.02)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(median.spread_m[3], 0.0, 1e-15);
  const JointOffsetFit::Result mean = fit.Finish(OffsetStatistic::kMean, 1);
  EXPECT_NEAR(mean.offset_m[3].z(), (5 * 0.02 + 2 * 0.5) / 7, 1e-15);
  EXPECT_EQ(mean.samples[3], 7);
  // Median of an even count: the mean of the middle two.
  JointOffsetFit even(5);
  for (const double dz : {0.01, 0.04, 0.02, 0.10}) {
    Eigen::Matrix3Xd gt = person.topRows<3>();
    gt(2, 3) += dz;
    even.Add(person, gt, joints);
  }
  EXPECT_NEAR(even.Finish(OffsetStatistic::kMedian, 1).offset_m[3].z(), 0.03, 1e-15);
}

}  // namespace
}  // namespace rpt
