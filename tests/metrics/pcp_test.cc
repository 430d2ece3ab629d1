// SPDX-License-Identifier: MIT
#include "metrics/pcp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/metrics/metrics_test_util.h"

namespace rpt::metrics {
namespace {

using test::AddPerson;
using test::CocoBodyTemplate;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(IsPartCorrect, NonStrictHalfLengthRule) {
  const Eigen::Vector3d gt_a(0, 0, 0), gt_b(0, 0, 200);  // length 200 -> tolerance 100
  EXPECT_TRUE(IsPartCorrect({100, 0, 0}, {100, 0, 200}, gt_a, gt_b, 0.5));   // mean error 100 <= 100
  EXPECT_FALSE(IsPartCorrect({100, 0, 0}, {101, 0, 200}, gt_a, gt_b, 0.5));  // 100.5 > 100
  EXPECT_TRUE(IsPartCorrect({0, 0, 0}, {199, 0, 200}, gt_a, gt_b, 0.5));     // 99.5: one end may be far
  EXPECT_FALSE(IsPartCorrect({kNaN, 0, 0}, {0, 0, 200}, gt_a, gt_b, 0.5));
}

// The evaluated-13 persons of a COCO pose (metres) with GT validity 0.1 / prediction validity 0.
EvalPerson Gt13(const Poses3D& poses) {
  return ExtractPerson(poses, 0, MapJointNames(EvaluationJoints13(), CocoBodyJoints(), "gt"), 0.1);
}
EvalPerson Pred13(const Poses3D& poses) {
  return ExtractPerson(poses, 0, MapJointNames(EvaluationJoints13(), CocoBodyJoints(), "pred"), 0.0);
}

int PartIndex(const std::string& name) {
  for (size_t k = 0; k < GenericPcpParts().size(); ++k) {
    if (GenericPcpParts()[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

TEST(GenericPcp, TenPartsWithHeadEndingAtTheNose) {
  ASSERT_EQ(GenericPcpParts().size(), 10u);
  const PcpPartSpec& head = GenericPcpParts()[PartIndex("head")];
  EXPECT_EQ(head.a.joint_1, "shoulder_left");
  EXPECT_EQ(head.a.joint_2, "shoulder_right");
  EXPECT_EQ(head.b.joint_1, "nose");
  const GenericPcpLayout layout = MakeGenericPcpLayout(EvaluationJoints13());
  for (const auto& part : layout.parts) EXPECT_TRUE(part.defined);
  // Without a nose the head part cannot be evaluated.
  EXPECT_FALSE(MakeGenericPcpLayout(DefaultCoreJoints()).parts[PartIndex("head")].defined);
}

TEST(GenericPcp, OutcomesPerPart) {
  Poses3D gt, pred;
  AddPerson(&gt, CocoBodyTemplate());
  AddPerson(&pred, CocoBodyTemplate());
  pred.Person(0)(1, 9) += 0.4;  // wrist_left 400 mm off: lower_arm_left wrong (200 > 0.5 * 256)
  pred.Person(0)(3, 0) = 0.0;   // nose missing: head wrong
  gt.Person(0)(3, 13) = 0.05;   // GT knee_left invalid: both left leg parts not evaluated
  const GenericPcpLayout layout = MakeGenericPcpLayout(EvaluationJoints13());
  const EvalPerson g = Gt13(gt);
  const EvalPerson p = Pred13(pred);
  const std::vector<PartOutcome> outcomes = EvaluateGenericPcp(layout, g, &p, 0.5);
  for (size_t k = 0; k < outcomes.size(); ++k) {
    const std::string& name = GenericPcpParts()[k].name;
    PartOutcome expected = PartOutcome::kCorrect;
    if (name == "lower_arm_left" || name == "head") expected = PartOutcome::kWrong;
    if (name == "upper_leg_left" || name == "lower_leg_left") expected = PartOutcome::kNotEvaluated;
    EXPECT_EQ(outcomes[k], expected) << name;
  }
  // No prediction: every evaluable part is wrong.
  const std::vector<PartOutcome> missed = EvaluateGenericPcp(layout, g, nullptr, 0.5);
  EXPECT_EQ(missed[PartIndex("torso")], PartOutcome::kWrong);
  EXPECT_EQ(missed[PartIndex("upper_leg_left")], PartOutcome::kNotEvaluated);
}

// COCO-17 in mm with a simple head: nose (0, 100, 1600), ears (+-80, 0, 1620), shoulders (+-200, 0, 1400).
Coco17 HandCoco() {
  Coco17 coco = 1000.0 * CocoBodyTemplate();
  coco.col(0) << 0, 100, 1600;
  coco.col(3) << 80, 0, 1620;
  coco.col(4) << -80, 0, 1620;
  coco.col(5) << 200, 0, 1400;
  coco.col(6) << -200, 0, 1400;
  return coco;
}

// Shelf14 GT equal to HandCoco() converted by hand with the given head points.
Shelf14 HandShelf(const Eigen::Vector3d& head_bottom, const Eigen::Vector3d& head_top) {
  const Coco17 coco = HandCoco();
  const int coco_for_shelf[12] = {16, 14, 12, 11, 13, 15, 10, 8, 6, 5, 7, 9};
  Shelf14 shelf;
  for (int j = 0; j < 12; ++j) shelf.col(j) = coco.col(coco_for_shelf[j]);
  shelf.col(12) = head_bottom;
  shelf.col(13) = head_top;
  return shelf;
}

// By hand: mid_sho = (0, 0, 1400), head_center = mid-ears = (0, 0, 1620),
// hb = (mid_sho + head_center) / 2 = (0, 0, 1510), ht = hb + 2 (head_center - hb) = (0, 0, 1730).
const Eigen::Vector3d kCampusBottom(0, 0, 1510), kCampusTop(0, 0, 1730);
// Shelf: top = mid_sho + (nose - mid_sho) .* (.75, .75, 1.5) = (0, 75, 1400 + 300) = (0, 75, 1700);
// bottom = (mid_sho + nose) / 2 = (0, 50, 1500);
// head_top = .75 (0, 75, 1700) + .25 (0, 0, 1730) = (0, 56.25, 1707.5);
// head_bottom = .75 (0, 50, 1500) + .25 (0, 0, 1510) = (0, 37.5, 1502.5).
const Eigen::Vector3d kShelfBottom(0, 37.5, 1502.5), kShelfTop(0, 56.25, 1707.5);

TEST(CocoToShelf14, ShelfHeadSynthesisByHand) {
  const Shelf14 shelf = CocoToShelf14(HandCoco(), LegacyPcpLayout::kShelf);
  EXPECT_TRUE(shelf.col(12).isApprox(kShelfBottom, 1e-12)) << shelf.col(12).transpose();
  EXPECT_TRUE(shelf.col(13).isApprox(kShelfTop, 1e-12)) << shelf.col(13).transpose();
  EXPECT_TRUE(shelf.isApprox(HandShelf(kShelfBottom, kShelfTop), 1e-12));
  EXPECT_TRUE(shelf.col(0).isApprox(HandCoco().col(16)));  // ankle_right
  EXPECT_TRUE(shelf.col(9).isApprox(HandCoco().col(5)));   // shoulder_left
}

TEST(CocoToShelf14, CampusHeadSynthesisByHand) {
  const Shelf14 shelf = CocoToShelf14(HandCoco(), LegacyPcpLayout::kCampus);
  EXPECT_TRUE(shelf.col(12).isApprox(kCampusBottom, 1e-12)) << shelf.col(12).transpose();
  EXPECT_TRUE(shelf.col(13).isApprox(kCampusTop, 1e-12)) << shelf.col(13).transpose();
}

TEST(CocoToShelf14, MissingEarPropagatesToTheHead) {
  Coco17 coco = HandCoco();
  coco.col(3).setConstant(kNaN);
  const Shelf14 shelf = CocoToShelf14(coco, LegacyPcpLayout::kShelf);
  EXPECT_TRUE(shelf.col(12).hasNaN());
  EXPECT_FALSE(shelf.leftCols(12).hasNaN());
}

// Frame 1: actors 0 and 1 predicted (actor 1 with the right wrist 400 mm off), the 4th actor (id 3)
// far from every prediction. Frame 2: actor 0 present, no prediction at all.
LegacyPcpResult RunShelfScenario(bool skip_frames_without_predictions) {
  EvalOptions options;
  options.legacy_pcp = LegacyPcpLayout::kShelf;
  options.legacy_pcp_skip_empty_frames = skip_frames_without_predictions;
  LegacyPcpEvaluator evaluator(options);

  const Shelf14 actor0 = HandShelf(kShelfBottom, kShelfTop);
  const Eigen::Vector3d offset1(2000, 0, 0), offset3(10000, 0, 0);
  const std::vector<LegacyActor> frame1 = {
      {0, actor0}, {1, actor0.colwise() + offset1}, {3, actor0.colwise() + offset3}};
  Coco17 coco1 = HandCoco().colwise() + offset1;
  coco1(1, 10) += 400.0;  // wrist_right
  const std::vector<Shelf14> preds1 = {CocoToShelf14(HandCoco(), LegacyPcpLayout::kShelf),
                                       CocoToShelf14(coco1, LegacyPcpLayout::kShelf)};
  evaluator.AddFrame(frame1, preds1);
  const std::vector<LegacyActor> frame2 = {{0, actor0}};
  evaluator.AddFrame(frame2, {});
  return evaluator.Finalize();
}

TEST(LegacyPcpEvaluator, ShelfScenarioFramesWithoutPredictionsAreWrong) {
  const LegacyPcpResult result = RunShelfScenario(false);
  ASSERT_EQ(result.actors.size(), 3u);
  EXPECT_EQ(result.actors[0].actor_id, 0);
  EXPECT_EQ(result.actors[0].num_frames, 2);
  EXPECT_NEAR(result.actors[0].pcp, 50.0, 1e-9);  // 10 correct + 10 wrong (empty frame)
  EXPECT_NEAR(result.actors[1].pcp, 90.0, 1e-9);  // right lower arm wrong
  EXPECT_NEAR(result.actors[1].group_pcp[3], 50.0, 1e-9);   // Lower arms: 1 of 2
  EXPECT_NEAR(result.actors[1].group_pcp[0], 100.0, 1e-9);  // Head
  EXPECT_EQ(result.actors[2].actor_id, 3);
  EXPECT_NEAR(result.actors[2].pcp, 0.0, 1e-9);
  EXPECT_NEAR(result.average_pcp, 70.0, 1e-9);  // (50 + 90) / 2: actor 3 is not averaged
  EXPECT_TRUE(result.actors[0].averaged);
  EXPECT_TRUE(result.actors[1].averaged);
  EXPECT_FALSE(result.actors[2].averaged);
  EXPECT_NEAR(result.recall_500, 50.0, 1e-9);   // 2 of 4 actor-frames
  EXPECT_EQ(result.num_frames, 2);
  EXPECT_EQ(result.num_skipped_frames, 0);
}

TEST(LegacyPcpEvaluator, SkipFlagMimicsFasterVoxelPose) {
  const LegacyPcpResult result = RunShelfScenario(true);
  EXPECT_NEAR(result.actors[0].pcp, 100.0, 1e-9);
  EXPECT_EQ(result.actors[0].num_frames, 1);
  EXPECT_NEAR(result.average_pcp, 95.0, 1e-9);
  EXPECT_NEAR(result.recall_500, 200.0 / 3.0, 1e-9);
  EXPECT_EQ(result.num_skipped_frames, 1);
}

}  // namespace
}  // namespace rpt::metrics
