// SPDX-License-Identifier: MIT
// The shared real-world tolerance rules (datasets/input_warnings.h): rotations within 1e-3 of
// orthonormal and scores in (1, 1.5] are corrected and counted per file and kind; anything
// farther is an InputError naming the place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "datasets/input_warnings.h"
#include "tests/datasets/tolerance_test_util.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;
using test::InputErrorOf;

Eigen::Matrix3d SomeRotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

TEST(AcceptRotation, RoundedRotationBecomesTheNearestRotationAndIsCounted) {
  const Eigen::Matrix3d exact = SomeRotation();
  const Eigen::Matrix3d rounded = test::RoundedRotation(exact);
  InputWarnings warnings;
  const Eigen::Matrix3d R = AcceptRotation(rounded, "cal.json", "cal.json: /0/R", &warnings);
  EXPECT_LT(test::OrthonormalityError(R), 1e-12);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_LT((R - exact).cwiseAbs().maxCoeff(), 1e-5);
  test::ExpectOneWarning(warnings, "cal.json", test::kRotationsFixed, 1);
  EXPECT_DOUBLE_EQ(warnings.items()[0].worst, test::OrthonormalityError(rounded));
}

TEST(AcceptRotation, RoundOffIsKeptAsItIsAndNotCounted) {
  const Eigen::Matrix3d exact = SomeRotation();
  ASSERT_LE(test::OrthonormalityError(exact), kRotationRoundOff);
  InputWarnings warnings;
  const Eigen::Matrix3d R = AcceptRotation(exact, "cal.json", "cal.json: /0/R", &warnings);
  EXPECT_EQ(R, exact) << "bit-identical: nothing to correct";
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(AcceptRotation(Eigen::Matrix3d::Identity(), "a", "a", nullptr), Eigen::Matrix3d::Identity());
}

TEST(AcceptRotation, FartherThanTheToleranceIsAnErrorNamingThePlace) {
  InputWarnings warnings;
  EXPECT_THAT(InputErrorOf([&] { AcceptRotation(test::WrongRotation(SomeRotation()), "cal.json", "cal.json: /3/R", &warnings); }),
              HasSubstr("cal.json: /3/R: R is not a rotation (max |R^T R - I| = 0.010025, at most 0.001 is accepted"));
  Eigen::Matrix3d mirror = SomeRotation();
  mirror.row(1) *= -1;
  EXPECT_THAT(InputErrorOf([&] { AcceptRotation(mirror, "cal.json", "cal.json: /3/R", &warnings); }),
              HasSubstr("cal.json: /3/R: R is a reflection (det < 0)"));
  Eigen::Matrix3d nan = SomeRotation();
  nan(2, 1) = std::nan("");
  EXPECT_THAT(InputErrorOf([&] { AcceptRotation(nan, "cal.json", "cal.json: /3/R", &warnings); }),
              HasSubstr("cal.json: /3/R: R is not a rotation (non-finite entries)"));
  // Just inside and just outside the bound (max |R^T R - I| = s^2 - 1).
  EXPECT_NO_THROW(AcceptRotation(std::sqrt(1 + 0.99e-3) * SomeRotation(), "c", "c", &warnings));
  EXPECT_THROW(AcceptRotation(std::sqrt(1 + 1.01e-3) * SomeRotation(), "c", "c", &warnings), InputError);
  EXPECT_EQ(warnings.total(), 1) << "only the accepted one is counted";
}

TEST(AcceptQuaternion, NormalisesAndCountsBeyondRoundOff) {
  InputWarnings warnings;
  const Eigen::Vector4d unit = Eigen::Vector4d(0.5, -0.5, 0.5, 0.5);
  EXPECT_EQ(AcceptQuaternion(unit, "images.txt", "images.txt:4", &warnings), unit);
  EXPECT_TRUE(warnings.empty());
  const Eigen::Vector4d rounded(0.500001, -0.5, 0.499999, 0.500002);  // 6 significant digits
  const Eigen::Vector4d q = AcceptQuaternion(rounded, "images.txt", "images.txt:6", &warnings);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  test::ExpectOneWarning(warnings, "images.txt", test::kQuaternionsFixed, 1);
  EXPECT_THAT(InputErrorOf([&] { AcceptQuaternion(1.01 * unit, "images.txt", "images.txt:8", &warnings); }),
              HasSubstr("images.txt:8: quaternion (0.505, -0.505, 0.505, 0.505) has norm 1.01, expected a unit quaternion"));
}

TEST(AcceptScore, ValuesInRangePassUntouchedAndCostNoMessage) {
  InputWarnings warnings;
  int built = 0;
  const auto where = [&] {
    ++built;
    return std::string("d.json: /frames/0");
  };
  for (double s : {0.0, 0.25, 1.0}) EXPECT_EQ(AcceptScore(s, "d.json", &warnings, where), s);
  EXPECT_EQ(built, 0) << "the place is only built on the slow path";
  EXPECT_TRUE(warnings.empty());
}

TEST(AcceptScore, SlightOvershootIsClampedAndCounted) {
  InputWarnings warnings;
  const auto where = [] { return std::string("d.json: somewhere"); };
  EXPECT_EQ(AcceptScore(1.008, "d.json", &warnings, where), 1.0);
  EXPECT_EQ(AcceptScore(1.018, "d.json", &warnings, where), 1.0);
  EXPECT_EQ(AcceptScore(1.5, "d.json", &warnings, where), 1.0) << "the bound is inclusive";
  test::ExpectOneWarning(warnings, "d.json", test::kScoresClamped, 3);
  EXPECT_DOUBLE_EQ(warnings.items()[0].worst, 1.5);
  EXPECT_EQ(AcceptScore(1.2, "d.json", nullptr, where), 1.0) << "no sink: still clamped";
}

TEST(AcceptScore, NegativeNanAndLargeValuesAreErrorsNamingThePlace) {
  InputWarnings warnings;
  const auto where = [] { return std::string("d.json: /frames/2/views/0/poses/1/4"); };
  EXPECT_THAT(InputErrorOf([&] { AcceptScore(1.6, "d.json", &warnings, where); }),
              HasSubstr("d.json: /frames/2/views/0/poses/1/4: score 1.6 outside [0, 1] (values up to 1.5 are clamped to 1)"));
  EXPECT_THAT(InputErrorOf([&] { AcceptScore(-0.1, "d.json", &warnings, where); }),
              HasSubstr("d.json: /frames/2/views/0/poses/1/4: score -0.1 outside [0, 1]"));
  EXPECT_THAT(InputErrorOf([&] { AcceptScore(std::nan(""), "d.json", &warnings, where); }),
              HasSubstr("d.json: /frames/2/views/0/poses/1/4: score nan outside [0, 1]"));
  EXPECT_THROW(AcceptScore(std::numeric_limits<double>::infinity(), "d.json", &warnings, where), InputError);
  EXPECT_TRUE(warnings.empty());
}

TEST(InputWarnings, AggregatesPerSourceAndKindAndFormatsOneLine) {
  InputWarnings warnings;
  warnings.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 1.2e-6);
  warnings.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 0.4e-6);
  warnings.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 0.9e-6);
  warnings.Add("a.json", "scores above 1 clamped to 1", "largest", 1.018);
  warnings.Add("b.json", "rotations re-orthonormalised", "max |R^T R - I|", 2e-6);
  ASSERT_EQ(warnings.items().size(), 3u);
  EXPECT_EQ(warnings.total(), 5);
  EXPECT_EQ(warnings.items()[0].Line(), "a.json: 3 rotations re-orthonormalised (max |R^T R - I| = 1.2e-06)");
  EXPECT_EQ(warnings.items()[1].Line(), "a.json: 1 scores above 1 clamped to 1 (largest = 1.018)");
  EXPECT_EQ(warnings.items()[2].Line(), "b.json: 1 rotations re-orthonormalised (max |R^T R - I| = 2e-06)");
  const InputWarning bare{"c.json", "things fixed", "", 2, 0};
  EXPECT_EQ(bare.Line(), "c.json: 2 things fixed");
}

TEST(InputWarnings, MergeAddsCountsAndMergeRepeatedKeepsTheLarger) {
  InputWarnings first, second;
  first.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 1e-6);
  first.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 1e-6);
  second.Add("a.json", "rotations re-orthonormalised", "max |R^T R - I|", 3e-6);
  second.Add("p.pkl", "scores above 1 clamped to 1", "largest", 1.1);

  InputWarnings sum = first;
  sum.Merge(second);  // other values of the same file: counts add
  ASSERT_EQ(sum.items().size(), 2u);
  EXPECT_EQ(sum.items()[0].count, 3);
  EXPECT_DOUBLE_EQ(sum.items()[0].worst, 3e-6);
  EXPECT_EQ(sum.items()[1].Line(), "p.pkl: 1 scores above 1 clamped to 1 (largest = 1.1)");

  InputWarnings repeated = first;
  repeated.MergeRepeated(first);  // the same file read again: still 2, not 4
  repeated.MergeRepeated(second);
  ASSERT_EQ(repeated.items().size(), 2u);
  EXPECT_EQ(repeated.items()[0].count, 2);
  EXPECT_DOUBLE_EQ(repeated.items()[0].worst, 3e-6);
  EXPECT_EQ(repeated.items()[1].count, 1);
}

}  // namespace
}  // namespace rpt

namespace rpt {
namespace {

TEST(InputWarnings, UnusedInputIsCountedInBulkAndKeptApartFromCorrections) {
  InputWarnings warnings;
  warnings.Add("cal.json", "rotations re-orthonormalised", "max |R^T R - I|", 1e-6);
  warnings.AddUnused("dets", "frames ignored", 3);
  warnings.AddUnused("dets", "frames ignored", 2);
  warnings.AddUnused("dets", "files ignored", 0);  // nothing to report: no line
  ASSERT_EQ(warnings.items().size(), 2u);
  EXPECT_EQ(warnings.items()[1].Line(), "dets: 5 frames ignored");
  const std::vector<InputWarning> unused = warnings.Unused();
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_EQ(unused[0].what, "frames ignored");
  EXPECT_EQ(warnings.items()[0].kind, InputWarningKind::kCorrected);

  InputWarnings again;
  again.AddUnused("dets", "frames ignored", 4);
  warnings.MergeRepeated(again);
  EXPECT_EQ(warnings.items()[1].count, 5);
  warnings.Merge(again);
  EXPECT_EQ(warnings.items()[1].count, 9);
  EXPECT_EQ(warnings.items()[1].kind, InputWarningKind::kUnused);
}

}  // namespace
}  // namespace rpt
