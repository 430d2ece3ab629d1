// SPDX-License-Identifier: MIT
// `rpt report` without a browser: the page is self-contained, carries the run's frames (sampled to
// --max-frames), degrades with a warning when the run's input is gone, and bad input exits 2.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

#include "core/printable_text.h"
#include "engine/outputs/text_escaping.h"
#include "engine/report/report_run.h"
#include "tests/hostile_strings.h"
#include "tests/report/report_test_util.h"

namespace rpt::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const char* kSyntheticRun = "--dataset synthetic --param frames=40 --param people=3 --param cameras=4";

TEST(ReportCommand, SelfContainedPageWithSampledFrames) {
  const fs::path dir = TempDir("report_sampled");
  ASSERT_TRUE(EvalAndReport(kSyntheticRun, dir, "--max-frames 10"));
  const std::string html = ReadAll(dir / "report.html");
  // Opens offline: no external script, style sheet or image.
  EXPECT_FALSE(std::regex_search(html, std::regex(R"((src|href)\s*=\s*["']?(https?:)?//)", std::regex::icase)));
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_NE(html.find("Chart.js v3"), std::string::npos) << "Chart.js inlined";
  EXPECT_NE(html.find("OrbitControls"), std::string::npos) << "three.js controls inlined";

  const Json data = ReportData(html);
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["dataset"], "synthetic");
  EXPECT_TRUE(data["paper"].is_null()) << "the paper has no synthetic row";
  EXPECT_TRUE(data["input_loaded"].get<bool>());
  ASSERT_EQ(data["sequences"].size(), 1u);
  EXPECT_EQ(data["sequences"][0]["mpjpe_mm"].size(), 40u) << "the error plot has every frame";
  EXPECT_EQ(data["sequences"][0]["cameras"].size(), 4u);
  ASSERT_EQ(data["scenes"].size(), 10u) << "--max-frames bounds the frames with a scene";
  EXPECT_EQ(data["scenes"][0]["frame"], 0);
  EXPECT_EQ(data["scenes"][1]["frame"], 4) << "evenly spaced";
  EXPECT_EQ(data["scenes"][0]["views"].size(), 4u);
  // The scene's predictions are the recorded ones.
  const Json predictions = Json::parse(ReadAll(dir / "predictions.json"));
  EXPECT_EQ(data["scenes"][0]["predictions"].size(), predictions["frames"][0]["persons"].size());
  EXPECT_EQ(data["scenes"][0]["views"][0]["predictions"].size(), predictions["frames"][0]["persons"].size());
  // Per-frame matches add up to the summary's.
  const Json summary = Json::parse(ReadAll(dir / "summary.json"));
  long matched = 0;
  for (const Json& m : data["sequences"][0]["num_matched"]) matched += m.get<long>();
  EXPECT_EQ(matched, summary["matches"].get<long>());
  EXPECT_EQ(data["per_joint"].size(), 13u);
  EXPECT_FALSE(data["recall_curve"]["recall"].empty());
}

// per_joint.csv as the eval writer writes it (CsvField) with hostile joint names: a comma, a quote,
// a formula, a line break; `rpt report` reads it back with the same rules (issue 19: a comma made
// the report refuse its own eval's file).
// A right-to-left override in a name (here a PCP part's and a warning's) is shown as the text
// "\xe2\x80\xae", as every other output writes it: raw, it turned the rest of a camera's caption
// around ("reprojection error 16.6 px" read "xp 6.61 rorre noitcejorper").
TEST(ReportCommand, BidiOverridesInNamesAreShownAsText) {
  const fs::path dir = TempDir("report_bidi");
  ASSERT_TRUE(EvalAndReport(kSyntheticRun, dir, "--max-frames 2"));
  Json summary = Json::parse(ReadAll(dir / "summary.json"));
  summary["pcp_parts"] = {{"cam1\xe2\x80\xae part", 50.0}, {"isolate \xe2\x81\xa6x\xe2\x81\xa9", 40.0}};
  std::ofstream(dir / "summary.json") << summary.dump();
  ASSERT_EQ(RunRpt("report " + dir.string()).exit_code, 0);
  const std::string html = ReadAll(dir / "report.html");
  for (const std::string control : {"\xe2\x80\xae", "\xe2\x81\xa6", "\xe2\x81\xa9"}) {
    EXPECT_EQ(html.find(control), std::string::npos) << "a raw bidirectional control in the page";
  }
  const Json data = ReportData(html);
  EXPECT_TRUE(data.dump().find(R"(cam1\\xe2\\x80\\xae part)") != std::string::npos) << data.dump().substr(0, 3000);
  EXPECT_TRUE(data.dump().find(R"(isolate \\xe2\\x81\\xa6x\\xe2\\x81\\xa9)") != std::string::npos);
}

// A run into a folder holding a report.html keeps that page (the folder's other files are carried
// over), which shows the earlier run: said, with the command that makes this run's.
TEST(ReportCommand, ARerunSaysTheReportIsTheEarlierRuns) {
  const fs::path dir = TempDir("report_stale");
  ASSERT_TRUE(EvalAndReport(kSyntheticRun, dir, "--max-frames 2"));
  const CommandResult again = RunRpt("eval " + std::string(kSyntheticRun) + " --quiet --out " + dir.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("warning: " + dir.string() + "/report.html: the page of the earlier run here"),
            std::string::npos)
      << again.err;
  ASSERT_EQ(RunRpt("report " + dir.string()).exit_code, 0);
  const fs::path fresh = TempDir("report_stale_fresh");
  const CommandResult first = RunRpt("eval " + std::string(kSyntheticRun) + " --quiet --out " + fresh.string());
  EXPECT_EQ(first.err.find("report.html"), std::string::npos) << first.err;
}

TEST(ReportCommand, ReadsBackPerJointCsvWithCommasInJointNames) {
  const fs::path dir = TempDir("report_per_joint");
  ASSERT_EQ(
      RunRpt("eval --dataset synthetic --param frames=5 --param cameras=2 --quiet --out " + dir.string()).exit_code, 0);
  std::istringstream csv(ReadAll(dir / "per_joint.csv"));
  std::string header, line, rewritten;
  std::getline(csv, header);
  rewritten = header + "\n";
  std::vector<std::string> names;
  for (size_t row = 0; std::getline(csv, line); ++row) {
    const std::string name = HostileStrings()[row % HostileStrings().size()] + " joint " + std::to_string(row);
    names.push_back(PrintableText(name, LineBreaks::kEscape));
    rewritten += engine::CsvField(name) + line.substr(engine::CsvField(engine::SplitCsvLine(line)[0]).size()) + "\n";
  }
  ASSERT_GE(names.size(), 13u);
  std::ofstream(dir / "per_joint.csv") << rewritten;
  const CommandResult r = RunRpt("report " + dir.string() + " --max-frames 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json data = ReportData(ReadAll(dir / "report.html"));
  ASSERT_EQ(data["per_joint"].size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(data["per_joint"][i]["joint"], names[i]);
  EXPECT_TRUE(data["per_joint"][0]["mean_error_mm"].is_number()) << "the numbers stay in their columns";
}

TEST(ReportCommand, PaperRowForKnownDatasets) {
  // The page reads the paper's numbers from results/paper.json (embedded); a run of a dataset the paper
  // evaluated shows them. Rewriting run.json's dataset is enough: the input then fails to re-load.
  const fs::path dir = TempDir("report_paper");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3", dir));
  Json run = Json::parse(ReadAll(dir / "run.json"));
  run.erase("argv");  // as written before "argv" was recorded: "command" is read
  run["command"] = "rpt eval --dataset panoptic --root " + (dir / "no-such-folder").string();
  std::ofstream(dir / "run.json") << run.dump(2);
  const CommandResult r = RunRpt("report " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: the run's input could not be re-loaded"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no-such-folder"), std::string::npos) << "says why: " << r.err;
  const Json data = ReportData(ReadAll(dir / "report.html"));
  EXPECT_FALSE(data["input_loaded"].get<bool>());
  EXPECT_FALSE(data.contains("scenes"));
  ASSERT_TRUE(data["paper"].is_object());
  EXPECT_EQ(data["paper"]["mpjpe_mm"], 30.6);
  EXPECT_EQ(data["paper"]["recall500"], 99.8);
}

// Input paths with a space: run.json records the argument vector ("argv") beside the command line,
// and `rpt report` re-loads the input from it. Before, it split the one-string "command" at spaces,
// so such a path did not re-load; it still does so for a run.json without "argv" (older rpt).
TEST(ReportCommand, ReloadsInputWhosePathHoldsASpace) {
  const fs::path dir = TempDir("report_space");
  const fs::path cache = dir / "my data" / "cache.h5";
  fs::create_directories(cache.parent_path());
  const CommandResult convert =
      RunRpt("convert --dataset synthetic --param frames=6 --param cameras=3 --out '" + cache.string() + "'");
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const fs::path out = dir / "run";
  ASSERT_TRUE(EvalAndReport("--labels '" + cache.string() + "' --detections '" + cache.string() + "'", out));
  Json run = Json::parse(ReadAll(out / "run.json"));
  ASSERT_TRUE(run["argv"].is_array()) << run.dump(2);
  EXPECT_EQ(run["argv"][0], "rpt");
  EXPECT_EQ(run["argv"][1], "eval");
  EXPECT_NE(std::find(run["argv"].begin(), run["argv"].end(), Json(cache.string())), run["argv"].end())
      << "the path is one argument: " << run["argv"].dump();
  EXPECT_EQ(run["command"], "rpt eval --labels '" + cache.string() + "' --detections '" + cache.string() +
                                "' --quiet --out " + out.string())
      << "quoted as a shell reads it back (it can be pasted)";
  CommandResult r = RunRpt("report " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("could not be re-loaded"), std::string::npos) << r.err;
  Json data = ReportData(ReadAll(out / "report.html"));
  EXPECT_TRUE(data["input_loaded"].get<bool>());
  ASSERT_EQ(data["sequences"].size(), 1u);
  EXPECT_EQ(data["sequences"][0]["cameras"].size(), 3u);

  // A run.json without "argv": the command line is split at spaces, the cut path does not load,
  // and the page is written without the input, with the warning.
  run.erase("argv");
  std::ofstream(out / "run.json") << run.dump(2);
  r = RunRpt("report " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: the run's input could not be re-loaded"), std::string::npos) << r.err;
  EXPECT_FALSE(ReportData(ReadAll(out / "report.html"))["input_loaded"].get<bool>());

  // A damaged "argv" is named in the warning, not guessed around.
  run["argv"] = Json::array({"rpt", "eval", 7});
  std::ofstream(out / "run.json", std::ios::trunc) << run.dump(2);
  r = RunRpt("report " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find((out / "run.json").string() + ": /argv: expected a list of strings"), std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

// Relative input paths are the run's: `rpt report` re-loads them from the folder the run ran in
// (run.json's "working_directory"), wherever it is started.
TEST(ReportCommand, ReloadsRelativeInputPathsFromTheRunsFolder) {
  const fs::path dir = fs::absolute(TempDir("report_relative"));
  const CommandResult convert =
      RunRpt("convert --dataset synthetic --param frames=6 --param cameras=3 --out " + (dir / "cache.h5").string());
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const CommandResult eval =
      RunRpt("eval --labels cache.h5 --detections cache.h5 --quiet --out run", "cd '" + dir.string() + "' && ");
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  const Json run = Json::parse(ReadAll(dir / "run" / "run.json"));
  EXPECT_EQ(run["working_directory"], "..") << "relative to the run folder: no machine path in the file";
  const CommandResult r = RunRpt("report " + (dir / "run").string(), "cd / && ");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("could not be re-loaded"), std::string::npos) << r.err;
  EXPECT_TRUE(ReportData(ReadAll(dir / "run" / "report.html"))["input_loaded"].get<bool>());
  // The project moved as a whole (input and run folder together) still re-loads.
  const fs::path moved = dir.string() + "_moved";
  fs::rename(dir, moved);
  const CommandResult after = RunRpt("report " + (moved / "run").string(), "cd / && ");
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_TRUE(ReportData(ReadAll(moved / "run" / "report.html"))["input_loaded"].get<bool>()) << after.err;
  fs::remove_all(moved);
}

// A run exported with --no-filled-joints writes a filled joint as [null, null, null, 0]: report and
// render read it as missing (they refused the run: "found null in row 9").
TEST(ReportCommand, ReadsJointsTheExportDidNotWrite) {
  const fs::path dir = TempDir("report_unwritten");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3", dir));
  nlohmann::json predictions = nlohmann::json::parse(ReadAll(dir / "predictions.json"));
  predictions["frames"][0]["persons"][0][2] = {nullptr, nullptr, nullptr, 0};
  std::ofstream(dir / "predictions.json") << predictions.dump();
  CommandResult r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  predictions["frames"][0]["persons"][0][2] = {nullptr, nullptr, nullptr, 0.5};  // a score without a place
  std::ofstream(dir / "predictions.json") << predictions.dump();
  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("predictions.json: /frames/0/persons/0: expected 20x4 array of numbers"), std::string::npos)
      << r.err;
}

TEST(ReportCommand, BadInputExitsTwoNamingTheFile) {
  const fs::path dir = TempDir("report_bad");
  CommandResult r = RunRpt("report " + (dir / "missing").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing: not a folder"), std::string::npos) << r.err;

  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("summary.json: file not found"), std::string::npos) << r.err;

  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3", dir));
  std::ofstream(dir / "predictions.json") << R"({"joints": ["nose"], "frames": [{"id": "a", "persons": [[[1, 2]]], "track_ids": [0]}]})";
  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("predictions.json: /frames/0/persons/0"), std::string::npos) << r.err;

  // A track id rpt would not write (it became another id on the page and in rpt render), a score
  // above 1.
  for (const auto& [value, expected] : std::vector<std::pair<std::string, std::string>>{
           {"1e30", "/frames/0/track_ids/0: 1e+30 is not a track id (-1 or an integer from 0 to 2147483647)"},
           {"2147483648", "/frames/0/track_ids/0: 2147483648 is not a track id"},
           {"2.5", "/frames/0/track_ids/0: 2.5 is not a track id"},
           {"-2", "/frames/0/track_ids/0: -2 is not a track id"}}) {
    std::ofstream(dir / "predictions.json") << R"({"joints": ["nose"], "frames": [{"id": "a", "persons": [[[1, 2, 3, 0.5]]], "track_ids": [)"
                                            << value << "]}]}";
    r = RunRpt("report " + dir.string());
    EXPECT_EQ(r.exit_code, 2) << value;
    EXPECT_NE(r.err.find("predictions.json: " + expected), std::string::npos) << r.err;
  }
  std::ofstream(dir / "predictions.json") << R"({"joints": ["nose"], "frames": [{"id": "a", "persons": [[[1, 2, 3, 1e308]]], "track_ids": [0]}]})";
  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("predictions.json: /frames/0/persons/0/0/3: score 1e+308 outside [0, 1]"), std::string::npos)
      << r.err;

  std::ofstream(dir / "per_joint.csv") << "joint,mean_error_mm,pck100_pct,count,num_gt\nnose,12.5,x,3,4\n";
  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("per_joint.csv:2: 'x' is not a number"), std::string::npos) << r.err;

  // A summary whose numbers no run writes (edited by someone): refused as rpt merge refuses them,
  // not shown as "PCP NaN" or "-5 matches" beside plots that say otherwise.
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3", dir));
  const std::string good_summary = ReadAll(dir / "summary.json");
  for (const auto& [key, value, expected] : std::vector<std::tuple<std::string, nlohmann::json, std::string>>{
           {"pcp", "99.9", "/pcp: expected a number or null, got string"},
           {"matches", -5, "/matches: -5.0 is not a count or measure >= 0"},
           {"recall500", 140.0, "/recall500: 140.0 is not a percentage in [0, 100]"}}) {
    nlohmann::json summary = nlohmann::json::parse(good_summary);
    summary[key] = value;
    std::ofstream(dir / "summary.json") << summary.dump();
    r = RunRpt("report " + dir.string());
    EXPECT_EQ(r.exit_code, 2) << key;
    EXPECT_NE(r.err.find("summary.json: " + expected), std::string::npos) << r.err;
  }
  std::ofstream(dir / "summary.json") << good_summary;

  // --out naming a file of the run folder the report reads (or the folder): refused before anything
  // is written (`--out RUN/predictions.json` replaced the predictions with the page, exit 0). A page
  // of another name in the folder is fine.
  const std::string predictions_before = ReadAll(dir / "predictions.json");
  for (const fs::path& out : {dir / "predictions.json", dir, dir / "." / "summary.json"}) {
    r = RunRpt("report " + dir.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_NE(r.err.find("--out '" + out.string() + "': is "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("which this command reads"), std::string::npos) << r.err;
  }
  EXPECT_EQ(ReadAll(dir / "predictions.json"), predictions_before);
  r = RunRpt("report " + dir.string() + " --out " + (dir / "second.html").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;

  // The predictions of another run copied in: the page would draw them beside this run's summary.
  const fs::path other = TempDir("report_other_run");
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3", dir));
  ASSERT_TRUE(EvalAndReport("--dataset synthetic --param frames=3 --set filter.min_match_score=0.95", other));
  fs::copy_file(other / "predictions.json", dir / "predictions.json", fs::copy_options::overwrite_existing);
  r = RunRpt("report " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(dir.string() + ": summary.json is of run '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(", predictions.json of run '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the folder mixes the files of two runs"), std::string::npos) << r.err;

  // A run written without predictions: the message says why there is no predictions.json.
  fs::remove_all(other);
  const CommandResult bare = RunRpt("eval --dataset synthetic --param frames=3 --no-predictions --quiet --out " + other.string());
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  r = RunRpt("report " + other.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("predictions.json: not written: the run was made with --no-predictions"), std::string::npos)
      << r.err;
  // Exported as CSV only (for pandas): said, with the option to add (it read "file not found").
  fs::remove_all(other);
  const CommandResult csv = RunRpt("triangulate --dataset synthetic --param frames=3 --export csv --quiet --out " + other.string());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  r = RunRpt("report " + other.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("predictions.json: not written: the run was made with --export csv (run.json), without json; "
                       "the report reads predictions.json: run its command again with --export json,csv"),
            std::string::npos)
      << r.err;
  // Exported as json too, predictions.json deleted since: not "without json", the file is missing.
  fs::remove_all(other);
  ASSERT_EQ(RunRpt("triangulate --dataset synthetic --param frames=3 --export json,csv --quiet --out " + other.string())
                .exit_code,
            0);
  fs::remove(other / "predictions.json");
  r = RunRpt("report " + other.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.find("without json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("predictions.json"), std::string::npos) << r.err;
  fs::remove_all(other);
}

TEST(ReportCommand, MissingJavascriptLibraryNamesThePackage) {
  const fs::path dir = TempDir("report_nolib");
  const CommandResult eval = RunRpt("eval --dataset synthetic --param frames=3 --quiet --out " + dir.string());
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  ::setenv("RPT_JAVASCRIPT_DIR", (dir / "none").c_str(), 1);  // the child inherits it
  const CommandResult r = RunRpt("report " + dir.string());
  ::unsetenv("RPT_JAVASCRIPT_DIR");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("three/three.min.js: not found"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("libjs-three"), std::string::npos) << r.err;
}

// A camera at T = 1e308 (accepted with a warning) killed the 3D viewer: the page now lists cameras
// farther than 1000 km without a position; nearer ones keep theirs.
// Frame ids from file names that are not UTF-8: predictions.json holds them with U+FFFD in place of
// the bad bytes, and the re-loaded input's ids are compared as written there (report and render
// --run refused the run: "frame 0 of predictions.json is 'fr\xef\xbf\xbd...'").
TEST(ReportRun, FrameIdsThatAreNotUtf8MatchAsPredictionsJsonWroteThem) {
  engine::RecordedPredictions predictions;
  predictions.frame_ids = {"fr\xef\xbf\xbd\xef\xbf\xbd" "000", "plain"};
  predictions.frames.resize(2);
  std::vector<Sequence> sequences(1);
  sequences[0].frames.resize(2);
  sequences[0].frames[0].id = "fr\xff\xfe" "000";
  sequences[0].frames[1].id = "plain";
  std::vector<std::vector<Poses3D>> split;
  std::string why;
  EXPECT_TRUE(engine::SplitPredictions(predictions, sequences, &split, &why)) << why;
  sequences[0].frames[1].id = "other";
  EXPECT_FALSE(engine::SplitPredictions(predictions, sequences, &split, &why));
  EXPECT_NE(why.find("frame 1 of predictions.json is 'plain', the input's is 'other'"), std::string::npos) << why;
}

TEST(ReportData, FarCamerasHaveNoPositionInThePage) {
  const fs::path dir = TempDir("report_far_cameras");
  const std::string input = FarCameraInput(dir / "input", {{0, "1e308"}, {2, "2e6"}});
  ASSERT_TRUE(EvalAndReport(input, dir / "run"));
  const Json data = ReportData(ReadAll(dir / "run" / "report.html"));
  ASSERT_TRUE(data["input_loaded"].get<bool>());
  const Json& cameras = data["sequences"][0]["cameras"];
  ASSERT_EQ(cameras.size(), 4u);
  EXPECT_TRUE(cameras[0]["center"].is_null());
  EXPECT_TRUE(cameras[0]["corners"].is_null());
  EXPECT_TRUE(cameras[2]["center"].is_null()) << "2000 km: not drawn";
  for (int c : {1, 3}) {
    ASSERT_TRUE(cameras[c]["center"].is_array()) << c;
    for (const Json& v : cameras[c]["center"]) EXPECT_TRUE(v.is_number()) << c;
    ASSERT_EQ(cameras[c]["corners"].size(), 4u);
  }
  EXPECT_EQ(cameras[0]["width"], cameras[1]["width"]) << "still listed for its camera view";
  fs::remove_all(dir);
}

// --max-frames scenes of a large rig made pages of hundreds of MB: the scenes are kept under
// --max-scene-mb by carrying fewer frames, evenly spaced, with a warning.
TEST(ReportData, ScenesAreKeptUnderTheirShareOfThePage) {
  const fs::path dir = TempDir("report_scene_budget");
  ASSERT_TRUE(EvalAndReport(kSyntheticRun, dir));
  EXPECT_EQ(ReportData(ReadAll(dir / "report.html"))["scenes"].size(), 40u) << "within the default budget";
  const CommandResult small = RunRpt("report " + dir.string() + " --max-scene-mb 0.1");
  ASSERT_EQ(small.exit_code, 0) << small.err;
  const Json data = ReportData(ReadAll(dir / "report.html"));
  const size_t scenes = data["scenes"].size();
  EXPECT_GE(scenes, 1u);
  EXPECT_LT(scenes, 40u);
  EXPECT_NE(small.err.find(std::to_string(scenes) + " frames carry a 3D scene, not 40"), std::string::npos) << small.err;
  EXPECT_NE(small.err.find("--max-scene-mb"), std::string::npos) << small.err;
  EXPECT_LT(data["scenes"].dump().size(), 150000u) << "about the budget";
  EXPECT_EQ(RunRpt("report " + dir.string() + " --max-frames 100000").exit_code, 2) << "--max-frames is bounded";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::test
