// SPDX-License-Identifier: MIT
// rpt detector-stats end to end: markdown and JSON on generated data, profiles, bad arguments,
// and MVOR's real detections when the data is present.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

nlohmann::json StatsJson(const std::string& args) {
  const test::CommandResult r = test::RunRpt("detector-stats " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

TEST(DetectorStatsCommand, MarkdownNamesEveryTable) {
  const test::CommandResult r = test::RunRpt("detector-stats --dataset synthetic --param frames=10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* heading : {"## Detection per view", "## Joint errors (box units)", "## By 2D label",
                              "## Other statistics", "## Confidence distribution", "## Per joint"}) {
    EXPECT_NE(r.out.find(heading), std::string::npos) << heading;
  }
}

TEST(DetectorStatsCommand, ProfilesOrderAsDocumented) {
  const std::string input = "--dataset synthetic --param frames=40 --param noise=";
  const nlohmann::json perfect = StatsJson(input + "perfect");
  const nlohmann::json clean = StatsJson(input + "clean");
  const nlohmann::json realistic = StatsJson(input + "realistic");
  const nlohmann::json hard = StatsJson(input + "hard");
  EXPECT_EQ(perfect["error"]["all"]["p99"], 0.0);
  EXPECT_EQ(perfect["total"]["detection_rate"], 1.0);
  EXPECT_EQ(clean["hidden_share"], 0.0) << "the clean model has no occluders";
  const double clean_median = clean["error"]["all"]["median"], realistic_median = realistic["error"]["all"]["median"];
  EXPECT_GT(realistic_median, 2 * clean_median);
  EXPECT_GT(hard["error"]["all"]["median"].get<double>(), realistic_median);
  EXPECT_GT(realistic["hidden_share"].get<double>(), 0.2);
  EXPECT_LT(hard["total"]["detection_rate"].get<double>(), realistic["total"]["detection_rate"].get<double>());
  for (const char* key : {"views", "total", "error", "by_visibility", "per_joint", "confidence_histogram", "swap_rate",
                          "truncated_share", "detection_by_label"}) {
    EXPECT_TRUE(realistic.contains(key)) << key;
  }
  EXPECT_EQ(realistic["views"].size(), 5u);
}

TEST(DetectorStatsCommand, BadArgumentsExitWithCode2) {
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --detector hard").exit_code, 2) << "needs --simulate";
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --simulate --detector noisy").exit_code, 2);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --param noise=noisy").exit_code, 2);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --joints ankle_left,unknown").exit_code, 0);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --joints unknown").exit_code, 2);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --simulate --simulate-perfect --detector hard").exit_code, 2);
}

TEST(DetectorStatsCommand, SimulatedDetectionsOnARealDatasetAndItsOwn) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const std::string input = "--dataset mvor --root " + test::SharedData("mvor").string();
  const nlohmann::json real = StatsJson(input);
  const nlohmann::json simulated = StatsJson(input + " --simulate --detector realistic --seed 2");
  EXPECT_EQ(real["joints"].size(), 8u) << "MVOR's evaluated arm and torso joints";
  EXPECT_GT(real["total"]["duplicates"].get<int>(), 0) << "MVOR's file repeats detections";
  EXPECT_EQ(simulated["total"]["duplicates"], 0);
  EXPECT_EQ(real["persons_in_view"], simulated["persons_in_view"]) << "same GT and cameras";
  EXPECT_GT(real["by_visibility"]["occluded"]["joints"].get<int>(), 0) << "MVOR's 2D labels are read";
}

}  // namespace
}  // namespace rpt
