// SPDX-License-Identifier: MIT
#include "engine/outputs/results_writer.h"
#include "engine/outputs/run_info.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace rpt::engine {
namespace {

// Splits one CSV line by RFC 4180 (quoted fields may hold commas; "" is a quote).
std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// CsvField itself: OutputEscaping.CsvFieldsAreOneLineNeverAFormulaAndReadBack (tests/cli).

// Sweep rows are named by people ("bone-length check (rpt addition, off by default)"): a comma in
// the name must not shift the numbers into the wrong columns.
TEST(ResultsWriter, SummaryCsvKeepsColumnsWhenTheRunNameHasCommas) {
  nlohmann::ordered_json summary = {{"pcp", 97.5}, {"mpjpe_mm", 60.25}};
  std::istringstream csv(SummaryCsv({{"bone-length check (rpt addition, off by default)", summary}}));
  std::string header_line, row_line;
  std::getline(csv, header_line);
  std::getline(csv, row_line);
  const std::vector<std::string> header = SplitCsvLine(header_line), row = SplitCsvLine(row_line);
  ASSERT_EQ(row.size(), header.size());
  EXPECT_EQ(row[0], "bone-length check (rpt addition, off by default)");
  int checked = 0;
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "pcp") {
      EXPECT_EQ(row[i], "97.5000");
      ++checked;
    }
    if (header[i] == "mpjpe_mm") {
      EXPECT_EQ(row[i], "60.2500");
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

// Per-part PCP: every part some GT person has, by name, in the order of the parts; a part never
// evaluated (no GT, or its joints not evaluated) is left out rather than reported as 0.
TEST(ResultsWriter, PcpPerPartInJson) {
  RunResult run;
  const auto part = [](const std::string& name, int correct, int total, double pcp) {
    metrics::PcpPartResult p;
    p.name = name;
    p.correct = correct;
    p.total = total;
    p.pcp = pcp;
    return p;
  };
  run.metrics.pcp_parts = {part("upper_arm_left", 9, 10, 90.0), part("lower_arm_left", 3, 4, 75.0),
                           part("head", 0, 0, 0.0), part("torso", 0, 2, 0.0)};
  const nlohmann::ordered_json summary = SummaryJson(run);
  ASSERT_TRUE(summary.contains("pcp_parts"));
  const nlohmann::ordered_json& parts = summary["pcp_parts"];
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts.begin().key(), "upper_arm_left");
  EXPECT_DOUBLE_EQ(parts["upper_arm_left"].get<double>(), 90.0);
  EXPECT_DOUBLE_EQ(parts["lower_arm_left"].get<double>(), 75.0);
  EXPECT_DOUBLE_EQ(parts["torso"].get<double>(), 0.0) << "evaluated and all wrong";
  EXPECT_FALSE(parts.contains("head")) << "never evaluated";
  EXPECT_EQ(summary["units"]["pcp_parts"], "%");
  EXPECT_FALSE(SummaryJson(RunResult{}).contains("pcp_parts")) << "no part evaluated";
}

// The unmatched predictions by cause: counts under their names in summary.json (unit
// "predictions"), and the terminal line that names the ranges by the gate.
TEST(ResultsWriter, InvalidCausesInJsonAndOnTheTerminal) {
  RunResult run;
  run.metrics.invalid_causes = {
      .duplicate = 1, .near_matched_gt = 2, .near_missed_gt = 5, .far_from_gt = 3, .no_gt = 4};
  const nlohmann::ordered_json summary = SummaryJson(run);
  ASSERT_TRUE(summary.contains("invalid_causes"));
  const nlohmann::ordered_json& causes = summary["invalid_causes"];
  EXPECT_EQ(causes["duplicate"], 1);
  EXPECT_EQ(causes["near_matched_gt"], 2);
  EXPECT_EQ(causes["near_missed_gt"], 5);
  EXPECT_EQ(causes["far_from_gt"], 3);
  EXPECT_EQ(causes["no_gt"], 4);
  EXPECT_EQ(summary["units"]["invalid_causes"], "predictions");
  EXPECT_EQ(InvalidCausesLine(run.metrics, 500),
            "unmatched predictions (Invalid): 15 = 1 duplicate + 2 beside a found person (500-1000 mm) + 5 near a "
            "missed person (500-1000 mm) + 3 far from every GT person + 4 without GT to compare");
  EXPECT_EQ(InvalidCausesLine(metrics::MetricsResult{}, 500), "") << "nothing unmatched: no line";
}

// Legacy Shelf/Campus PCP: the papers report it per actor and as the average over actors 1-3.
TEST(ResultsWriter, LegacyPcpPerActorInJsonCsvAndMarkdown) {
  RunResult run;
  metrics::LegacyPcpResult legacy;
  const auto actor = [](int id, double pcp, bool averaged) {
    metrics::LegacyPcpResult::Actor a;
    a.actor_id = id;
    a.num_frames = 10;
    a.pcp = pcp;
    a.averaged = averaged;
    return a;
  };
  legacy.actors = {actor(0, 90.0, true), actor(1, 80.0, true), actor(2, 70.5, true), actor(3, 10.0, false)};
  legacy.average_pcp = 80.166666;
  run.metrics.legacy_pcp = legacy;
  const nlohmann::ordered_json summary = SummaryJson(run);
  EXPECT_DOUBLE_EQ(summary["legacy_pcp"].get<double>(), 80.166666);
  EXPECT_DOUBLE_EQ(summary["legacy_pcp_actor1"].get<double>(), 90.0);
  EXPECT_DOUBLE_EQ(summary["legacy_pcp_actor3"].get<double>(), 70.5);
  EXPECT_FALSE(summary.contains("legacy_pcp_actor4")) << "actor 4 is not in the average";
  EXPECT_EQ(summary["units"]["legacy_pcp_actor2"], "%");

  // A sweep table may mix rows with and without a legacy PCP.
  const nlohmann::ordered_json plain = {{"pcp", 50.0}};
  const std::vector<std::pair<std::string, nlohmann::ordered_json>> rows = {{"shelf", summary}, {"plain", plain}};
  std::istringstream csv(SummaryCsv(rows));
  std::string line;
  std::vector<std::vector<std::string>> table;
  while (std::getline(csv, line)) table.push_back(SplitCsvLine(line));
  ASSERT_EQ(table.size(), 3u);
  const std::vector<std::string>& header = table[0];
  ASSERT_GE(header.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(header.end() - 4, header.end()),
            (std::vector<std::string>{"legacy_pcp", "legacy_pcp_actor1", "legacy_pcp_actor2", "legacy_pcp_actor3"}));
  EXPECT_EQ(std::vector<std::string>(table[1].end() - 4, table[1].end()),
            (std::vector<std::string>{"80.1667", "90.0000", "80.0000", "70.5000"}));
  EXPECT_EQ(std::vector<std::string>(table[2].end() - 4, table[2].end()), (std::vector<std::string>{"", "", "", ""}));
  EXPECT_EQ(table[1].size(), header.size());
  EXPECT_EQ(table[2].size(), header.size());

  const std::string markdown = SummaryMarkdown(rows);
  EXPECT_NE(markdown.find("| run | Actor 1 | Actor 2 | Actor 3 | Average |\n|---|---|---|---|---|\n"
                          "| shelf | 90.0 | 80.0 | 70.5 | 80.2 |\n| plain | - | - | - | - |\n"),
            std::string::npos)
      << markdown;
  // An actor without GT in the frames evaluated (Shelf frames 300-302 have no actor 2) shows "-".
  const nlohmann::ordered_json gap = {{"legacy_pcp", 100.0}, {"legacy_pcp_actor1", 100.0}, {"legacy_pcp_actor3", 99.0}};
  EXPECT_NE(SummaryMarkdown({{"gap", gap}}).find("| gap | 100.0 | - | 99.0 | 100.0 |"), std::string::npos)
      << SummaryMarkdown({{"gap", gap}});
  // Without a legacy PCP nothing changes.
  EXPECT_EQ(SummaryMarkdown({{"plain", plain}}).find("Legacy"), std::string::npos);
  EXPECT_EQ(SummaryCsv({{"plain", plain}}).find("legacy"), std::string::npos);
}

}  // namespace
}  // namespace rpt::engine

namespace rpt::engine {
namespace {

TEST(CommandLine, QuotesWhatAShellWouldSplitOrExpand) {
  std::vector<std::string> args = {"rpt", "eval", "--root", "../sp ace/d", "--set", "a.b=1", "it's", "", "$HOME"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  EXPECT_EQ(CommandLine(static_cast<int>(argv.size()), argv.data()),
            "rpt eval --root '../sp ace/d' --set a.b=1 'it'\\''s' '' '$HOME'");
}

}  // namespace
}  // namespace rpt::engine
