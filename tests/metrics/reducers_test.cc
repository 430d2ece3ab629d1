// SPDX-License-Identifier: MIT
// The metric families folded over hand-made frame records and reduced (no accumulator involved).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "metrics/reducers/reducers.h"

namespace rpt::metrics {
namespace {

// Two frames: the first with two GT persons and two predictions, a 40 mm match and a 300 mm match
// (not one at 100 mm); the second without GT and one prediction. All predictions are counted.
std::vector<FrameRecords> ThreePredictions() {
  auto pair = [](int pred_idx, int gt_idx, double error, double score, std::uint8_t flags, Eigen::ArrayXd joints) {
    PairRecord record;
    record.pred_idx = pred_idx;
    record.gt_idx = gt_idx;
    record.error_mm = error;
    record.score = score;
    record.flags = flags;
    record.report_error_mm = error;
    record.joint_errors = joints;
    record.report_joint_errors = joints;
    return record;
  };
  FrameRecords with_gt;
  EvalPerson person;
  person.xyz_mm.setZero(3, 2);
  person.valid.setConstant(2, true);
  with_gt.gt = {person, person};
  with_gt.kept_gt_idx = {0, 1};
  with_gt.num_predictions = 2;
  with_gt.pairs.push_back(
      pair(0, 0, 40.0, 0.9, kNearest | kMatch | kMatch100 | kMatch500, (Eigen::ArrayXd(2) << 30.0, 50.0).finished()));
  with_gt.pairs.push_back(
      pair(1, 1, 300.0, 0.8, kNearest | kMatch | kMatch500, (Eigen::ArrayXd(2) << 200.0, 400.0).finished()));
  FrameRecords without_gt;
  without_gt.num_predictions = 1;
  without_gt.pairs.push_back(pair(0, -1, INFINITY, 0.7, kNearest, Eigen::ArrayXd()));
  return {with_gt, without_gt};
}

MetricsResult Reduce(const MetricTotals& totals, const EvalOptions& options) {
  MetricsResult result;
  for (const MetricReducer reduce : {ReduceRecall, ReduceInvalid, ReduceF1, ReduceMpjpe, ReducePck, ReduceCounts}) {
    reduce(totals, options, &result);
  }
  return result;
}

TEST(MetricReducers, RecallInvalidF1AndMpjpeFromFoldedFrames) {
  EvalOptions options;
  options.evaluated_joints = {"a", "b"};
  MetricTotals totals(options);
  for (const FrameRecords& frame : ThreePredictions()) totals.Fold(frame);
  const MetricsResult result = Reduce(totals, options);
  EXPECT_DOUBLE_EQ(result.recall_100, 50.0);
  EXPECT_DOUBLE_EQ(result.recall_500, 100.0);
  EXPECT_DOUBLE_EQ(result.invalid, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(result.f1, 100.0 * 4.0 / 5.0);  // 2 TP / (2 TP + 1 FP + 0 FN)
  EXPECT_DOUBLE_EQ(result.mpjpe_mm, 170.0);
  EXPECT_DOUBLE_EQ(result.pck_100, 50.0);          // 30 and 50 of 4 GT-valid joints
  EXPECT_DOUBLE_EQ(result.pck_500, 100.0);
  EXPECT_EQ(result.num_matches, 2);
  EXPECT_EQ(result.num_gt_persons, 2);
  EXPECT_EQ(result.num_frames, 2);
  EXPECT_EQ(result.num_frames_with_gt, 1);

  // Folding the frames into two totals and merging them gives the same numbers.
  MetricTotals first(options), second(options);
  first.Fold(ThreePredictions()[0]);
  second.Fold(ThreePredictions()[1]);
  first.Merge(second);
  const MetricsResult merged = Reduce(first, options);
  EXPECT_EQ(merged.recall_100, result.recall_100);
  EXPECT_EQ(merged.invalid, result.invalid);
  EXPECT_EQ(merged.f1, result.f1);
  EXPECT_EQ(merged.mpjpe_mm, result.mpjpe_mm);
  EXPECT_EQ(merged.pck_100, result.pck_100);
  EXPECT_EQ(merged.num_frames, 2);
}

TEST(MetricReducers, EveryReducerIsListedOnce) {
  const std::span<const MetricReducer> reducers = MetricReducers();
  EXPECT_EQ(reducers.size(), 11u);
  for (size_t i = 0; i < reducers.size(); ++i) {
    for (size_t k = 0; k < i; ++k) EXPECT_NE(reducers[i], reducers[k]);
  }
}

}  // namespace
}  // namespace rpt::metrics
