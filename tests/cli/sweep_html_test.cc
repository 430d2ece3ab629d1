// SPDX-License-Identifier: MIT
// sweep.html (engine/outputs/sweep_html.h): well-formed, one row per configuration, a column per varied
// option, deltas against the default configuration worked out by hand, one bar per row per chart;
// and `rpt sweep` / `rpt merge` write it.
#include "engine/outputs/sweep_html.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "tests/cli/cli_test_util.h"
#include "tests/cli/xml_check.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;
using test::XmlElement;

// Every element named `name` below `root`, depth first.
std::vector<const XmlElement*> FindAll(const XmlElement& root, const std::string& name) {
  std::vector<const XmlElement*> out;
  std::function<void(const XmlElement&)> visit = [&](const XmlElement& e) {
    if (e.name == name) out.push_back(&e);
    for (const XmlElement& child : e.children) visit(child);
  };
  visit(root);
  return out;
}

std::string Attribute(const XmlElement& e, const std::string& key) {
  const auto it = e.attributes.find(key);
  return it == e.attributes.end() ? "" : it->second;
}

// The text of an element and its descendants.
std::string AllText(const XmlElement& e) {
  std::string text = e.text;
  for (const XmlElement& child : e.children) text += AllText(child);
  return text;
}

// The rows of the table with id "sweep".
std::vector<const XmlElement*> TableRows(const XmlElement& html) {
  for (const XmlElement* table : FindAll(html, "table")) {
    if (Attribute(*table, "id") == "sweep") return FindAll(*FindAll(*table, "tbody").at(0), "tr");
  }
  ADD_FAILURE() << "no table id=sweep";
  return {};
}

// The cell of `row` holding `metric` (data-metric attribute), or nullptr.
const XmlElement* MetricCell(const XmlElement& row, const std::string& metric) {
  for (const XmlElement* td : FindAll(row, "td")) {
    if (Attribute(*td, "data-metric") == metric) return td;
  }
  return nullptr;
}

nlohmann::ordered_json Row(const std::string& name, nlohmann::ordered_json set, bool is_default,
                           nlohmann::ordered_json summary) {
  return {{"name", name}, {"set", set}, {"default", is_default}, {"summary", summary}};
}

TEST(SweepHtml, RowsOptionsAndDeltasAgainstTheDefault) {
  nlohmann::ordered_json sweep;
  sweep["base"] = {{"score.mode", "adaptive"}, {"merge.top_k", "2"}};
  sweep["run"] = {{"command", "rpt sweep --list a&b.json"}};
  sweep["rows"] = {
      Row("fewer <outliers>", {{"merge.top_k", "0"}}, false,
          {{"pcp", 92.5}, {"mpjpe_mm", 55.25}, {"invalid", 10.0}, {"frame_time_us_median", 120.0}}),
      Row("default", nlohmann::ordered_json::object(), true,
          {{"pcp", 90.0}, {"mpjpe_mm", 50.0}, {"invalid", 10.0}, {"frame_time_us_median", 100.0}}),
      Row("triangulation only", {{"score.mode", "triangulation"}}, false,
          {{"pcp", nullptr}, {"mpjpe_mm", 49.0}, {"invalid", 12.0}, {"frame_time_us_median", 90.0}}),
  };
  EXPECT_EQ(engine::FindSweepBaseline(sweep["rows"]).row, 1u);
  EXPECT_TRUE(engine::FindSweepBaseline(sweep["rows"]).is_default);
  const std::string page = engine::SweepHtml(sweep);
  const XmlElement html = test::XmlReader::Parse(page, test::Markup::kDocument);  // throws when malformed
  EXPECT_EQ(html.name, "html");

  const std::vector<const XmlElement*> rows = TableRows(html);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(Attribute(*rows[1], "class"), "baseline");
  EXPECT_EQ(FindAll(*rows[0], "td").at(0)->text, "fewer <outliers>");
  // Columns: configuration, the two varied options (first appearance), then the metrics reported.
  const std::vector<const XmlElement*> header = FindAll(*FindAll(html, "thead").at(0), "th");
  ASSERT_EQ(header.size(), 1u + 2u + 4u);
  EXPECT_EQ(header[1]->text, "merge.top_k");
  EXPECT_EQ(header[2]->text, "score.mode");
  EXPECT_EQ(header[3]->text, "PCP (%)");
  EXPECT_EQ(header[4]->text, "MPJPE (mm)");
  // A row shows its own value, else the base value greyed.
  const std::vector<const XmlElement*> first = FindAll(*rows[0], "td");
  EXPECT_EQ(first[1]->text, "0");
  EXPECT_EQ(first[2]->text, "adaptive");
  EXPECT_EQ(Attribute(*first[2], "class"), "option inherited");

  // Deltas by hand: PCP 92.5 - 90 = +2.5 (better), MPJPE 55.25 - 50 = +5.25 (worse), Invalid
  // 10 - 10 = 0 (same), time 120 - 100 = +20 us (worse); row 3: MPJPE -1 (better), PCP missing.
  const auto delta = [&](size_t row, const std::string& metric) -> const XmlElement* {
    const XmlElement* cell = MetricCell(*rows[row], metric);
    if (cell == nullptr || cell->children.empty()) return nullptr;
    return &cell->children[0];
  };
  ASSERT_NE(delta(0, "pcp"), nullptr);
  EXPECT_EQ(Attribute(*delta(0, "pcp"), "data-delta"), "2.5000");
  EXPECT_EQ(Attribute(*delta(0, "pcp"), "class"), "delta better");
  EXPECT_EQ(delta(0, "pcp")->text, "+2.5");
  EXPECT_EQ(Attribute(*delta(0, "mpjpe_mm"), "data-delta"), "5.2500");
  EXPECT_EQ(Attribute(*delta(0, "mpjpe_mm"), "class"), "delta worse");
  EXPECT_EQ(Attribute(*delta(0, "invalid"), "class"), "delta same");
  EXPECT_EQ(delta(0, "invalid")->text, "\u00b10.0");
  EXPECT_EQ(Attribute(*delta(0, "frame_time_us_median"), "class"), "delta worse");
  EXPECT_EQ(delta(0, "frame_time_us_median")->text, "+20");
  EXPECT_EQ(Attribute(*delta(2, "mpjpe_mm"), "class"), "delta better");
  EXPECT_EQ(delta(2, "mpjpe_mm")->text, "\u22121.0");
  EXPECT_EQ(MetricCell(*rows[2], "pcp")->text, "-");
  EXPECT_EQ(delta(1, "pcp"), nullptr) << "no delta on the baseline row";

  // One chart per reported headline metric, one bar per configuration.
  const std::vector<const XmlElement*> charts = FindAll(html, "svg");
  ASSERT_EQ(charts.size(), 4u);
  for (const XmlElement* chart : charts) {
    int bars = 0;
    for (const XmlElement* g : FindAll(*chart, "g")) bars += Attribute(*g, "class").rfind("bar ", 0) == 0 ? 1 : 0;
    EXPECT_EQ(bars, 3) << Attribute(*chart, "data-metric");
  }
  EXPECT_EQ(Attribute(*charts[0], "data-metric"), "pcp");
  EXPECT_EQ(FindAll(*charts[0], "rect").size(), 2u) << "no bar for a missing value";
  EXPECT_NE(AllText(html).find("rpt sweep --list a&b.json"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos) << "no script, nothing to load";
}

TEST(SweepHtml, WithoutADefaultRowDeltasAreAgainstTheFirst) {
  nlohmann::ordered_json sweep;
  sweep["rows"] = {Row("a", {{"param.cameras", "3"}}, false, {{"pcp", 50.0}}),
                   Row("b", {{"param.cameras", "5"}}, false, {{"pcp", 75.0}})};
  EXPECT_EQ(engine::FindSweepBaseline(sweep["rows"]).row, 0u);
  EXPECT_FALSE(engine::FindSweepBaseline(sweep["rows"]).is_default);
  const XmlElement html = test::XmlReader::Parse(engine::SweepHtml(sweep), test::Markup::kDocument);
  const std::vector<const XmlElement*> rows = TableRows(html);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(Attribute(MetricCell(*rows[1], "pcp")->children.at(0), "data-delta"), "25.0000");
  EXPECT_NE(AllText(html).find("the first row: no configuration equals the base configuration"), std::string::npos);
}

// A row measured with other metrics options (e.g. fewer evaluated joints) shows its values but no
// difference: a lower MPJPE over 4 joints is not better than one over 13.
TEST(SweepHtml, ARowMeasuredDifferentlyShowsNoDifference) {
  nlohmann::ordered_json sweep;
  sweep["rows"] = {Row("default", nlohmann::ordered_json::object(), true, {{"mpjpe_mm", 50.0}}),
                   Row("arms", {{"metrics.evaluated_joints", "wrist_left,wrist_right"}}, false, {{"mpjpe_mm", 44.0}}),
                   Row("other", {{"merge.top_k", "0"}}, false, {{"mpjpe_mm", 51.0}})};
  sweep["rows"][1]["measured_differently"] = true;
  const XmlElement html = test::XmlReader::Parse(engine::SweepHtml(sweep), test::Markup::kDocument);
  const std::vector<const XmlElement*> rows = TableRows(html);
  ASSERT_EQ(rows.size(), 3u);
  const XmlElement& arms = MetricCell(*rows[1], "mpjpe_mm")->children.at(0);
  EXPECT_EQ(Attribute(arms, "class"), "delta incomparable");
  EXPECT_EQ(arms.text, "n/a");
  EXPECT_EQ(MetricCell(*rows[1], "mpjpe_mm")->text, "44.0 ");  // the value, then the "n/a" span
  EXPECT_EQ(Attribute(MetricCell(*rows[2], "mpjpe_mm")->children.at(0), "data-delta"), "1.0000");
  // Its bar is neither better nor worse either (it was green: 44 < 50).
  std::vector<std::string> bar_classes;
  for (const XmlElement* g : FindAll(*FindAll(html, "svg").at(0), "g")) bar_classes.push_back(Attribute(*g, "class"));
  EXPECT_EQ(bar_classes, (std::vector<std::string>{"bar baseline", "bar incomparable", "bar worse"}));
}

// Bars of values close together start below the smallest, so that their differences show, and the
// chart says so; the deltas are those of the shown values (38.447 vs 38.459 shows 38.4 vs 38.5:
// -0.1, better, not a grey ±0.0).
TEST(SweepHtml, CloseValuesGetAZoomedAxisAndDeltasOfTheShownValues) {
  nlohmann::ordered_json sweep;
  sweep["rows"] = {Row("default", nlohmann::ordered_json::object(), true, {{"mpjpe_mm", 38.459}, {"pcp", 10.0}}),
                   Row("top 5", {{"merge.top_k", "5"}}, false, {{"mpjpe_mm", 38.447}, {"pcp", 90.0}}),
                   Row("top 0", {{"merge.top_k", "0"}}, false, {{"mpjpe_mm", 41.0}, {"pcp", 50.0}})};
  const XmlElement html = test::XmlReader::Parse(engine::SweepHtml(sweep), test::Markup::kDocument);
  const std::vector<const XmlElement*> rows = TableRows(html);
  const XmlElement& close = MetricCell(*rows[1], "mpjpe_mm")->children.at(0);
  EXPECT_EQ(close.text, "\u22120.1");
  EXPECT_EQ(Attribute(close, "class"), "delta better");
  // MPJPE 38.447-41.0: the spread 2.553 is under a third of 41, so the bars start at
  // 38.447 - 2.553 / 2 = 37.17 (shown 37.2); PCP 10-90 starts at 0.
  std::string mpjpe_note, pcp_note;
  for (const XmlElement* chart : FindAll(html, "svg")) {
    std::string note;
    for (const XmlElement* text : FindAll(*chart, "text")) {
      if (Attribute(*text, "class") == "axis-start") note = text->text;
    }
    (Attribute(*chart, "data-metric") == "pcp" ? pcp_note : mpjpe_note) = note;
  }
  EXPECT_EQ(mpjpe_note, "bars start at 37.2, not 0");
  EXPECT_EQ(pcp_note, "");
  // The top-0 bar (41.0) is the longest, 260 px; top 5's (38.447) (38.447 - 37.1705) / (41 - 37.1705) of it.
  for (const XmlElement* chart : FindAll(html, "svg")) {
    if (Attribute(*chart, "data-metric") != "mpjpe_mm") continue;
    const std::vector<const XmlElement*> rects = FindAll(*chart, "rect");
    ASSERT_EQ(rects.size(), 3u);
    EXPECT_EQ(Attribute(*rects[2], "width"), "260.0");
    EXPECT_EQ(Attribute(*rects[1], "width"), "86.7");
  }
}

nlohmann::json ReadJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The sweep says which configurations change how they are measured, and marks their rows.
TEST(SweepHtml, SweepMarksConfigurationsThatChangeTheMetrics) {
  const fs::path out = test::TempDir("sweep_measured");
  const test::CommandResult r = test::RunRpt(
      "sweep --dataset synthetic --param frames=5 --grid metrics.match_threshold_mm=500,300 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: configuration 'metrics.match_threshold_mm=300' changes a metrics option"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("'metrics.match_threshold_mm=500' changes"), std::string::npos) << "500 is the default";
  const nlohmann::json sweep = ReadJson(out / "sweep.json");
  EXPECT_FALSE(sweep["rows"][0]["measured_differently"].get<bool>());
  EXPECT_TRUE(sweep["rows"][1]["measured_differently"].get<bool>());
  fs::remove_all(out);
}

TEST(SweepHtml, WrittenBySweepAndMergeWithDeltasMatchingSweepJson) {
  const fs::path out = test::TempDir("sweep_html");
  // filter.min_match_score defaults to 0.7: the second configuration is the default.
  const std::string grid =
      "--dataset synthetic --param frames=20 --grid filter.min_match_score=0.95,0.7 --out " + out.string();
  const test::CommandResult r = test::RunRpt("sweep " + grid);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("sweep.{json,csv,md,html}"), std::string::npos) << r.err;
  const nlohmann::json sweep = ReadJson(out / "sweep.json");
  ASSERT_EQ(sweep["rows"].size(), 2u);
  EXPECT_FALSE(sweep["rows"][0]["default"].get<bool>());
  EXPECT_TRUE(sweep["rows"][1]["default"].get<bool>());
  EXPECT_EQ(sweep["base"]["filter.min_match_score"], "0.7");
  EXPECT_EQ(sweep["base_options"]["filter"]["min_match_score"], 0.7) << "every option of the base configuration";
  const test::CommandResult report = test::RunRpt("report " + out.string());
  EXPECT_EQ(report.exit_code, 2);
  EXPECT_NE(report.err.find(" is the output folder of `rpt sweep`, whose report is its sweep.html"), std::string::npos)
      << report.err;
  // Options given with --set (or --config) are in base_options, the sweep's record of what it ran.
  const fs::path set_out = out / "with_set";
  ASSERT_EQ(test::RunRpt("sweep --dataset synthetic --param frames=5 --set group.max_distance_m=0.3 --grid "
                         "merge.top_k=0,3 --out " + set_out.string())
                .exit_code,
            0);
  EXPECT_EQ(ReadJson(set_out / "sweep.json")["base_options"]["group"]["max_distance_m"], 0.3);
  const XmlElement html = test::XmlReader::Parse(test::ReadAll(out / "sweep.html"), test::Markup::kDocument);
  const std::vector<const XmlElement*> rows = TableRows(html);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(Attribute(*rows[1], "class"), "baseline");
  for (const std::string metric : {"pcp", "mpjpe_mm", "recall500"}) {
    const double expected =
        sweep["rows"][0]["summary"][metric].get<double>() - sweep["rows"][1]["summary"][metric].get<double>();
    const XmlElement* cell = MetricCell(*rows[0], metric);
    ASSERT_NE(cell, nullptr) << metric;
    ASSERT_FALSE(cell->children.empty()) << metric;
    EXPECT_NEAR(std::stod(Attribute(cell->children[0], "data-delta")), expected, 1e-4) << metric;
  }

  ASSERT_EQ(test::RunRpt("sweep " + grid + " --shard 1/2").exit_code, 0);
  ASSERT_EQ(test::RunRpt("sweep " + grid + " --shard 2/2").exit_code, 0);
  const test::CommandResult merged =
      test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " " +
                   (out / "sweep-shard-2-of-2.json").string() + " --out " + (out / "m").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const XmlElement joined = test::XmlReader::Parse(test::ReadAll(out / "m" / "sweep.html"), test::Markup::kDocument);
  const std::vector<const XmlElement*> joined_rows = TableRows(joined);
  ASSERT_EQ(joined_rows.size(), 2u);
  EXPECT_EQ(Attribute(*joined_rows[1], "class"), "baseline");
  EXPECT_EQ(Attribute(MetricCell(*joined_rows[0], "mpjpe_mm")->children.at(0), "data-delta"),
            Attribute(MetricCell(*rows[0], "mpjpe_mm")->children.at(0), "data-delta"));
  fs::remove_all(out);
}

}  // namespace
}  // namespace rpt::cli
