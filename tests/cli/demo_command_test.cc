// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

TEST(DemoCommand, JsonHasTheDocumentedKeysAndSaneValues) {
  const test::CommandResult r = test::RunRpt("demo --frames 60 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"frames", "persons_present", "persons_found", "mpjpe_mm", "frame_time_us_median",
                          "step_time_us_median"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["frames"], 60);
  EXPECT_EQ(j["persons_present"], 4 * 60);
  EXPECT_GE(j["persons_found"].get<int>(), 4 * 60 * 95 / 100);
  // The default detector profile is `realistic` (fitted to real OpenPose output, whose hips and
  // shoulders sit 3-6 cm from the GT's): about 43 mm here. Below 30 mm would mean the noise is
  // not applied; the clean profile gives about 17 mm.
  EXPECT_GT(j["mpjpe_mm"].get<double>(), 30.0);
  EXPECT_LT(j["mpjpe_mm"].get<double>(), 55.0);
  EXPECT_GT(j["frame_time_us_median"].get<double>(), 0.0);
  for (const char* step : {"undistort", "make_pairs", "prefilter", "triangulate_core", "group", "merge", "track"}) {
    EXPECT_TRUE(j["step_time_us_median"].contains(step)) << step;
  }
}

TEST(DemoCommand, NoiseFreeWholeBodyIsExact) {
  const test::CommandResult r = test::RunRpt("demo --frames 20 --people 2 --joints wholebody --noise none --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_LT(j["mpjpe_mm"].get<double>(), 1.0);
  EXPECT_TRUE(j.contains("wholebody_mpjpe_mm"));
}

TEST(DemoCommand, TextOutputNamesEveryStep) {
  const test::CommandResult r = test::RunRpt("demo --frames 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* word : {"persons present", "mean joint error", "time per frame", "triangulate_full", "clip_speed"}) {
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  }
}

TEST(DemoCommand, BadArgumentsExitWithCode2) {
  EXPECT_EQ(test::RunRpt("demo --cameras 1").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --joints tail").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --frames abc").exit_code, 2);
  EXPECT_EQ(test::RunRpt("nonsense").exit_code, 2);
  const test::CommandResult help = test::RunRpt("demo --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--cameras"), std::string::npos);
}

}  // namespace
}  // namespace rpt
