// SPDX-License-Identifier: MIT
#include "metrics/accumulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.h"
#include "tests/metrics/metrics_test_util.h"

namespace rpt::metrics {
namespace {

using test::AddPerson;
using test::CocoBodyTemplate;
using test::EmptyPoses;
using test::Reorder;
using test::Shifted;

constexpr double kTol = 1e-6;

// Predictions use the COCO-17 names in reverse order, so every test also checks mapping by name.
const JointNames& PredNames() {
  static const JointNames names(CocoBodyJoints().rbegin(), CocoBodyJoints().rend());
  return names;
}

// A COCO-17 person (metres) standing at x = x_m.
Eigen::Matrix3Xd PersonAt(double x_m) { return Shifted(CocoBodyTemplate(), {x_m, 0.0, 0.0}); }

// One frame under construction: GT in CocoBodyJoints() order, predictions in PredNames() order.
struct Frame {
  Poses3D gt = EmptyPoses(17);
  Poses3D pred = EmptyPoses(17);
  std::vector<double> scores;  // optional person scores

  int Gt(const Eigen::Matrix3Xd& xyz_m, double score = 1.0) { return AddPerson(&gt, xyz_m, score); }
  // Adds a prediction given in COCO order; returns its index.
  int Pred(const Eigen::Matrix3Xd& xyz_m, double joint_score = 1.0) {
    return AddPerson(&pred, Reorder(xyz_m, CocoBodyJoints(), PredNames()), joint_score);
  }
  // Sets the score of COCO joint `name` of GT person g / prediction p.
  void GtScore(int g, const std::string& name, double score) { gt.Person(g)(3, FindJoint(CocoBodyJoints(), name)) = score; }
  void PredScore(int p, const std::string& name, double score) { pred.Person(p)(3, FindJoint(PredNames(), name)) = score; }
  void AddTo(MetricsAccumulator* accumulator, const std::string& id) const {
    accumulator->Add(id, gt, CocoBodyJoints(), pred, PredNames(), scores);
  }
};

MetricsResult Evaluate(const std::vector<Frame>& frames, const EvalOptions& options = {}) {
  MetricsAccumulator accumulator(options);
  for (size_t f = 0; f < frames.size(); ++f) frames[f].AddTo(&accumulator, "frame_" + std::to_string(f));
  return accumulator.Finalize();
}

const JointResult& JointRow(const MetricsResult& result, const std::string& name) {
  for (const JointResult& joint : result.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint row " + name);
}
const PcpPartResult& PartRow(const MetricsResult& result, const std::string& name) {
  for (const PcpPartResult& part : result.pcp_parts) {
    if (part.name == name) return part;
  }
  throw std::runtime_error("no part row " + name);
}

TEST(MetricsAccumulator, PerfectPredictionsScoreFullMarks) {
  std::vector<Frame> frames(2);
  for (Frame& frame : frames) {
    frame.Gt(PersonAt(0.0));
    frame.Gt(PersonAt(3.0));
    frame.Pred(PersonAt(3.0));  // order of predictions does not matter
    frame.Pred(PersonAt(0.0));
  }
  const MetricsResult r = Evaluate(frames);
  EXPECT_NEAR(r.pcp, 100.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0, kTol);
  EXPECT_NEAR(r.pck_500, 100.0, kTol);
  EXPECT_NEAR(r.recall_100, 100.0, kTol);
  EXPECT_NEAR(r.recall_500, 100.0, kTol);
  EXPECT_NEAR(r.invalid, 0.0, kTol);
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);
  EXPECT_NEAR(r.f1, 100.0, kTol);
  for (const double ap : r.ap) EXPECT_NEAR(ap, 100.0, kTol);
  EXPECT_EQ(r.num_frames, 2);
  EXPECT_EQ(r.num_frames_with_gt, 2);
  EXPECT_EQ(r.num_gt_persons, 4);
  EXPECT_EQ(r.num_predictions, 4);
  EXPECT_EQ(r.num_matches, 4);
  ASSERT_EQ(r.joints.size(), 13u);
  EXPECT_EQ(r.joints[0].name, "nose");
  for (const JointResult& joint : r.joints) {
    EXPECT_NEAR(joint.mean_error_mm, 0.0, kTol) << joint.name;
    EXPECT_NEAR(joint.pck_100, 100.0, kTol) << joint.name;
    EXPECT_EQ(joint.count, 4) << joint.name;
  }
  ASSERT_EQ(r.pcp_parts.size(), 10u);
  EXPECT_EQ(PartRow(r, "head").total, 4);
  ASSERT_EQ(r.wholebody.size(), 4u);
  EXPECT_NEAR(r.wholebody[0].mpjpe_mm, 0.0, kTol);  // All: the 17 body joints present
  EXPECT_EQ(r.wholebody[0].num_joints, 17);
  EXPECT_EQ(r.wholebody[2].num_joints, 0);  // no face joints in a COCO-17 layout
  EXPECT_TRUE(std::isnan(r.wholebody[2].mpjpe_mm));
  EXPECT_FALSE(r.legacy_pcp.has_value());
}

TEST(MetricsAccumulator, Shift50mmOnEveryJoint) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Pred(Shifted(PersonAt(0.0), {0.03, 0.0, 0.04}));  // |(30, 0, 40)| = 50 mm
  const MetricsResult r = Evaluate({frame});
  EXPECT_NEAR(r.mpjpe_mm, 50.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0, kTol);
  EXPECT_NEAR(r.recall_100, 100.0, kTol);
  EXPECT_NEAR(r.recall_500, 100.0, kTol);
  EXPECT_NEAR(r.pcp, 100.0, kTol);  // 50 mm <= half of the shortest part (head, 224 mm)
  EXPECT_NEAR(r.ap[0], 0.0, kTol);    // AP@25
  EXPECT_NEAR(r.ap[2], 100.0, kTol);  // AP@75
  EXPECT_NEAR(JointRow(r, "knee_left").mean_error_mm, 50.0, kTol);
}

TEST(MetricsAccumulator, Shift150mmFailsRecall100ButPassesRecall500) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Pred(Shifted(PersonAt(0.0), {0.09, 0.0, 0.12}));  // 150 mm
  const MetricsResult r = Evaluate({frame});
  EXPECT_NEAR(r.mpjpe_mm, 150.0, kTol);
  EXPECT_NEAR(r.recall_100, 0.0, kTol);
  EXPECT_NEAR(r.recall_500, 100.0, kTol);
  EXPECT_NEAR(r.pck_100, 0.0, kTol);
  EXPECT_NEAR(r.pck_500, 100.0, kTol);
  EXPECT_NEAR(r.invalid, 0.0, kTol);
  EXPECT_NEAR(r.f1, 100.0, kTol);
}

// Every gate with a prediction just inside and just outside it. A shift of d mm on every joint makes
// every joint's error, the MPJPE and each part's mean endpoint error d. The parts' half lengths of
// CocoBodyTemplate() (PCP: correct when the mean endpoint error <= half the GT part's length), mm:
// head (mid-shoulder to nose: |(0, 0.10, 0.20)| = 223.6) 111.8, lower arms (|(0.02, 0.05, 0.25)| =
// 255.7) 127.9, lower legs 210.3, torso 225.0, upper legs 225.3, upper arms 150.3.
TEST(MetricsAccumulator, EveryGateJustInsideAndJustOutside) {
  struct Case {
    double shift_mm;
    double recall_100, recall_500, pck_100, pck_500, invalid, f1, pcp;
  };
  const Case cases[] = {
      {99, 100, 100, 100, 100, 0, 100, 100},  // inside the 100 mm gates
      {101, 0, 100, 0, 100, 0, 100, 100},     // outside them
      {111, 0, 100, 0, 100, 0, 100, 100},     // head still correct (111 <= 111.8)
      {112, 0, 100, 0, 100, 0, 100, 90},      // head wrong: 9 of 10 parts
      {127, 0, 100, 0, 100, 0, 100, 90},      // lower arms still correct (127 <= 127.9)
      {128, 0, 100, 0, 100, 0, 100, 70},      // head and both lower arms wrong
      {499, 0, 100, 0, 100, 0, 100, 0},       // inside the 500 mm gates (every part wrong)
      {501, 0, 0, 0, 0, 100, 0, 0},           // outside: a false positive and a miss
  };
  for (const Case& c : cases) {
    Frame frame;
    frame.Gt(PersonAt(0.0));
    frame.Pred(Shifted(PersonAt(0.0), {0.0006 * c.shift_mm, 0.0, 0.0008 * c.shift_mm}));  // |(0.6, 0, 0.8)| d
    const MetricsResult r = Evaluate({frame});
    const std::string at = "shift " + std::to_string(c.shift_mm) + " mm";
    EXPECT_NEAR(r.recall_100, c.recall_100, kTol) << at;
    EXPECT_NEAR(r.recall_500, c.recall_500, kTol) << at;
    EXPECT_NEAR(r.pck_100, c.pck_100, kTol) << at;
    EXPECT_NEAR(r.pck_500, c.pck_500, kTol) << at;
    EXPECT_NEAR(r.invalid, c.invalid, kTol) << at;
    EXPECT_NEAR(r.f1, c.f1, kTol) << at;
    EXPECT_NEAR(r.pcp, c.pcp, kTol) << at;
    if (c.shift_mm < 500) {
      EXPECT_NEAR(r.mpjpe_mm, c.shift_mm, kTol) << at;
    }
  }
}

TEST(MetricsAccumulator, MissedPersonAndPckDenominatorSwitch) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Gt(PersonAt(3.0));  // never predicted
  frame.Pred(PersonAt(0.0));
  const MetricsResult all_gt = Evaluate({frame});
  EXPECT_NEAR(all_gt.recall_500, 50.0, kTol);
  EXPECT_NEAR(all_gt.recall_100, 50.0, kTol);
  EXPECT_NEAR(all_gt.pck_100, 50.0, kTol);  // 13 of 26 GT joints
  EXPECT_NEAR(all_gt.pck_500, 50.0, kTol);
  EXPECT_NEAR(all_gt.pcp, 50.0, kTol);
  EXPECT_NEAR(all_gt.invalid, 0.0, kTol);
  EXPECT_NEAR(all_gt.mpjpe_mm, 0.0, kTol);
  EXPECT_NEAR(all_gt.f1, 200.0 / 3.0, kTol);  // 2 TP / (2 TP + FP + FN) = 2 / 3
  EXPECT_NEAR(all_gt.ap[0], 50.0, kTol);      // recall stops at 1/2 with precision 1
  EXPECT_EQ(JointRow(all_gt, "nose").num_gt, 2);
  EXPECT_NEAR(JointRow(all_gt, "nose").pck_100, 50.0, kTol);

  EvalOptions options;
  options.pck_denominator = PckDenominator::kMatchedGt;
  const MetricsResult matched = Evaluate({frame}, options);
  EXPECT_NEAR(matched.pck_100, 100.0, kTol);  // 13 of the 13 joints of the matched person
  EXPECT_NEAR(matched.pck_500, 100.0, kTol);
  EXPECT_EQ(JointRow(matched, "nose").num_gt, 1);
  EXPECT_NEAR(matched.recall_500, 50.0, kTol);  // person-level metrics do not change
}

TEST(MetricsAccumulator, DuplicatePredictionWithLowerScoreIsInvalid) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Pred(Shifted(PersonAt(0.0), {0.0, 0.0, 0.02}), 0.9);  // 20 mm, person score = mean joint score 0.9
  frame.Pred(Shifted(PersonAt(0.0), {0.0, 0.0, 0.01}), 0.5);  // 10 mm but lower score: duplicate
  const MetricsResult r = Evaluate({frame});
  EXPECT_EQ(r.num_matches, 1);
  EXPECT_NEAR(r.invalid, 50.0, kTol);
  EXPECT_NEAR(r.recall_500, 100.0, kTol);
  EXPECT_NEAR(r.mpjpe_mm, 20.0, kTol);  // the highest-scored prediction is the match
  EXPECT_NEAR(r.f1, 200.0 / 3.0, kTol);

  // Explicit person scores override the mean joint score.
  frame.scores = {0.1, 0.9};
  const MetricsResult swapped = Evaluate({frame});
  EXPECT_NEAR(swapped.mpjpe_mm, 10.0, kTol);
  EXPECT_NEAR(swapped.invalid, 50.0, kTol);
}

TEST(MetricsAccumulator, FalsePositiveFarAway) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Pred(PersonAt(0.0));
  frame.Pred(PersonAt(10.0));  // 10 m from the only GT
  const MetricsResult r = Evaluate({frame});
  EXPECT_NEAR(r.invalid, 50.0, kTol);
  EXPECT_NEAR(r.recall_500, 100.0, kTol);
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0, kTol);
  EXPECT_NEAR(r.pcp, 100.0, kTol);
  EXPECT_NEAR(r.f1, 200.0 / 3.0, kTol);
  EXPECT_NEAR(r.ap[0], 100.0, kTol);  // equal scores: the accurate one ranks first
  EXPECT_EQ(r.num_predictions, 2);
}

TEST(MetricsAccumulator, PredictionsInFrameWithoutGtBothSwitchSettings) {
  Frame with_gt;
  with_gt.Gt(PersonAt(0.0));
  with_gt.Pred(PersonAt(0.0));
  Frame without_gt;
  without_gt.Pred(PersonAt(2.0));

  const MetricsResult counted = Evaluate({with_gt, without_gt});
  EXPECT_NEAR(counted.invalid, 50.0, kTol);
  EXPECT_NEAR(counted.f1, 200.0 / 3.0, kTol);
  EXPECT_EQ(counted.num_predictions, 2);
  EXPECT_EQ(counted.num_frames, 2);
  EXPECT_EQ(counted.num_frames_with_gt, 1);
  EXPECT_NEAR(counted.ap[0], 100.0, kTol);  // the FP ranks after the TP (equal score, larger error)

  EvalOptions options;
  options.count_preds_without_gt = false;  // VoxelPose: GT-empty frames are skipped
  const MetricsResult skipped = Evaluate({with_gt, without_gt}, options);
  EXPECT_NEAR(skipped.invalid, 0.0, kTol);
  EXPECT_NEAR(skipped.f1, 100.0, kTol);
  EXPECT_EQ(skipped.num_predictions, 1);
  EXPECT_EQ(skipped.num_predictions_total, 2);
  EXPECT_NEAR(skipped.recall_500, 100.0, kTol);
}

// The counted predictions that are not matches, by cause (InvalidCauses), each at the edges of its
// range: the nearest GT person within the gate but taken by a better-scored prediction (duplicate),
// at the gate to twice the gate from a person another prediction matched (near_matched_gt) or from
// a person nobody matched (near_missed_gt), from twice the gate (far), and no GT to compare with (a
// frame without GT; not counted at all when such frames are skipped). The causes sum to the false
// positives.
TEST(MetricsAccumulator, InvalidPredictionsByCauseAtTheEdgesOfEachRange) {
  // A prediction d mm from a GT person on every joint (|(0.6, 0, 0.8)| d).
  auto at = [](double x_m, double d_mm) { return Shifted(PersonAt(x_m), {0.0006 * d_mm, 0.0, 0.0008 * d_mm}); };
  auto expect_causes = [](const MetricsResult& r, const InvalidCauses& expected, const std::string& what) {
    EXPECT_EQ(r.invalid_causes.duplicate, expected.duplicate) << what;
    EXPECT_EQ(r.invalid_causes.near_matched_gt, expected.near_matched_gt) << what;
    EXPECT_EQ(r.invalid_causes.near_missed_gt, expected.near_missed_gt) << what;
    EXPECT_EQ(r.invalid_causes.far_from_gt, expected.far_from_gt) << what;
    EXPECT_EQ(r.invalid_causes.no_gt, expected.no_gt) << what;
  };
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Gt(PersonAt(10.0));       // nobody predicts it within the gate
  frame.Pred(at(0, 0));           // the match of person 0
  frame.Pred(at(0, 499), 0.5);    // within the gate, lower score: duplicate
  frame.Pred(at(0, 501));         // just outside the gate of a matched person: near_matched_gt
  frame.Pred(at(0, 999));         // near_matched_gt
  frame.Pred(at(0, 1001));        // just outside twice the gate: far
  frame.Pred(PersonAt(5.0));      // 5 m from both: far
  frame.Pred(at(10, 700));        // near the person nobody matched: near_missed_gt
  Frame without_gt;
  without_gt.Pred(PersonAt(0.0));
  const MetricsResult r = Evaluate({frame, without_gt});
  EXPECT_EQ(r.num_matches, 1);
  expect_causes(r, {.duplicate = 1, .near_matched_gt = 2, .near_missed_gt = 1, .far_from_gt = 2, .no_gt = 1},
                "gate 500 mm");
  EXPECT_EQ(r.invalid_causes.Total(), 7);
  EXPECT_NEAR(r.invalid, 100.0 * 7 / 8, kTol);  // the seven causes over the eight counted predictions

  // The ranges follow the gate: at 1000 mm the 700 mm prediction matches person 1, the 501 and
  // 999 mm ones are duplicates of person 0 (greedy matching: one match per GT person), 1001 mm is
  // near person 0 (1000 to 2000 mm), 5 m is far.
  EvalOptions wide;
  wide.match_threshold_mm = 1000;
  const MetricsResult w = Evaluate({frame, without_gt}, wide);
  EXPECT_EQ(w.num_matches, 2);
  expect_causes(w, {.duplicate = 3, .near_matched_gt = 1, .near_missed_gt = 0, .far_from_gt = 1, .no_gt = 1},
                "gate 1000 mm");

  // Frames without GT not counted: neither in Invalid nor among its causes.
  EvalOptions skip;
  skip.count_preds_without_gt = false;
  expect_causes(Evaluate({frame, without_gt}, skip),
                {.duplicate = 1, .near_matched_gt = 2, .near_missed_gt = 1, .far_from_gt = 2, .no_gt = 0},
                "frames without GT skipped");

  // Hungarian matching: the same causes.
  EvalOptions hungarian;
  hungarian.matching = MatchingMode::kHungarian;
  const MetricsResult h = Evaluate({frame, without_gt}, hungarian);
  EXPECT_EQ(h.num_matches, 1);
  expect_causes(h, {.duplicate = 1, .near_matched_gt = 2, .near_missed_gt = 1, .far_from_gt = 2, .no_gt = 1},
                "Hungarian");
}

TEST(MetricsAccumulator, FrameWithoutGtMayOmitJointNames) {
  MetricsAccumulator accumulator;
  Poses3D pred = EmptyPoses(17);
  AddPerson(&pred, PersonAt(0.0));
  accumulator.Add("empty", Poses3D{}, {}, pred, CocoBodyJoints());
  const MetricsResult r = accumulator.Finalize();
  EXPECT_EQ(r.num_gt_persons, 0);
  EXPECT_NEAR(r.invalid, 100.0, kTol);
  EXPECT_TRUE(std::isnan(r.recall_500));  // no GT at all: undefined
}

TEST(MetricsAccumulator, FrameWithGtButNoPredictions) {
  Frame predicted;
  predicted.Gt(PersonAt(0.0));
  predicted.Pred(PersonAt(0.0));
  Frame missed;
  missed.Gt(PersonAt(0.0));
  const MetricsResult r = Evaluate({predicted, missed});
  EXPECT_NEAR(r.recall_500, 50.0, kTol);
  EXPECT_NEAR(r.pck_100, 50.0, kTol);
  EXPECT_NEAR(r.pcp, 50.0, kTol);
  EXPECT_NEAR(r.invalid, 0.0, kTol);
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);
  EXPECT_NEAR(r.f1, 200.0 / 3.0, kTol);
  EXPECT_EQ(r.num_frames_with_gt, 2);
  EXPECT_EQ(r.num_gt_persons, 2);
}

TEST(MetricsAccumulator, MissingGtJointsAreExcluded) {
  Frame frame;
  const int g = frame.Gt(PersonAt(0.0));
  frame.GtScore(g, "nose", 0.1);  // exactly 0.1 is invalid (> 0.1 required)
  frame.GtScore(g, "wrist_left", 0.0);
  frame.GtScore(g, "ankle_right", 0.05);
  // 30 mm everywhere, and 1 m more on the three invalid joints, which must not count.
  Eigen::Matrix3Xd pred = Shifted(PersonAt(0.0), {0.0, 0.03, 0.0});
  for (const char* name : {"nose", "wrist_left", "ankle_right"}) pred(0, FindJoint(CocoBodyJoints(), name)) += 1.0;
  frame.Pred(pred);
  const MetricsResult r = Evaluate({frame});
  EXPECT_NEAR(r.mpjpe_mm, 30.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0, kTol);  // 10 of 10 valid joints
  EXPECT_EQ(JointRow(r, "nose").num_gt, 0);
  EXPECT_EQ(JointRow(r, "nose").count, 0);
  EXPECT_TRUE(std::isnan(JointRow(r, "nose").mean_error_mm));
  EXPECT_EQ(JointRow(r, "elbow_left").count, 1);
  // Parts touching an invalid GT joint are not evaluated; the others are correct.
  EXPECT_EQ(PartRow(r, "head").total, 0);
  EXPECT_EQ(PartRow(r, "lower_arm_left").total, 0);
  EXPECT_EQ(PartRow(r, "lower_leg_right").total, 0);
  EXPECT_EQ(PartRow(r, "torso").total, 1);
  EXPECT_NEAR(r.pcp, 100.0, kTol);
}

TEST(MetricsAccumulator, PersonWithOnlyAFewJointsAndEmptyPersonDropped) {
  Frame frame;
  const int few = frame.Gt(PersonAt(0.0), 0.0);  // all joints invalid ...
  for (const char* name : {"nose", "elbow_left", "wrist_left"}) frame.GtScore(few, name, 1.0);  // ... but three
  frame.Gt(PersonAt(3.0), 0.0);  // no valid joint at all: dropped from GT
  frame.Pred(Shifted(PersonAt(0.0), {0.0, 0.04, 0.0}));  // 40 mm
  const MetricsResult r = Evaluate({frame});
  EXPECT_EQ(r.num_gt_persons, 1);
  EXPECT_EQ(r.num_dropped_gt_persons, 1);
  EXPECT_NEAR(r.mpjpe_mm, 40.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0, kTol);  // 3 of 3
  EXPECT_NEAR(r.recall_100, 100.0, kTol);
  EXPECT_NEAR(r.invalid, 0.0, kTol);
  EXPECT_EQ(PartRow(r, "lower_arm_left").total, 1);  // the only evaluable part
  EXPECT_NEAR(r.pcp, 100.0, kTol);
}

TEST(MetricsAccumulator, MissingPredictedJointIsWrongButExcludedFromMpjpe) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  Eigen::Matrix3Xd pred = Shifted(PersonAt(0.0), {0.0, 0.0, 0.02});  // 20 mm
  pred.col(FindJoint(CocoBodyJoints(), "wrist_right")).setConstant(99.0);  // garbage, score 0 below
  const int p = frame.Pred(pred);
  frame.PredScore(p, "wrist_right", 0.0);
  const MetricsResult r = Evaluate({frame});
  EXPECT_NEAR(r.mpjpe_mm, 20.0, kTol);
  EXPECT_NEAR(r.pck_100, 100.0 * 12.0 / 13.0, kTol);
  EXPECT_NEAR(r.pck_500, 100.0 * 12.0 / 13.0, kTol);
  EXPECT_EQ(r.num_missing_pred_joints, 1);
  EXPECT_NEAR(JointRow(r, "wrist_right").pck_100, 0.0, kTol);
  EXPECT_EQ(JointRow(r, "wrist_right").count, 0);
  EXPECT_EQ(JointRow(r, "wrist_right").num_gt, 1);
  EXPECT_EQ(PartRow(r, "lower_arm_right").correct, 0);
  EXPECT_NEAR(r.pcp, 90.0, kTol);
}

// GT A at x = 0 and B at x = 0.25 m; P1 (score .9) at +0.11 m, P2 (score .8) at -0.04 m.
// Errors: P1-A 110, P1-B 140, P2-A 40, P2-B 290. Both predictions are nearest to A.
Frame CrossingFrame() {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Gt(PersonAt(0.25));
  frame.Pred(PersonAt(0.11), 0.9);
  frame.Pred(PersonAt(-0.04), 0.8);
  return frame;
}

TEST(MetricsAccumulator, GreedyAndHungarianDifferOnCrossingAssignments) {
  // Greedy: P1 -> A (110) is accepted first; P2 is a duplicate of A; B is missed.
  const MetricsResult greedy = Evaluate({CrossingFrame()});
  EXPECT_EQ(greedy.num_matches, 1);
  EXPECT_NEAR(greedy.recall_500, 50.0, kTol);
  EXPECT_NEAR(greedy.invalid, 50.0, kTol);
  EXPECT_NEAR(greedy.mpjpe_mm, 110.0, kTol);
  EXPECT_NEAR(greedy.recall_100, 50.0, kTol);  // at 100 mm, P2 -> A (40) is the TP

  // Hungarian: P1 -> B (140) + P2 -> A (40) = 180 < 110 + 290.
  EvalOptions options;
  options.matching = MatchingMode::kHungarian;
  const MetricsResult hungarian = Evaluate({CrossingFrame()}, options);
  EXPECT_EQ(hungarian.num_matches, 2);
  EXPECT_NEAR(hungarian.recall_500, 100.0, kTol);
  EXPECT_NEAR(hungarian.invalid, 0.0, kTol);
  EXPECT_NEAR(hungarian.mpjpe_mm, 90.0, kTol);
  EXPECT_NEAR(hungarian.recall_100, 50.0, kTol);  // gate 100: only P2 -> A
  EXPECT_NEAR(hungarian.f1, 100.0, kTol);
  // AP always follows the VoxelPose protocol (nearest-GT records), whatever the matching.
  EXPECT_NEAR(hungarian.ap[5], greedy.ap[5], kTol);
}

TEST(MetricsAccumulator, AveragePrecisionTinyCaseByHand) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Gt(PersonAt(3.0));
  frame.Pred(Shifted(PersonAt(0.0), {0.0, 0.02, 0.0}));  // 20 mm from A
  frame.Pred(PersonAt(10.0));                              // far: FP
  frame.Pred(Shifted(PersonAt(3.0), {0.0, 0.06, 0.0}));  // 60 mm from B
  frame.scores = {0.9, 0.8, 0.7};
  const MetricsResult r = Evaluate({frame});
  // t = 25, 50: TP FP FP -> AP = 1/2. t >= 75: TP FP TP -> AP = 1/2 * 1 + 1/2 * 2/3 = 5/6.
  EXPECT_NEAR(r.ap[0], 50.0, kTol);
  EXPECT_NEAR(r.ap[1], 50.0, kTol);
  for (int k = 2; k < 6; ++k) EXPECT_NEAR(r.ap[k], 500.0 / 6.0, kTol) << kApThresholdsMm[k];
}

TEST(MetricsAccumulator, GenericPcpMatchingSwitch) {
  // MPJPE = 7000 / 13 = 538 mm > 500: not a match, but 9 of 10 parts are right.
  Frame frame;
  frame.Gt(PersonAt(0.0));
  Eigen::Matrix3Xd pred = PersonAt(0.0);
  pred(0, 0) += 7.0;  // nose 7 m off
  frame.Pred(pred);
  const MetricsResult nearest = Evaluate({frame});
  EXPECT_EQ(nearest.num_matches, 0);
  EXPECT_NEAR(nearest.pcp, 90.0, kTol);
  EvalOptions options;
  options.pcp_matching = PcpMatching::kMatched;
  EXPECT_NEAR(Evaluate({frame}, options).pcp, 0.0, kTol);
}

TEST(MetricsAccumulator, PelvisAlignmentAffectsOnlyReportedErrors) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  frame.Pred(Shifted(PersonAt(0.0), {0.09, 0.0, 0.12}));  // 150 mm
  Frame no_pelvis;
  const int g = no_pelvis.Gt(PersonAt(0.0));
  no_pelvis.GtScore(g, "hip_left", 0.0);
  no_pelvis.Pred(Shifted(PersonAt(0.0), {0.0, 0.2, 0.0}));
  EvalOptions options;
  options.alignment = Alignment::kPelvis;
  const MetricsResult r = Evaluate({frame, no_pelvis}, options);
  EXPECT_EQ(r.num_matches, 2);
  EXPECT_EQ(r.num_unaligned_matches, 1);
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);  // only the aligned pair
  EXPECT_NEAR(JointRow(r, "nose").mean_error_mm, 0.0, kTol);
  EXPECT_NEAR(r.recall_100, 0.0, kTol);  // matching stays absolute
  EXPECT_NEAR(r.pck_100, 0.0, kTol);
}

TEST(MetricsAccumulator, WholeBodyGroupsOnlyFaceShifted) {
  const JointNames& names = CocoWholeBodyJoints();
  ASSERT_EQ(names.size(), 133u);
  const JointNames reversed(names.rbegin(), names.rend());
  Poses3D gt = EmptyPoses(133), pred = EmptyPoses(133);
  AddPerson(&gt, test::WholeBodyTemplate());
  Eigen::Matrix3Xd shifted = test::WholeBodyTemplate();
  shifted.middleCols(23, 68).row(1).array() += 0.03;  // face 23-90: 30 mm
  AddPerson(&pred, Reorder(shifted, names, reversed));

  MetricsAccumulator accumulator;
  accumulator.Add("wb", gt, names, pred, reversed);
  const MetricsResult r = accumulator.Finalize();
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);  // matching and MPJPE on the 13 body joints
  ASSERT_EQ(r.wholebody.size(), 4u);
  EXPECT_EQ(r.wholebody[0].name, "All");
  EXPECT_NEAR(r.wholebody[0].mpjpe_mm, 30.0 * 68.0 / 133.0, kTol);
  EXPECT_EQ(r.wholebody[0].num_joints, 133);
  EXPECT_EQ(r.wholebody[1].name, "Body");
  EXPECT_NEAR(r.wholebody[1].mpjpe_mm, 0.0, kTol);
  EXPECT_EQ(r.wholebody[1].num_joints, 23);
  EXPECT_EQ(r.wholebody[2].name, "Face");
  EXPECT_NEAR(r.wholebody[2].mpjpe_mm, 30.0, kTol);
  EXPECT_EQ(r.wholebody[2].num_joints, 68);
  EXPECT_EQ(r.wholebody[3].name, "Hands");
  EXPECT_NEAR(r.wholebody[3].mpjpe_mm, 0.0, kTol);
  EXPECT_EQ(r.wholebody[3].num_joints, 42);
  EXPECT_EQ(r.wholebody[2].num_persons, 1);
}

TEST(MetricsAccumulator, UnknownEvaluatedJointThrowsConfigErrorWithItsName) {
  EvalOptions options;
  options.evaluated_joints = {"nose", "tail"};
  Frame frame;
  frame.Gt(PersonAt(0.0));
  MetricsAccumulator accumulator(options);
  try {
    frame.AddTo(&accumulator, "f");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("'tail'"), std::string::npos) << error.what();
  }
  // A prediction joint list lacking an evaluated joint fails too.
  MetricsAccumulator defaults;
  JointNames no_nose(CocoBodyJoints().begin() + 1, CocoBodyJoints().end());
  EXPECT_THROW(defaults.Add("f", frame.gt, CocoBodyJoints(), EmptyPoses(16), no_nose), ConfigError);
}

TEST(MetricsAccumulator, InconsistentInputThrowsInputError) {
  Frame frame;
  frame.Gt(PersonAt(0.0));
  MetricsAccumulator accumulator;
  const JointNames too_few(CocoBodyJoints().begin(), CocoBodyJoints().begin() + 16);
  EXPECT_THROW(accumulator.Add("a", frame.gt, too_few, frame.pred, PredNames()), InputError);
  frame.AddTo(&accumulator, "b");
  EXPECT_THROW(frame.AddTo(&accumulator, "b"), InputError);  // repeated frame id
  const std::vector<double> scores = {1.0};  // but no predictions
  EXPECT_THROW(accumulator.Add("c", frame.gt, CocoBodyJoints(), frame.pred, PredNames(), scores), InputError);
}

TEST(MetricsAccumulator, LegacyShelfPcpThroughTheAccumulator) {
  // GT in Shelf14 names with actor ids as track ids; predictions in COCO-17.
  EvalOptions options;
  options.evaluated_joints = DefaultCoreJoints();  // Shelf14 GT has no nose
  options.legacy_pcp = LegacyPcpLayout::kShelf;
  Poses3D gt = EmptyPoses(14), pred = EmptyPoses(17);
  for (int actor = 0; actor < 2; ++actor) {
    const Eigen::Matrix3Xd coco = PersonAt(2.0 * actor);
    const Shelf14 shelf = CocoToShelf14(1000.0 * coco, LegacyPcpLayout::kShelf) / 1000.0;
    AddPerson(&gt, shelf, 1.0, /*track_id=*/actor);
    AddPerson(&pred, coco);
  }
  MetricsAccumulator accumulator(options);
  accumulator.Add("shelf_300", gt, Shelf14Joints(), pred, CocoBodyJoints());
  const MetricsResult r = accumulator.Finalize();
  ASSERT_TRUE(r.legacy_pcp.has_value());
  ASSERT_EQ(r.legacy_pcp->actors.size(), 2u);
  EXPECT_EQ(r.legacy_pcp->actors[1].actor_id, 1);
  EXPECT_NEAR(r.legacy_pcp->average_pcp, 100.0, kTol);
  EXPECT_NEAR(r.pcp, 100.0, kTol);
  EXPECT_EQ(PartRow(r, "head").total, 0);  // no nose in the evaluated set
  EXPECT_NEAR(r.mpjpe_mm, 0.0, kTol);
}

}  // namespace
}  // namespace rpt::metrics
