// SPDX-License-Identifier: MIT
#include "metrics/eval_options.h"

#include <gtest/gtest.h>

#include "core/errors.h"

namespace rpt::metrics {
namespace {

TEST(EvalOptions, DefaultsAreValidAndEvaluateThePapers13Joints) {
  const EvalOptions options;
  EXPECT_NO_THROW(options.Check());
  EXPECT_EQ(options.EvaluatedJoints(), EvaluationJoints13());
  EXPECT_EQ(options.EvaluatedJoints().size(), 13u);
  EXPECT_DOUBLE_EQ(options.match_threshold_mm, 500.0);
  EXPECT_DOUBLE_EQ(options.min_gt_score, 0.1);
  EXPECT_EQ(options.matching, MatchingMode::kGreedy);
  EXPECT_EQ(options.pck_denominator, PckDenominator::kAllGt);
  EXPECT_TRUE(options.count_preds_without_gt);
  EXPECT_EQ(options.alignment, Alignment::kNone);
}

TEST(EvalOptions, CheckRejectsBadValues) {
  EvalOptions options;
  options.match_threshold_mm = 0.0;
  EXPECT_THROW(options.Check(), ConfigError);
  options = {};
  options.evaluated_joints = {"nose", "nose"};
  EXPECT_THROW(options.Check(), ConfigError);
  options = {};
  options.pcp_alpha = -1.0;
  EXPECT_THROW(options.Check(), ConfigError);
  options = {};
  options.legacy_pcp_gt_joints = {"a", "b"};
  EXPECT_THROW(options.Check(), ConfigError);
  options = {};
  options.legacy_pcp_actors = 0;
  EXPECT_THROW(options.Check(), ConfigError);
  options = {};
  options.legacy_pcp_alpha = 0.0;
  try {
    options.Check();
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "metrics.legacy_pcp_alpha: 0 must be > 0");
  }
}

}  // namespace
}  // namespace rpt::metrics
