// SPDX-License-Identifier: MIT
// The report in a real browser (headless Chromium; skipped when it is absent): no error on the
// console, the 3D viewer drew the expected skeletons on a non-blank canvas, the five plots and one
// view per camera exist; screenshots go to RPT_SCREENSHOT_DIR (or $RPT_REPORT_SCREENSHOTS), for
// docs/report.md. A small synthetic run always; the Shelf, Panoptic and MVOR fixtures when
// ../shared/data has them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "engine/outputs/text_escaping.h"
#include "tests/hostile_input.h"
#include "tests/report/report_test_util.h"
#include "tests/test_data.h"

namespace rpt::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

fs::path ScreenshotDir() {
  if (const char* env = std::getenv("RPT_REPORT_SCREENSHOTS"); env != nullptr && *env != '\0') return env;
  return RPT_SCREENSHOT_DIR;
}

#define RPT_REQUIRE_CHROMIUM()                                                                       \
  do {                                                                                               \
    if (ChromiumBinary().empty()) GTEST_SKIP() << "chromium not installed (scripts/install_deps.sh)"; \
  } while (0)

// The PCP-per-part table of a dumped page ("" when there is none).
std::string PcpPartsTable(const std::string& dom) {
  const size_t at = dom.find("id=\"pcp-parts-table\"");
  if (at == std::string::npos) return "";
  return dom.substr(at, dom.find("</table>", at) - at);
}

// Checks the page of `dir` in the browser and saves its screenshots as report_<name>_*.png.
void CheckInBrowser(const fs::path& dir, const std::string& name) {
  const fs::path page = dir / "report.html";
  const Json data = ReportData(ReadAll(page));
  ASSERT_TRUE(data.is_object());
  ASSERT_TRUE(data["input_loaded"].get<bool>());
  // The page opens on the frame with the most predictions (?scene=K), so that the check counts skeletons.
  size_t scene = 0;
  for (size_t k = 0; k < data["scenes"].size(); ++k) {
    if (data["scenes"][k]["predictions"].size() > data["scenes"][scene]["predictions"].size()) scene = k;
  }
  const Json& first = data["scenes"][scene];
  ASSERT_GT(first["predictions"].size(), 0u);
  const size_t cameras = data["sequences"][first["sequence"].get<int>()]["cameras"].size();
  size_t gt_evaluated = 0;
  for (const Json& gt : first["gt"]) gt_evaluated += gt["state"].get<int>() >= 0 ? 1 : 0;
  const std::string query = "?scene=" + std::to_string(scene);

  const std::string dom = DumpDom(page, query);
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM";
  const size_t errors_at = dom.find("id=\"rpt-errors\"");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-errors"), "0")
      << "console errors: " << dom.substr(errors_at, dom.find("</pre>", errors_at) - errors_at);
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-ready"), "1");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-plots"), "5") << "joints, recall, frames, step times, step counts";
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-skeletons"), std::to_string(first["predictions"].size()));
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-gt-skeletons"), std::to_string(gt_evaluated));
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-camera-views"), std::to_string(cameras));
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-frame"), first["id"].get<std::string>());
  // Each camera's caption gives the view's mean over its measured joints, the number rpt render's
  // legend shows (the page data's "mean_error_px" and "error_joints" of the view).
  for (size_t c = 0; c < cameras; ++c) {
    const Json& view = first["views"][c];
    char expected[96];
    if (view["error_joints"].get<long>() > 0) {
      std::snprintf(expected, sizeof expected, "reprojection error %.1f px (mean, %ld joints)",
                    view["mean_error_px"].get<double>(), view["error_joints"].get<long>());
    } else {
      std::snprintf(expected, sizeof expected, "no joint matched a detection");
    }
    EXPECT_NE(dom.find(expected), std::string::npos) << "camera " << c << ": " << expected;
  }
  const std::string nonblank = BodyAttribute(dom, "data-rpt-nonblank-pixels");
  ASSERT_FALSE(nonblank.empty()) << "the 3D viewer did not draw";
  EXPECT_GT(std::stol(nonblank), 2000) << "the 3D canvas is blank";
  EXPECT_EQ(dom.find("<canvas id=\"plot-frames\"") == std::string::npos, false);
  // PCP per part: one column per part of summary.json's "pcp_parts" (underscores as spaces), its value
  // with one decimal.
  const nlohmann::ordered_json summary = nlohmann::ordered_json::parse(ReadAll(dir / "summary.json"));  // the file's order
  const std::string parts = PcpPartsTable(dom);
  ASSERT_FALSE(parts.empty()) << "no PCP-per-part table";
  EXPECT_EQ(parts.find("hidden"), std::string::npos);
  ASSERT_GE(summary["pcp_parts"].size(), 5u);
  for (const auto& [part, value] : summary["pcp_parts"].items()) {
    std::string label = part;
    std::replace(label.begin(), label.end(), '_', ' ');
    EXPECT_NE(parts.find("<th>" + label + "</th>"), std::string::npos) << part;
    char cell[32];
    std::snprintf(cell, sizeof cell, "<td>%.1f</td>", value.get<double>());
    EXPECT_NE(parts.find(cell), std::string::npos) << part << " " << cell;
  }

  // Why the Invalid predictions are not matches: one sentence in the summary note, from
  // summary.json's "invalid_causes", only when there are any.
  const auto& causes = summary["invalid_causes"];
  const int unmatched = causes["duplicate"].get<int>() + causes["near_matched_gt"].get<int>() +
                        causes["near_missed_gt"].get<int>() + causes["far_from_gt"].get<int>() +
                        causes["no_gt"].get<int>();
  const std::string sentence = "Unmatched predictions (Invalid): " + std::to_string(unmatched) + " = " +
                               std::to_string(causes["duplicate"].get<int>()) + " duplicate, " +
                               std::to_string(causes["near_matched_gt"].get<int>()) + " beside a found person, " +
                               std::to_string(causes["near_missed_gt"].get<int>()) + " near a missed person, " +
                               std::to_string(causes["far_from_gt"].get<int>()) + " far from every GT person, " +
                               std::to_string(causes["no_gt"].get<int>()) + " without GT.";
  const size_t note_at = dom.find("id=\"summary-note\"");
  ASSERT_NE(note_at, std::string::npos);
  const std::string note = dom.substr(note_at, dom.find("</p>", note_at) - note_at);
  EXPECT_EQ(note.find(sentence) != std::string::npos, unmatched > 0) << note << "\nexpected: " << sentence;
  EXPECT_EQ(note.find("Unmatched predictions") != std::string::npos, unmatched > 0) << note;

  // With --loss-table: a row of the PCP-per-part table (the parts within reach of the best pair,
  // from summary.json's "loss_table.parts.per_part") and the categories in the summary note.
  const bool losses = summary.contains("loss_table");
  EXPECT_EQ(parts.find("best pair of the detections") != std::string::npos, losses);
  EXPECT_EQ(note.find("GT persons are lost") != std::string::npos, losses) << note;
  if (losses) {
    const auto& table = summary["loss_table"];
    const auto& categories = table["categories"];
    EXPECT_NE(note.find("Where the " + std::to_string(table["gt_persons"].get<int>()) + " GT persons are lost (--loss-table): " +
                        std::to_string(categories["found"].get<int>()) + " found, "),
              std::string::npos)
        << note;
    // The reach row follows the PCP row, part by part.
    std::string reach = "<td>best pair of the detections</td>";
    for (const auto& [part, value] : summary["pcp_parts"].items()) {
      const auto& counts = table["parts"]["per_part"][part];
      const double evaluated = counts["evaluated"].get<double>();
      char cell[32];
      std::snprintf(cell, sizeof cell, "<td>%.1f</td>",
                    100.0 * (evaluated - counts["beyond_best_pair"].get<double>()) / evaluated);
      reach += cell;
    }
    EXPECT_NE(parts.find(reach), std::string::npos) << parts << "\nexpected: " << reach;
  }

  // Screenshots (two more Chromium runs, about a third of this test's time each) for the synthetic
  // run always, for the fixtures when RPT_REPORT_SCREENSHOTS asks for them (docs/report.md).
  if (name != "synthetic" && std::getenv("RPT_REPORT_SCREENSHOTS") == nullptr) return;
  // A blank page compresses to about 6 kB; these hold tables, plots, skeletons and camera views.
  const fs::path plots = ScreenshotDir() / ("report_" + name + "_plots.png");
  const fs::path viewer = ScreenshotDir() / ("report_" + name + "_viewer.png");
  ASSERT_TRUE(Screenshot(page, query + "#only-summary+plots", plots, 1280, 1000));
  ASSERT_TRUE(Screenshot(page, query + "#only-viewer", viewer, 1280, 1100));
  EXPECT_GT(fs::file_size(plots), 40000u);
  EXPECT_GT(fs::file_size(viewer), 40000u);
}

TEST(ReportBrowser, SyntheticRun) {
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_synthetic");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=60 --param people=3 --param cameras=4", dir));
  CheckInBrowser(dir, "synthetic");
}

// The summary's warnings ({code, message} objects) are shown as their messages, not as JSON.
TEST(ReportBrowser, WarningsShowTheirMessages) {
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_warnings");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=10 --set filter.min_match_score=0.999", dir));
  const std::string dom = DumpDom(dir / "report.html");
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM";
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-errors"), "0");
  const size_t list = dom.find("id=\"warnings\"");
  ASSERT_NE(list, std::string::npos);
  const std::string warnings = dom.substr(list, dom.find("</ul>", list) - list);
  EXPECT_NE(warnings.find("<li>very low recall: Recall@500 is"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("code"), std::string::npos) << "a warning shown as JSON: " << warnings;
  fs::remove_all(dir);
}

TEST(ReportBrowser, ShelfFixture) {
  RPT_REQUIRE_CHROMIUM();
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  const fs::path dir = TempDir("report_browser_shelf");
  ASSERT_TRUE(EvalAndReport("--dataset shelf-4da --root " + SharedData("shelf/4d_association").string() + " --loss-table",
                            dir, "--max-frames 60"));
  CheckInBrowser(dir, "shelf");
}

TEST(ReportBrowser, PanopticFixture) {
  RPT_REQUIRE_CHROMIUM();
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const fs::path dir = TempDir("report_browser_panoptic");
  ASSERT_TRUE(EvalAndReport("--dataset panoptic --root " + SharedData("panoptic").string() +
                                " --param sequences=160906_band1 --param every=1 --simulate",
                            dir));
  CheckInBrowser(dir, "panoptic");
}

TEST(ReportBrowser, MvorFixture) {
  RPT_REQUIRE_CHROMIUM();
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const fs::path dir = TempDir("report_browser_mvor");
  ASSERT_TRUE(EvalAndReport("--dataset mvor --root " + SharedData("mvor").string(), dir, "--max-frames 60"));
  CheckInBrowser(dir, "mvor");
}

// Issue 19: "<!--<script>" in a camera, scene, frame id, joint name or input path blanked the page
// while the error counter stayed 0. Every hostile string in those places: the page loads, draws and
// counts no error; the names are shown as text.
TEST(ReportBrowser, HostileNamesLoadWithoutErrors) {
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_hostile");
  const HostileInput input = MakeHostileInput(dir);
  const fs::path run = dir / "run <!--<script>";
  ASSERT_EQ(RunRpt("eval " + input.args() + " --quiet --out '" + run.string() + "'").exit_code, 0);
  std::istringstream csv(ReadAll(run / "per_joint.csv"));
  std::string header, line, rewritten;
  std::getline(csv, header);
  rewritten = header + "\n";
  for (size_t row = 0; std::getline(csv, line); ++row) {
    const std::string name = HostileStrings()[row % HostileStrings().size()] + " " + std::to_string(row);
    rewritten += engine::CsvField(name) + line.substr(engine::CsvField(engine::SplitCsvLine(line)[0]).size()) + "\n";
  }
  std::ofstream(run / "per_joint.csv") << rewritten;
  Json summary = Json::parse(ReadAll(run / "summary.json"));
  Json hostile_parts = Json::object();
  for (size_t k = 0; k < HostileStrings().size(); ++k) hostile_parts[HostileStrings()[k] + " part"] = 50.0 + k;
  summary["pcp_parts"] = hostile_parts;
  std::ofstream(run / "summary.json") << summary.dump(-1, ' ', false, Json::error_handler_t::replace);
  const CommandResult report = RunRpt("report '" + run.string() + "'");
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string dom = DumpDom(run / "report.html");
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM";
  const size_t errors_at = dom.find("id=\"rpt-errors\"");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-errors"), "0")
      << (errors_at == std::string::npos ? dom.substr(0, 2000) : dom.substr(errors_at, 2000));
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-ready"), "1");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-camera-views"), std::to_string(input.cameras.size()));
  EXPECT_NE(dom.find("&lt;!--&lt;script&gt;"), std::string::npos) << "the names are text, not markup";
  EXPECT_NE(PcpPartsTable(dom).find("&lt;!--&lt;script&gt; part"), std::string::npos) << "part names are text";
}

TEST(ReportBrowser, RunWhoseInputIsGone) {
  // The recorded tables only: the page still loads without errors, with the plots it has data for.
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_no_input");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=5", dir));
  Json run = Json::parse(ReadAll(dir / "run.json"));
  run["command"] = "rpt eval --dataset shelf --root " + (dir / "gone").string();
  run["argv"] = Json::array({"rpt", "eval", "--dataset", "shelf", "--root", (dir / "gone").string()});
  std::ofstream(dir / "run.json") << run.dump(2);
  const CommandResult r = RunRpt("report " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string dom = DumpDom(dir / "report.html");
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM";
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-errors"), "0") << dom.substr(dom.find("id=\"rpt-errors\""), 2000);
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-ready"), "1");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-plots"), "4") << "joints, recall, step times, step counts; no frames";
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-skeletons"), "");
  EXPECT_NE(dom.find("Frames: not available"), std::string::npos);
  // The plots made from the re-loaded input say why they are empty (the markup, not the script's text).
  EXPECT_NE(dom.find("<span class=\"caption-note\">: not available (the run's input could not be re-loaded)</span>"),
            std::string::npos);
}

// A run without ground truth (rpt triangulate): the frames plot marks the frame shown on the
// persons axis. It threw (the marker was the 4th series, which such a run does not have) and the
// page stopped drawing.
TEST(ReportBrowser, TriangulateRunWithoutGroundTruth) {
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_triangulate");
  const CommandResult run = RunRpt("triangulate --dataset synthetic --param frames=20 --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CommandResult r = RunRpt("report " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string dom = DumpDom(dir / "report.html", "?scene=3");
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM";
  const size_t errors_at = dom.find("id=\"rpt-errors\"");
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-errors"), "0")
      << "console errors: " << dom.substr(errors_at, dom.find("</pre>", errors_at) - errors_at);
  EXPECT_EQ(BodyAttribute(dom, "data-rpt-ready"), "1");
  EXPECT_NE(BodyAttribute(dom, "data-rpt-skeletons"), "0");
  // No GT: the legends name neither GT nor invalid predictions (the page itself has the words).
  EXPECT_EQ(dom.find("GT, missed"), std::string::npos);
  EXPECT_EQ(dom.find("reprojected GT"), std::string::npos);
  EXPECT_NE(dom.find("2D detection"), std::string::npos);
  fs::remove_all(dir);
}

// Cameras at T = 1e308 and 2e6 m (accepted with warnings): the viewer drew a grid of 1e308 lines
// (RangeError) and stopped; now the page has no console error and draws the near cameras.
TEST(ReportBrowser, FarCamerasDoNotBreakTheViewer) {
  RPT_REQUIRE_CHROMIUM();
  const fs::path dir = TempDir("report_browser_far");
  const std::string input = FarCameraInput(dir / "input", {{0, "1e308"}, {2, "2e6"}});
  ASSERT_TRUE(EvalAndReport(input, dir / "run"));
  CheckInBrowser(dir / "run", "far_cameras");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::test
