// SPDX-License-Identifier: MIT
// rpt detector-stats end to end: markdown and JSON on generated data, profiles, bad arguments,
// --compare (the input next to simulated profiles), and MVOR's real detections when present.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

nlohmann::json StatsJson(const std::string& args) {
  const test::CommandResult r = test::RunRpt("detector-stats " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// The cells of a markdown table row "| a | b | c |" (trimmed), empty when `line` is not one.
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  if (line.size() < 2 || line.front() != '|' || line.back() != '|') return cells;
  std::stringstream in(line.substr(1, line.size() - 2));
  for (std::string cell; std::getline(in, cell, '|');) {
    const size_t begin = cell.find_first_not_of(' '), end = cell.find_last_not_of(' ');
    cells.push_back(begin == std::string::npos ? "" : cell.substr(begin, end - begin + 1));
  }
  return cells;
}

// The first markdown table of `text` whose first header cell is "statistic": row name -> cells
// after it, plus the header under "statistic".
std::map<std::string, std::vector<std::string>> CompareTable(const std::string& text) {
  std::map<std::string, std::vector<std::string>> table;
  std::stringstream in(text);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> cells = Cells(line);
    if (cells.empty()) {
      if (inside) break;
      continue;
    }
    if (cells.front() == "statistic") inside = true;
    if (inside && cells.front().rfind("---", 0) != 0) table[cells.front()] = {cells.begin() + 1, cells.end()};
  }
  return table;
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
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --simulate --param noise=clean").exit_code, 2)
      << "the dataset's noise would be ignored";
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --joints ankle_left,unknown").exit_code, 0);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --joints unknown").exit_code, 2);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --simulate --simulate-perfect --detector hard").exit_code, 2);
}

TEST(DetectorStatsCommand, CompareTablesTheInputAndEachProfile) {
  const test::CommandResult r =
      test::RunRpt("detector-stats --dataset synthetic --param frames=20 --compare clean,realistic");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = CompareTable(r.out);
  ASSERT_TRUE(table.count("statistic")) << r.out;
  EXPECT_EQ(table.at("statistic"), (std::vector<std::string>{"input: synthetic", "clean", "realistic"}));
  for (const char* row :
       {"detection rate, GT persons in view", "... mostly visible / mostly hidden persons", "false positives per view",
        "joint error, all: median / p90 / p99", "visible joints", "hidden joints (occluded or not labelled)",
        "persons neither truncated nor hidden", "confidence <= 0.5", "confidence 0.5-0.9", "confidence >= 0.9",
        "hidden share of in-image joints", "missing joints: all / visible / hidden",
        "confidence mean: visible / hidden joints", "share of confidences >= 0.9 / < 0.5", "left/right swaps",
        "hip offset, down / out (medians)", "truncated persons", "false positives: mean confidence / reported joints"}) {
    ASSERT_TRUE(table.count(row)) << row << "\n" << r.out;
    EXPECT_EQ(table.at(row).size(), 3u) << row;
  }
  EXPECT_EQ(table.at("hidden joints (occluded or not labelled)")[1], "-") << "the clean model hides nothing";
  EXPECT_EQ(table.at("GT persons in view")[0], table.at("GT persons in view")[2]) << "same GT and cameras";
  EXPECT_NE(r.out.find("Per joint (input: synthetic / clean / realistic;"), std::string::npos);
}

TEST(DetectorStatsCommand, ComparePerfectColumnIsExact) {
  const test::CommandResult r = test::RunRpt("detector-stats --dataset synthetic --param frames=20 --compare perfect");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = CompareTable(r.out);
  ASSERT_EQ(table.at("statistic").size(), 2u);
  EXPECT_EQ(table.at("statistic")[1], "perfect");
  EXPECT_EQ(table.at("joint error, all: median / p90 / p99")[1], "0.000 / 0.000 / 0.000");
  EXPECT_EQ(table.at("left/right swaps")[1], "0.000");
  EXPECT_EQ(table.at("detection rate, GT persons in view")[1], "1.000");
  EXPECT_NE(table.at("joint error, all: median / p90 / p99")[0], "0.000 / 0.000 / 0.000")
      << "the input's own detections are the default realistic ones";
}

TEST(DetectorStatsCommand, CompareBadArgumentsExitWithCode2) {
  const test::CommandResult simulate =
      test::RunRpt("detector-stats --dataset synthetic --param frames=5 --simulate --compare clean");
  EXPECT_EQ(simulate.exit_code, 2);
  EXPECT_NE(simulate.err.find("--compare excludes --simulate"), std::string::npos) << simulate.err;
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --param frames=5 --compare noisy").exit_code, 2);
  EXPECT_EQ(test::RunRpt("detector-stats --dataset synthetic --param frames=5 --compare clean,clean").exit_code, 2);
}

TEST(DetectorStatsCommand, CompareJsonHasTheInputAndEachProfile) {
  const std::string input = "--dataset synthetic --param frames=20 --param noise=clean";
  const nlohmann::json both = StatsJson(input + " --compare realistic --seed 4");
  ASSERT_TRUE(both.is_object());
  EXPECT_EQ(both.size(), 2u);
  ASSERT_TRUE(both.contains("input"));
  ASSERT_TRUE(both.contains("realistic"));
  EXPECT_EQ(both["input"], StatsJson(input)) << "the input's own detections";
  // The same as --simulate on the same scene (its --param noise would be refused beside --simulate:
  // the simulated detector replaces the scene's; the description says which input it was).
  nlohmann::json simulated = StatsJson("--dataset synthetic --param frames=20 --simulate --detector realistic --seed 4");
  nlohmann::json compared = both["realistic"];
  ASSERT_TRUE(simulated.is_object());
  EXPECT_EQ(compared["input"], "dataset synthetic frames=20 noise=clean, simulated detector 'realistic', seed 4");
  simulated.erase("input");
  compared.erase("input");
  EXPECT_EQ(compared, simulated) << "the same as --simulate on the same scene";
}

// docs/detector_model.md's generated-scene table is one --compare run; it must equal the synthetic
// dataset's own detector (--param noise=PROFILE), which draws the same way.
TEST(DetectorStatsCommand, CompareOnTheSyntheticSceneEqualsItsNoiseParameter) {
  const std::string scene = "--dataset synthetic --param frames=20";
  nlohmann::json compared = StatsJson(scene + " --param noise=perfect --compare hard")["hard"];
  nlohmann::json own = StatsJson(scene + " --param noise=hard");
  compared.erase("input");
  own.erase("input");
  EXPECT_EQ(compared, own);
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

TEST(DetectorStatsCommand, CompareOnMvorKeepsTheRealDetectionsInTheFirstColumn) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const test::CommandResult r =
      test::RunRpt("detector-stats --dataset mvor --root " + test::SharedData("mvor").string() + " --compare hard");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = CompareTable(r.out);
  ASSERT_TRUE(table.count("detection rate, GT persons in view")) << r.out;
  EXPECT_EQ(table.at("statistic"), (std::vector<std::string>{"input: mvor", "hard"}));
  const std::vector<std::string>& rate = table.at("detection rate, GT persons in view");
  EXPECT_NEAR(std::stod(rate[0]), 0.678, 0.005) << "MVOR's OpenPose detections (rpt detector-stats --dataset mvor)";
  EXPECT_NEAR(std::stod(rate[1]), 0.678, 0.05) << "hard is the MVOR fit";
}

// How many views detect each GT person: MVOR's 3 cameras detect a quarter of its people in one
// view only (measured: 52 / 260 / 423 / 326 of 1061 in 0 / 1 / 2 / 3 views); a perfect detector
// on the synthetic scene detects everybody in view of a camera in at least one view.
TEST(DetectorStatsCommand, PersonsByDetectingViews) {
  const nlohmann::json perfect = StatsJson("--dataset synthetic --param frames=10 --param noise=perfect");
  const nlohmann::json& counts = perfect["persons_by_detecting_views"];
  EXPECT_EQ(counts["0"], 0);
  EXPECT_EQ(counts["0"].get<long>() + counts["1"].get<long>() + counts["2"].get<long>() + counts["3+"].get<long>(),
            perfect["persons_in_any_view"].get<long>());
  EXPECT_EQ(perfect["persons_in_any_view"], 40) << "4 people x 10 frames, all in view";
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const nlohmann::json mvor = StatsJson("--dataset mvor --root " + test::SharedData("mvor").string());
  EXPECT_EQ(mvor["persons_in_any_view"], 1061);
  EXPECT_EQ(mvor["persons_by_detecting_views"],
            (nlohmann::json{{"0", 52}, {"1", 260}, {"2", 423}, {"3+", 326}}));
}

}  // namespace
}  // namespace rpt
