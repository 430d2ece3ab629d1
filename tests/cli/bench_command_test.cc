// SPDX-License-Identifier: MIT
// rpt bench: structure of its JSON, the in-run baseline and the HDF5 loading mode (speed goals
// live in results/bench.md, not in tests).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/pipeline/frame_stats.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

TEST(BenchCommand, ReportsStepsAccuracyAndBaseline) {
  const test::CommandResult r =
      test::RunRpt("bench --scene few-views --frames 20 --repeat 1 --baseline-frames 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["scenes"].size(), 1u);
  const nlohmann::json& s = j["scenes"][0];
  EXPECT_EQ(s["name"], "few-views");
  EXPECT_GT(s["frame_time_us_median"].get<double>(), 0.0);
  EXPECT_EQ(s["step_time_us_median"].size(), static_cast<size_t>(kNumSteps)) << "one entry per step";
  EXPECT_GT(s["baseline_frame_time_us_median"].get<double>(), s["frame_time_us_median"].get<double>());
  EXPECT_GT(s["speedup"].get<double>(), 1.0);
  EXPECT_LT(s["mpjpe_mm"].get<double>(), 60.0);
  EXPECT_TRUE(j["run"].contains("cpu"));
  EXPECT_EQ(test::RunRpt("bench --scene nosuch").exit_code, 2);
}

TEST(BenchCommand, HdfCacheRoundTripTiming) {
  const test::CommandResult r = test::RunRpt("bench --io --io-frames 200 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 200);
  EXPECT_EQ(j["views"], 5);
  EXPECT_GT(j["read_s_median"].get<double>(), 0.0);
  EXPECT_GT(j["persons"].get<long>(), 200);
}

}  // namespace
}  // namespace rpt
