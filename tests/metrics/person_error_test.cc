// SPDX-License-Identifier: MIT
#include "metrics/person_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.h"
#include "tests/metrics/metrics_test_util.h"

namespace rpt::metrics {
namespace {

using test::AddPerson;
using test::CocoBodyTemplate;

TEST(MapJointNames, MapsByNameInWantedOrder) {
  const JointNames available = {"a", "b", "c"};
  EXPECT_EQ(MapJointNames({"c", "a"}, available, "ground-truth"), (std::vector<int>{2, 0}));
  EXPECT_EQ(FindJointNames({"c", "x"}, available), (std::vector<int>{2, -1}));
}

TEST(MapJointNames, UnknownNameThrowsConfigErrorNamingIt) {
  try {
    MapJointNames({"a", "tail"}, {"a", "b"}, "prediction");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("'tail'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("prediction"), std::string::npos) << error.what();
    // It lists what there is and says how to choose (labels converted from MVOR lack its choice).
    EXPECT_NE(std::string(error.what()).find("prediction joints (a, b); choose the joints with --set "
                                             "metrics.evaluated_joints=NAME,NAME,..."),
              std::string::npos)
        << error.what();
  }
}

TEST(JointErrors, InvalidGtIsNaNAndMissingPredictionIsInfinite) {
  Poses3D gt, pred;
  AddPerson(&gt, CocoBodyTemplate());
  AddPerson(&pred, test::Shifted(CocoBodyTemplate(), {0.0, 0.03, 0.04}));  // 50 mm
  gt.Person(0)(3, 1) = 0.1;   // score <= 0.1: invalid
  pred.Person(0)(3, 2) = 0.0;  // missing prediction
  const std::vector<int> idx = {0, 1, 2};
  const EvalPerson g = ExtractPerson(gt, 0, idx, 0.1);
  const EvalPerson p = ExtractPerson(pred, 0, idx, 0.0);
  EXPECT_DOUBLE_EQ(g.xyz_mm(2, 0), 1600.0);  // metres -> mm
  const Eigen::ArrayXd e = JointErrors(g, p);
  EXPECT_NEAR(e(0), 50.0, 1e-9);
  EXPECT_TRUE(std::isnan(e(1)));
  EXPECT_TRUE(std::isinf(e(2)));
  EXPECT_NEAR(PersonMpjpe(g, p), 50.0, 1e-9);  // only joint 0 counts
  EXPECT_NEAR(p.mean_score, 2.0 / 3.0, 1e-12);
}

TEST(PersonMpjpe, NoCommonJointIsInfinite) {
  Poses3D gt, pred;
  AddPerson(&gt, CocoBodyTemplate());
  AddPerson(&pred, CocoBodyTemplate(), 0.0);
  const std::vector<int> idx = {0, 5, 6};
  EXPECT_TRUE(std::isinf(PersonMpjpe(ExtractPerson(gt, 0, idx, 0.1), ExtractPerson(pred, 0, idx, 0.0))));
}

TEST(PelvisMm, MeanOfHipsOrNullopt) {
  Poses3D poses;
  AddPerson(&poses, CocoBodyTemplate());
  const auto pelvis = PelvisMm(poses, 0, 11, 12, 0.1);
  ASSERT_TRUE(pelvis.has_value());
  EXPECT_TRUE(pelvis->isApprox(Eigen::Vector3d(0.0, 0.0, 950.0)));
  poses.Person(0)(3, 12) = 0.0;
  EXPECT_FALSE(PelvisMm(poses, 0, 11, 12, 0.1).has_value());
}

}  // namespace
}  // namespace rpt::metrics
