// SPDX-License-Identifier: MIT
// The metric reducers are pure functions of hand-made records (no accumulator involved).
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/reducers/reducers.h"

namespace rpt::metrics {
namespace {

// Two GT persons, three counted predictions: a 40 mm match, a 300 mm near miss, and one without GT.
EvalRecords ThreePredictions() {
  EvalRecords records;
  records.evaluated = {"a", "b"};
  records.num_frames = 2;
  records.num_frames_with_gt = 1;
  records.num_gt = 2;
  records.num_pred_counted = 3;
  records.num_pred_total = 3;
  records.gt_valid_per_joint = {2, 2};
  auto pair = [](int gt_id, double error, double score, Eigen::ArrayXd joints) {
    PairRecord record;
    record.match = MatchRecord{gt_id, error, score};
    record.flags = kNearest;
    record.report_error_mm = error;
    record.joint_errors = joints;
    record.report_joint_errors = joints;
    return record;
  };
  records.pairs.push_back(pair(0, 40.0, 0.9, (Eigen::ArrayXd(2) << 30.0, 50.0).finished()));
  records.pairs.push_back(pair(1, 300.0, 0.8, (Eigen::ArrayXd(2) << 200.0, 400.0).finished()));
  records.pairs.push_back(pair(-1, INFINITY, 0.7, Eigen::ArrayXd()));
  return records;
}

TEST(MetricReducers, RecallInvalidF1AndMpjpeFromRecords) {
  const EvalRecords records = ThreePredictions();
  EvalOptions options;
  options.match_threshold_mm = 500.0;
  const MatchSets matches = SelectMatches(records, options);
  ASSERT_EQ(matches.at_gate, (std::vector<bool>{true, true, false}));
  EXPECT_EQ(matches.at_100, (std::vector<bool>{true, false, false}));
  MetricsResult result;
  for (const MetricReducer reduce : {ReduceRecall, ReduceInvalid, ReduceF1, ReduceMpjpe, ReducePck, ReduceCounts}) {
    reduce(records, matches, options, &result);
  }
  EXPECT_DOUBLE_EQ(result.recall_100, 50.0);
  EXPECT_DOUBLE_EQ(result.recall_500, 100.0);
  EXPECT_DOUBLE_EQ(result.invalid, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(result.f1, 100.0 * 4.0 / 5.0);  // 2 TP / (2 TP + 1 FP + 0 FN)
  EXPECT_DOUBLE_EQ(result.mpjpe_mm, 170.0);
  EXPECT_DOUBLE_EQ(result.pck_100, 50.0);          // 30 and 50 of 4 GT-valid joints
  EXPECT_DOUBLE_EQ(result.pck_500, 100.0);
  EXPECT_EQ(result.num_matches, 2);
  EXPECT_EQ(result.num_gt_persons, 2);
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
