// SPDX-License-Identifier: MIT
// The step tables (engine/outputs/step_tables.h) carry the reader's part-affinity grouping as its
// own row "paf_grouping (reader)" when a reader grouped raw candidates (shelf-4da), and no such
// row otherwise: terminal table, summary.json's step times and steps.csv.
#include "engine/outputs/step_tables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace rpt::engine {
namespace {

metrics::TimingSummary Summary(bool grouping) {
  metrics::TimingAccumulator timing;
  for (const double t : {10.0, 20.0, 30.0}) {
    FrameStats stats;
    stats.total_us = t;
    stats.time_us[static_cast<int>(Step::kMerge)] = t / 10;
    timing.Add(stats, grouping ? t / 2 : -1);
  }
  return timing.Finalize();
}

TEST(StepTables, ReaderGroupingRowOnlyWhenTheReaderGrouped) {
  const metrics::TimingSummary without = Summary(false);
  std::ostringstream plain;
  PrintStepTimes(plain, without);
  EXPECT_EQ(plain.str().find("paf_grouping"), std::string::npos) << plain.str();
  EXPECT_EQ(plain.str().find("frame + grouping"), std::string::npos) << plain.str();
  EXPECT_EQ(StepTimesJson(without).size(), static_cast<size_t>(kNumSteps));
  const metrics::StepCountSummary counts{};
  const std::string csv = StepsCsv(without, counts);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), kNumSteps + 1);

  const metrics::TimingSummary with = Summary(true);
  std::ostringstream table;
  PrintStepTimes(table, with);
  const std::string text = table.str();
  // Header, then the grouping first (it runs before the pipeline): median 10, mean 10.
  const size_t row = text.find("\n  paf_grouping (reader)        10.00        10.00\n");
  EXPECT_NE(row, std::string::npos) << text;
  EXPECT_LT(row, text.find(std::string(kSteps[0].key))) << text;
  // The frame total stays the pipeline's (20); with the grouping 30.
  EXPECT_NE(text.find("  frame (total)                20.00        20.00\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  frame + grouping             30.00        30.00\n"), std::string::npos) << text;
  const nlohmann::ordered_json json = StepTimesJson(with);
  ASSERT_EQ(json.size(), static_cast<size_t>(kNumSteps) + 1);
  EXPECT_EQ(json.begin().key(), "paf_grouping (reader)");
  EXPECT_DOUBLE_EQ(json["paf_grouping (reader)"].get<double>(), 10.0);
  const std::string with_csv = StepsCsv(with, counts);
  EXPECT_EQ(std::count(with_csv.begin(), with_csv.end(), '\n'), kNumSteps + 2);
  EXPECT_NE(with_csv.find("\npaf_grouping (reader),,,10.000,10.000\n"), std::string::npos) << with_csv;
}

}  // namespace
}  // namespace rpt::engine
