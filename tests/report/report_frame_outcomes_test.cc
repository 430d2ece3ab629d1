// SPDX-License-Identifier: MIT
// EvaluateFrameOutcomes: per-frame matches, misses and invalid predictions worked out by hand, and
// per-frame numbers that add up to the run's metrics.
#include "engine/report/report_frame_outcomes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/joints.h"

namespace rpt::cli {
namespace {

// A person standing at (x, y) with every COCO body joint at a fixed offset: GT and predictions
// share the layout, so the MPJPE between two such persons is their distance.
void AddPerson(Poses3D* poses, double x, double y, int track_id = -1) {
  auto person = poses->AddPerson(track_id);
  for (int j = 0; j < poses->num_joints; ++j) person.col(j) << x + 0.01 * j, y, 0.1 * j, 1.0;
}

Sequence OneFrameSequence(const std::vector<std::pair<double, double>>& gt_at) {
  Sequence sequence;
  sequence.name = "hand";
  sequence.gt_joints = CocoBodyJoints();
  sequence.detection_joints = CocoBodyJoints();
  SequenceFrame frame;
  frame.id = "f0";
  frame.gt.Clear(static_cast<int>(CocoBodyJoints().size()));
  for (const auto& [x, y] : gt_at) AddPerson(&frame.gt, x, y);
  sequence.frames.push_back(frame);
  return sequence;
}

TEST(ReportFrameOutcomes, MatchedMissedAndInvalidByHand) {
  // GT at x = 0 and x = 3; one prediction 50 mm from the first GT, one 2 m away from both.
  const std::vector<Sequence> sequences = {OneFrameSequence({{0, 0}, {3, 0}})};
  Poses3D predictions;
  predictions.Clear(static_cast<int>(CocoBodyJoints().size()));
  AddPerson(&predictions, 0.05, 0, 7);
  AddPerson(&predictions, 1.5, 2.0, 8);
  metrics::EvalOptions options;  // greedy matching at 500 mm
  const engine::RunOutcomes out = engine::EvaluateFrameOutcomes(sequences, {{predictions}}, CocoBodyJoints(), options);
  ASSERT_EQ(out.frames.size(), 1u);
  const engine::FrameOutcome& frame = out.frames[0][0];
  EXPECT_EQ(frame.num_gt, 2);
  EXPECT_EQ(frame.num_matched, 1);
  EXPECT_EQ(frame.num_invalid, 1);
  EXPECT_EQ(frame.gt_state, (std::vector<int>{1, 0}));
  EXPECT_EQ(frame.pred_invalid, (std::vector<bool>{false, true}));
  EXPECT_NEAR(frame.mpjpe_mm, 50.0, 1e-6);
  EXPECT_NEAR(frame.pred_error_mm[0], 50.0, 1e-6);
  EXPECT_NEAR(frame.pred_error_mm[1], 1000.0 * std::hypot(1.5, 2.0), 1e-6);  // nearest GT: the first
  // Recall curve: the only match has an error of 50 mm, so recall is 0 below it and 50 % from 60 mm on.
  ASSERT_EQ(out.recall_threshold_mm.size(), 50u);
  EXPECT_EQ(out.recall_threshold_mm.front(), 10.0);
  EXPECT_EQ(out.recall[3], 0.0);   // 40 mm
  EXPECT_EQ(out.recall[5], 50.0);  // 60 mm
  EXPECT_EQ(out.recall.back(), 50.0);
  EXPECT_NEAR(out.metrics.recall_500, 50.0, 1e-9);
}

TEST(ReportFrameOutcomes, GtWithoutValidJointsIsNotEvaluated) {
  std::vector<Sequence> sequences = {OneFrameSequence({{0, 0}, {3, 0}})};
  Poses3D& gt = sequences[0].frames[0].gt;
  for (int j = 0; j < gt.num_joints; ++j) gt.Person(1)(3, j) = 0.0;  // second GT: nothing visible
  Poses3D predictions;
  predictions.Clear(static_cast<int>(CocoBodyJoints().size()));
  const engine::RunOutcomes out = engine::EvaluateFrameOutcomes(sequences, {{predictions}}, CocoBodyJoints(), {});
  const engine::FrameOutcome& frame = out.frames[0][0];
  EXPECT_EQ(frame.gt_state, (std::vector<int>{0, -1}));
  EXPECT_EQ(frame.num_gt, 1);
  EXPECT_TRUE(std::isnan(frame.mpjpe_mm));
}

TEST(ReportFrameOutcomes, FramesAddUpToTheRun) {
  // Three frames with the GT moving and predictions 0, 1 and 2 persons; per-frame counts sum to the run's.
  Sequence sequence = OneFrameSequence({{0, 0}, {2, 0}});
  for (int f = 1; f < 3; ++f) {
    SequenceFrame frame = sequence.frames[0];
    frame.id = f == 1 ? "f1" : "f2";
    sequence.frames.push_back(frame);
  }
  std::vector<Poses3D> predictions(3);
  for (int f = 0; f < 3; ++f) {
    predictions[f].Clear(static_cast<int>(CocoBodyJoints().size()));
    for (int p = 0; p < f; ++p) AddPerson(&predictions[f], 2.0 * p + 0.02 * f, 0.6 * p);
  }
  const engine::RunOutcomes out = engine::EvaluateFrameOutcomes({sequence}, {predictions}, CocoBodyJoints(), {});
  int matched = 0, invalid = 0, gt = 0;
  for (const engine::FrameOutcome& frame : out.frames[0]) {
    matched += frame.num_matched;
    invalid += frame.num_invalid;
    gt += frame.num_gt;
  }
  EXPECT_EQ(gt, out.metrics.num_gt_persons);
  EXPECT_EQ(matched, out.metrics.num_matches);
  EXPECT_NEAR(100.0 * invalid / out.metrics.num_predictions, out.metrics.invalid, 1e-9);
  EXPECT_EQ(out.frames[0][0].num_matched, 0);
  EXPECT_EQ(out.frames[0][2].num_matched, 1);  // the second prediction is 601 mm from its GT: beyond the gate
  EXPECT_EQ(out.frames[0][2].num_invalid, 1);
}

}  // namespace
}  // namespace rpt::cli
