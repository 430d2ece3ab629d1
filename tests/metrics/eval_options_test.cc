// SPDX-License-Identifier: MIT
#include "metrics/eval_options.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "metrics/accumulator.h"
#include "tests/error_message.h"

namespace rpt::metrics {
namespace {

TEST(EvalOptions, DefaultsAreValidAndEvaluateThePapers13Joints) {
  const EvalOptions options;
  EXPECT_EQ(options.Check(), "");
  EXPECT_EQ(options.EvaluatedJoints(), EvaluationJoints13());
  EXPECT_EQ(options.EvaluatedJoints().size(), 13u);
  EXPECT_DOUBLE_EQ(options.match_threshold_mm, 500.0);
  EXPECT_DOUBLE_EQ(options.min_gt_score, 0.1);
  EXPECT_EQ(options.matching, MatchingMode::kGreedy);
  EXPECT_EQ(options.pck_denominator, PckDenominator::kAllGt);
  EXPECT_TRUE(options.count_preds_without_gt);
  EXPECT_EQ(options.alignment, Alignment::kNone);
}

// Check() returns the first problem as "metrics.key: problem" (core/options_check.h); the
// accumulator throws it.
TEST(EvalOptions, CheckNamesTheFirstBadValue) {
  const auto problem = [](auto change) {
    EvalOptions options;
    change(options);
    return options.Check();
  };
  EXPECT_EQ(problem([](EvalOptions& o) { o.match_threshold_mm = 0.0; }),
            "metrics.match_threshold_mm: '0.0' is not a number > 0");
  EXPECT_EQ(problem([](EvalOptions& o) {
              o.evaluated_joints = {"nose", "nose"};
            }),
            "metrics.evaluated_joints: lists 'nose' twice");
  EXPECT_EQ(problem([](EvalOptions& o) { o.pcp_alpha = -1.0; }), "metrics.pcp_alpha: '-1.0' is not a number > 0");
  EXPECT_EQ(problem([](EvalOptions& o) {
              o.legacy_pcp_gt_joints = {"a", "b"};
            }),
            "metrics.legacy_pcp_gt_joints: must list 14 names (Shelf14 order) or be empty, got 2");
  EXPECT_EQ(problem([](EvalOptions& o) { o.legacy_pcp_actors = 0; }),
            "metrics.legacy_pcp_actors: '0' is not an integer in [1, 10000]");
  EXPECT_EQ(problem([](EvalOptions& o) { o.legacy_pcp_alpha = std::nan(""); }),
            "metrics.legacy_pcp_alpha: 'nan' is not a number > 0");
  EvalOptions bad;
  bad.legacy_pcp_alpha = 0.0;
  EXPECT_EQ(test::ConfigErrorOf([&] { MetricsAccumulator accumulator(bad); }),
            "metrics.legacy_pcp_alpha: '0.0' is not a number > 0");
}

}  // namespace
}  // namespace rpt::metrics
