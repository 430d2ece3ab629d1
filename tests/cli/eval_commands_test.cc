// SPDX-License-Identifier: MIT
// rpt eval / check / sweep / merge end to end on the built-in synthetic dataset.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <thread>
#include <algorithm>

#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;


nlohmann::json ReadJson(const fs::path& path) { return nlohmann::json::parse(test::ReadAll(path)); }

TEST(EvalCommand, SyntheticRunWritesEveryOutput) {
  const fs::path out = test::TempDir("eval");
  const test::CommandResult r =
      test::RunRpt("eval --dataset synthetic --param frames=40 --param people=3 --out " + out.string() + " --json --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  for (const char* key : {"pcp", "pck100", "pck500", "mpjpe_mm", "recall100", "recall500", "invalid", "f1", "fps", "frames"}) {
    EXPECT_TRUE(summary.contains(key)) << key;
  }
  EXPECT_EQ(summary["frames"], 40);
  EXPECT_GT(summary["recall500"].get<double>(), 99.0);
  for (const char* file : {"summary.json", "summary.csv", "summary.md", "per_joint.csv", "config.json", "run.json",
                           "predictions.json"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const nlohmann::json predictions = ReadJson(out / "predictions.json");
  ASSERT_EQ(predictions["frames"].size(), 40u);
  EXPECT_EQ(predictions["joints"].size(), 20u);
  EXPECT_EQ(predictions["frames"][0]["id"], "synthetic_000000");
  EXPECT_EQ(predictions["frames"][5]["persons"].size(), predictions["frames"][5]["track_ids"].size());
  EXPECT_EQ(predictions["frames"][5]["persons"][0][0].size(), 4u) << "x, y, z, score";
  const nlohmann::json run = ReadJson(out / "run.json");
  EXPECT_TRUE(run.contains("git_revision"));
  EXPECT_TRUE(run.contains("cpu"));
  // What the input options resolved to: given, by default, and nothing else.
  EXPECT_EQ(run["input_settings"]["reader"], "synthetic");
  EXPECT_EQ(run["input_settings"]["param.frames"], "40");
  EXPECT_EQ(run["input_settings"]["param.people"], "3");
  EXPECT_EQ(run["input_settings"]["param.cameras"], "5");
  EXPECT_EQ(run["input_settings"]["param.noise"], "realistic");
  EXPECT_FALSE(run["input_settings"].contains("detector")) << "no --simulate";
  EXPECT_EQ(ReadJson(out / "summary.json")["f1"], summary["f1"]);
  EXPECT_NE(test::ReadAll(out / "per_joint.csv").find("wrist_left"), std::string::npos);
  fs::remove_all(out);
}

TEST(EvalCommand, BadInputExitsWith2AndNamesTheProblem) {
  const test::CommandResult unknown = test::RunRpt("eval --dataset nosuch --quiet");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown dataset 'nosuch'"), std::string::npos) << unknown.err;
  const test::CommandResult param = test::RunRpt("eval --dataset synthetic --param camras=3 --quiet");
  EXPECT_EQ(param.exit_code, 2);
  EXPECT_NE(param.err.find("camras"), std::string::npos) << param.err;
  const test::CommandResult labels = test::RunRpt("eval --labels /nonexistent/labels.json --simulate --quiet");
  EXPECT_EQ(labels.exit_code, 2);
  EXPECT_NE(labels.err.find("/nonexistent/labels.json"), std::string::npos) << labels.err;
  EXPECT_EQ(test::RunRpt("eval --quiet").exit_code, 2) << "neither --dataset nor --labels";
}

TEST(CheckCommand, PassesAtAchievedFloorsAndFailsAboveThem) {
  const fs::path dir = test::TempDir("check");
  fs::create_directories(dir);
  auto write = [&](const std::string& name, double floor) {
    std::ofstream(dir / name) << R"({"evaluations": [{"name": "tiny", "dataset": "synthetic",
        "params": {"frames": 30, "people": 2, "noise": "clean"}, "min": {"recall500": )" << floor << R"(}, "max": {"mpjpe_mm": 40}},
        {"name": "absent data", "dataset": "shelf", "root": "no/such/folder", "simulate": true, "min": {"pcp": 1}}]})";
  };
  write("pass.json", 90.0);
  write("fail.json", 100.1);
  const test::CommandResult pass = test::RunRpt("check --thresholds " + (dir / "pass.json").string());
  EXPECT_EQ(pass.exit_code, 0) << pass.out << pass.err;
  EXPECT_NE(pass.out.find("skipped"), std::string::npos);
  const test::CommandResult fail = test::RunRpt("check --thresholds " + (dir / "fail.json").string());
  EXPECT_EQ(fail.exit_code, 1) << fail.out << fail.err;
  EXPECT_NE(fail.out.find("FAILED"), std::string::npos);
  std::ofstream(dir / "bad.json") << R"({"evaluations": [{"name": "x", "dataset": "synthetic", "min": {"nonsense": 1}}]})";
  EXPECT_EQ(test::RunRpt("check --thresholds " + (dir / "bad.json").string()).exit_code, 2);
  fs::remove_all(dir);
}

TEST(SweepCommand, TwoConfigurationsGiveTwoRowsThatDifferWhereTheOptionMatters) {
  const fs::path out = test::TempDir("sweep");
  const test::CommandResult r = test::RunRpt("sweep --dataset synthetic --param frames=30 --grid merge.top_k=0,2 --out " +
                                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json sweep = ReadJson(out / "sweep.json");
  ASSERT_EQ(sweep["rows"].size(), 2u);
  EXPECT_EQ(sweep["rows"][0]["set"]["merge.top_k"], "0");
  EXPECT_NE(sweep["rows"][0]["summary"]["mpjpe_mm"], sweep["rows"][1]["summary"]["mpjpe_mm"]);
  EXPECT_EQ(sweep["rows"][0]["summary"]["recall500"], sweep["rows"][1]["summary"]["recall500"]);
  EXPECT_TRUE(fs::exists(out / "sweep.csv"));
  EXPECT_TRUE(fs::exists(out / "sweep.md"));
  EXPECT_EQ(test::RunRpt("sweep --dataset synthetic --grid merge.topk=1,2 --out " + out.string()).exit_code, 2);
  EXPECT_TRUE(sweep["rows"][0]["summary"]["warnings"].empty()) << "nothing to say of a good configuration";
  fs::remove_all(out);
}

// A configuration that triangulates nobody says so as rpt eval would: a warning after the table,
// in its row's summary (as in summary.json) and on sweep.html.
TEST(SweepCommand, AConfigurationWithoutPredictionsIsWarnedAbout) {
  const fs::path out = test::TempDir("sweep_warned");
  std::ofstream(out / "list.json") << R"([{"name": "none left", "set": {"postprocess.min_valid_joints": 1000}}, {"name": "fine"}])";
  const test::CommandResult r = test::RunRpt("sweep --dataset synthetic --param frames=5 --list " +
                                             (out / "list.json").string() + " --out " + (out / "s").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: configuration 'none left': no predictions at all"), std::string::npos) << r.err;
  const nlohmann::json sweep = ReadJson(out / "s" / "sweep.json");
  ASSERT_EQ(sweep["rows"][0]["summary"]["warnings"].size(), 1u);
  EXPECT_EQ(sweep["rows"][0]["summary"]["warnings"][0]["code"], "no_predictions");
  EXPECT_TRUE(sweep["rows"][1]["summary"]["warnings"].empty());
  EXPECT_NE(test::ReadAll(out / "s" / "sweep.html").find("<li><b>none left</b>: no predictions at all"),
            std::string::npos);
  fs::remove_all(out);
}

TEST(SweepCommand, ShardsMergeIntoTheFullTable) {
  const fs::path out = test::TempDir("shards");
  const std::string grid = "--dataset synthetic --param frames=20 --grid filter.min_match_score=0.8,0.9,0.95 --out " + out.string();
  const test::CommandResult full = test::RunRpt("sweep " + grid);
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const nlohmann::json whole = ReadJson(out / "sweep.json");
  ASSERT_EQ(test::RunRpt("sweep " + grid + " --shard 1/2").exit_code, 0);
  ASSERT_EQ(test::RunRpt("sweep " + grid + " --shard 2/2").exit_code, 0);
  EXPECT_EQ(ReadJson(out / "sweep-shard-1-of-2.json")["rows"].size(), 2u);
  EXPECT_EQ(test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " --out " + (out / "m1").string()).exit_code, 2)
      << "a missing shard is an error";
  const test::CommandResult merged = test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " " +
                                                  (out / "sweep-shard-2-of-2.json").string() + " --out " + (out / "m").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const nlohmann::json joined = ReadJson(out / "m" / "sweep.json");
  ASSERT_EQ(joined["rows"].size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(joined["rows"][i]["name"], whole["rows"][i]["name"]);
    EXPECT_EQ(joined["rows"][i]["summary"]["mpjpe_mm"], whole["rows"][i]["summary"]["mpjpe_mm"]);
  }
  // The merged file keeps what each shard recorded of its run, and what it is a shard of.
  ASSERT_EQ(joined["shard_runs"].size(), 2u);
  EXPECT_NE(joined["shard_runs"][1]["command"].get<std::string>().find("--shard 2/2"), std::string::npos);
  EXPECT_EQ(joined["sweep"], ReadJson(out / "sweep-shard-1-of-2.json")["sweep"]);
  EXPECT_NE(test::ReadAll(out / "m" / "sweep.html").find("--shard 2/2"), std::string::npos) << "the page lists the shards";
  // A shard of another sweep (other frames, other base options, another grid) is refused, named.
  const std::vector<std::pair<std::string, std::string>> others = {
      {"--dataset synthetic --param frames=21 --grid filter.min_match_score=0.8,0.9,0.95", "/sweep/input"},
      {"--dataset synthetic --param frames=20 --set merge.top_k=2 --grid filter.min_match_score=0.8,0.9,0.95",
       "/sweep/base_config"},
      {"--dataset synthetic --param frames=20 --grid filter.min_match_score=0.8,0.9,0.97", "/sweep/configurations"}};
  for (const auto& [other, part] : others) {
    ASSERT_EQ(test::RunRpt("sweep " + other + " --shard 2/2 --out " + (out / "other").string()).exit_code, 0) << other;
    const test::CommandResult mixed = test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " " +
                                                   (out / "other" / "sweep-shard-2-of-2.json").string() + " --out " +
                                                   (out / "mixed").string());
    EXPECT_EQ(mixed.exit_code, 2) << other;
    EXPECT_NE(mixed.err.find((out / "other" / "sweep-shard-2-of-2.json").string() + ": a shard of another sweep than " +
                             (out / "sweep-shard-1-of-2.json").string() + " (their " + part + " differ)"),
              std::string::npos)
        << mixed.err;
  }
  // Shards run by different builds of rpt are merged with a warning naming both revisions.
  nlohmann::json rebuilt = ReadJson(out / "sweep-shard-2-of-2.json");
  rebuilt["run"]["git_revision"] = "0123456789ab";
  std::ofstream(out / "rebuilt.json") << rebuilt.dump();
  const test::CommandResult revisions = test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " " +
                                                     (out / "rebuilt.json").string() + " --out " + (out / "mr").string());
  EXPECT_EQ(revisions.exit_code, 0) << revisions.err;
  EXPECT_NE(revisions.err.find("warning: merge: the shards were run by different revisions of rpt ("), std::string::npos)
      << revisions.err;
  EXPECT_NE(revisions.err.find("0123456789ab in " + (out / "rebuilt.json").string()), std::string::npos) << revisions.err;
  EXPECT_EQ(merged.err.find("different revisions"), std::string::npos) << "one build: no warning";
  // Missing configurations are counted from 1, as --shard counts.
  const test::CommandResult missing =
      test::RunRpt("merge " + (out / "sweep-shard-1-of-2.json").string() + " --out " + (out / "m1").string());
  EXPECT_NE(missing.err.find("counted from 1 as --shard counts: 2 of 3"), std::string::npos) << missing.err;
  fs::remove_all(out);
}

// A configuration that fails when it runs costs only its own row: the others are written, its row
// carries the error (empty CSV fields, a section of sweep.html), and the command exits 2 naming it.
// `rpt merge` carries the row over and exits 2 too.
// A setting without effect in one configuration is that configuration's warning: named when
// printed, kept in its row of sweep.json (and so on sweep.html), absent from the others.
TEST(SweepCommand, SettingsWithoutEffectAreTheirConfigurationsWarnings) {
  const fs::path out = test::TempDir("sweep_no_effect");
  const test::CommandResult r = test::RunRpt("sweep --dataset synthetic --param frames=5 --grid track.enabled=true,false "
                                             "--grid smooth.mode=off,causal --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: configuration 'track.enabled=false smooth.mode=causal': smooth.mode=causal has no "
                       "effect with track.enabled=false (it needs track ids)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("\nwarning: clip_speed"), std::string::npos) << "no unnamed lines: " << r.err;
  const nlohmann::json sweep = nlohmann::json::parse(test::ReadAll(out / "sweep.json"));
  ASSERT_EQ(sweep["rows"].size(), 4u);
  const auto codes = [&](int row) {
    std::vector<std::string> found;
    for (const auto& w : sweep["rows"][row]["summary"]["warnings"]) found.push_back(w["code"]);
    return std::count(found.begin(), found.end(), "option_without_effect");
  };
  EXPECT_EQ(codes(0), 0);
  EXPECT_EQ(codes(1), 0);
  EXPECT_EQ(codes(2), 0) << "clip_speed is on by default: an ablation that turns tracking off is no mistake";
  EXPECT_EQ(codes(3), 1) << "smooth";
  EXPECT_NE(test::ReadAll(out / "sweep.html").find("smooth.mode=causal has no effect"), std::string::npos);
  fs::remove_all(out);
}

// MVOR's param.evaluated=paper adds the head to the evaluated joints: that row is measured
// differently (no deltas), as a metrics.* axis is.
TEST(SweepCommand, AParamAxisThatChangesTheEvaluatedJointsIsMeasuredDifferently) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const fs::path out = test::TempDir("sweep_evaluated");
  const test::CommandResult r = test::RunRpt("sweep --dataset mvor --root " + test::SharedData("mvor").string() +
                                             " --param days=3 --grid param.evaluated=arms_torso,paper --out " +
                                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: configuration 'param.evaluated=paper' evaluates other joints (nose, shoulder_left"),
            std::string::npos)
      << r.err;
  const nlohmann::json sweep = nlohmann::json::parse(test::ReadAll(out / "sweep.json"));
  EXPECT_FALSE(sweep["rows"][0]["measured_differently"].get<bool>());
  EXPECT_TRUE(sweep["rows"][1]["measured_differently"].get<bool>());
  fs::remove_all(out);
}

TEST(SweepCommand, AFailingConfigurationKeepsTheOthersRows) {
  const fs::path out = test::TempDir("sweep_failing");
  const std::string grid = "--dataset synthetic --param frames=5 --grid triangulate.max_persons_per_view=100,1,102";
  const test::CommandResult r = test::RunRpt("sweep " + grid + " --out " + (out / "s").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("error: --grid (configuration 'triangulate.max_persons_per_view=1', 2 of the sweep): synthetic: "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 of 3 configurations failed to run (above); the others ran"), std::string::npos) << r.err;
  const nlohmann::json sweep = ReadJson(out / "s" / "sweep.json");
  ASSERT_EQ(sweep["rows"].size(), 3u);
  EXPECT_FALSE(sweep["rows"][0].contains("error"));
  EXPECT_GT(sweep["rows"][0]["summary"]["recall500"].get<double>(), 90.0);
  EXPECT_NE(sweep["rows"][1]["error"].get<std::string>().find("above triangulate.max_persons_per_view (1)"),
            std::string::npos);
  EXPECT_TRUE(sweep["rows"][1]["summary"].empty());
  EXPECT_EQ(sweep["rows"][2]["summary"]["recall500"], sweep["rows"][0]["summary"]["recall500"]);
  const std::string csv = test::ReadAll(out / "s" / "sweep.csv");
  EXPECT_NE(csv.find("\ntriangulate.max_persons_per_view=1,,,"), std::string::npos) << csv;
  EXPECT_NE(test::ReadAll(out / "s" / "sweep.html").find("<h2>Failed configurations</h2>"), std::string::npos);
  for (int k = 1; k <= 2; ++k) {
    EXPECT_EQ(test::RunRpt("sweep " + grid + " --shard " + std::to_string(k) + "/2 --out " + (out / "sh").string()).exit_code,
              k == 1 ? 0 : 2);
  }
  const test::CommandResult merged = test::RunRpt("merge " + (out / "sh" / "sweep-shard-1-of-2.json").string() + " " +
                                                  (out / "sh" / "sweep-shard-2-of-2.json").string() + " --out " +
                                                  (out / "m").string());
  EXPECT_EQ(merged.exit_code, 2) << merged.err;
  EXPECT_NE(merged.err.find("error: configuration 'triangulate.max_persons_per_view=1', 2 of the sweep: synthetic: "),
            std::string::npos)
      << merged.err;
  EXPECT_EQ(ReadJson(out / "m" / "sweep.json")["rows"][1]["error"], sweep["rows"][1]["error"]);
  fs::remove_all(out);
}

// --shard 1/1 writes its shard file (a job array of one task merges as any other); --threads is
// recorded as used; a merge of shards of two builds fails with --strict; a file whose rows are not
// those of its "shard" is refused.
TEST(SweepCommand, ShardFilesThreadsAndStrictMerge) {
  const fs::path out = test::TempDir("sweep_shard_one");
  const std::string grid = "--dataset synthetic --param frames=5 --grid merge.top_k=0,3,5";
  const test::CommandResult one = test::RunRpt("sweep " + grid + " --shard 1/1 --threads 2 --out " + out.string());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(fs::exists(out / "sweep-shard-1-of-1.json"));
  EXPECT_FALSE(fs::exists(out / "sweep.json"));
  EXPECT_NE(one.err.find("tables in " + out.string() + "/sweep-shard-1-of-1."), std::string::npos)
      << "where the tables went is a status line (stderr): " << one.err;
  EXPECT_EQ(one.out.find("tables in"), std::string::npos) << one.out;
  const nlohmann::json shard = ReadJson(out / "sweep-shard-1-of-1.json");
  EXPECT_EQ(shard["run"]["threads"], std::min(2u, std::max(1u, std::thread::hardware_concurrency())));
  ASSERT_EQ(test::RunRpt("merge " + (out / "sweep-shard-1-of-1.json").string() + " --out " + out.string()).exit_code, 0);
  EXPECT_EQ(ReadJson(out / "sweep.json")["rows"].size(), 3u);

  for (int k = 1; k <= 3; ++k) {
    ASSERT_EQ(test::RunRpt("sweep " + grid + " --shard " + std::to_string(k) + "/3 --out " + out.string()).exit_code, 0);
  }
  nlohmann::json other_build = ReadJson(out / "sweep-shard-3-of-3.json");
  other_build["run"]["git_revision"] = "0123456789ab";
  std::ofstream(out / "other_build.json") << other_build.dump();
  const std::string first_two =
      (out / "sweep-shard-1-of-3.json").string() + " " + (out / "sweep-shard-2-of-3.json").string() + " ";
  EXPECT_EQ(test::RunRpt("merge " + first_two + (out / "other_build.json").string() + " --out " + (out / "m").string())
                .exit_code,
            0);
  const test::CommandResult strict =
      test::RunRpt("merge " + first_two + (out / "other_build.json").string() + " --strict --out " + (out / "m").string());
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("different revisions of rpt"), std::string::npos) << strict.err;
  nlohmann::json renamed = ReadJson(out / "sweep-shard-3-of-3.json");
  renamed["shard"] = "2/3";
  std::ofstream(out / "renamed.json") << renamed.dump();
  const test::CommandResult wrong = test::RunRpt("merge " + (out / "sweep-shard-1-of-3.json").string() + " " +
                                                 (out / "renamed.json").string() + " --out " + (out / "m").string());
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("renamed.json: /rows/0/index: configuration 3 is not one of shard 2/3"), std::string::npos)
      << wrong.err;
  fs::remove_all(out);
}

// --seed seeds the simulated detector only: without --simulate it changed nothing, silently.
TEST(EvalCommand, SeedWithoutSimulateIsRefused) {
  const test::CommandResult r = test::RunRpt("eval --dataset synthetic --param frames=2 --seed 5 --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--seed seeds the simulated detector: it needs --simulate"), std::string::npos) << r.err;
  const fs::path out = test::TempDir("seeded") / "out";
  EXPECT_EQ(test::RunRpt("eval --dataset synthetic --param frames=2 --simulate --seed 5 --quiet --out " + out.string())
                .exit_code,
            0);
  const nlohmann::json settings = ReadJson(out / "run.json")["input_settings"];
  EXPECT_EQ(settings["detector"], "realistic") << "the default profile, recorded";
  EXPECT_EQ(settings["seed"], "5");
}

// Whole-body groups say what each number is over: joints and matched persons, in summary.json and
// on the terminal; with body-only predictions "All" is over their 17 joints.
TEST(EvalCommand, WholeBodyGroupsNameTheirJointsAndPersons) {
  const fs::path out = test::TempDir("wholebody_counts");
  const test::CommandResult whole = test::RunRpt(
      "eval --dataset synthetic --param frames=3 --param people=2 --param joints=wholebody --out " + out.string());
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const nlohmann::json counts = ReadJson(out / "summary.json")["wholebody_counts"];
  EXPECT_EQ(counts["All"]["joints"], 133);
  EXPECT_EQ(counts["Body"]["joints"], 23);
  EXPECT_EQ(counts["Face"]["joints"], 68);
  EXPECT_EQ(counts["Hands"]["joints"], 42);
  EXPECT_EQ(counts["Face"]["persons"], 6) << "2 people x 3 frames, all matched";
  EXPECT_NE(whole.out.find("whole-body MPJPE Face"), std::string::npos) << whole.out;
  EXPECT_NE(whole.out.find("(68 joints, 6 persons)"), std::string::npos) << whole.out;
  const test::CommandResult body = test::RunRpt("eval --dataset synthetic --param frames=3 --param people=2 --out " +
                                                (out / "body").string());
  ASSERT_EQ(body.exit_code, 0) << body.err;
  const nlohmann::json body_counts = ReadJson(out / "body" / "summary.json")["wholebody_counts"];
  EXPECT_EQ(body_counts["All"]["joints"], 17);
  EXPECT_EQ(body_counts["Face"]["persons"], 0);
  EXPECT_LT(counts["Face"]["filled_share"].get<double>(), 0.1);
  EXPECT_EQ(whole.err.find("wholebody_group_filled"), std::string::npos);
  EXPECT_EQ(whole.err.find("filled from a neighbour"), std::string::npos) << whole.err;
  // A detector without face points (OpenPose run without --face): the face joints are all neighbours'
  // copies, and the Face number measures that filling: said, not shown as a face error alone.
  ASSERT_EQ(test::RunRpt("convert --dataset synthetic --param frames=3 --param people=2 --param joints=wholebody "
                         "--labels-out " + (out / "labels.json").string() + " --detections-out " +
                         (out / "detections.json").string())
                .exit_code,
            0);
  nlohmann::json detections = ReadJson(out / "detections.json");
  for (auto& frame : detections["frames"]) {
    for (auto& view : frame["views"]) {
      for (auto& pose : view["poses"]) {
        for (int j = 23; j <= 90; ++j) pose[j] = nullptr;  // COCO-WholeBody's face
      }
    }
  }
  std::ofstream(out / "no_face.json") << detections.dump();
  const test::CommandResult no_face = test::RunRpt("eval --labels " + (out / "labels.json").string() + " --detections " +
                                                   (out / "no_face.json").string() + " --out " + (out / "nf").string());
  ASSERT_EQ(no_face.exit_code, 0) << no_face.err;
  EXPECT_NE(no_face.err.find("warning: whole-body group Face: 100 % of its measured joints were filled from a "
                             "neighbour, not triangulated"),
            std::string::npos)
      << no_face.err;
  EXPECT_EQ(ReadJson(out / "nf" / "summary.json")["wholebody_counts"]["Face"]["filled_share"], 1.0);
  // Body-only detections of the whole-body labels (a COCO-17 detector on a whole-body dataset):
  // Face and Hands are not measured and All is over 17 joints; said (it was silent), counted.
  nlohmann::json body_only = ReadJson(out / "detections.json");
  ASSERT_EQ(body_only["joints"].size(), 133u);
  body_only["joints"].erase(body_only["joints"].begin() + 17, body_only["joints"].end());
  for (auto& frame : body_only["frames"]) {
    for (auto& view : frame["views"]) {
      for (auto& pose : view["poses"]) pose.erase(pose.begin() + 17, pose.end());
    }
  }
  std::ofstream(out / "body_only.json") << body_only.dump();
  const test::CommandResult coco17 =
      test::RunRpt("eval --labels " + (out / "labels.json").string() + " --detections " +
                   (out / "body_only.json").string() + " --out " + (out / "b17").string());
  ASSERT_EQ(coco17.exit_code, 0) << coco17.err;
  EXPECT_NE(coco17.err.find("warning: whole-body group Face: the ground truth has 68 of its joints, the predictions "
                            "none (detections of the body only?): it is not measured, and All is over the joints both "
                            "have"),
            std::string::npos)
      << coco17.err;
  EXPECT_NE(coco17.err.find("warning: whole-body group Hands: the ground truth has 42 of its joints"),
            std::string::npos);
  EXPECT_EQ(coco17.err.find("whole-body group Body:"), std::string::npos) << "its 17 body joints are measured";
  const nlohmann::json b17 = ReadJson(out / "b17" / "summary.json")["wholebody_counts"];
  EXPECT_EQ(b17["All"]["joints"], 17);
  EXPECT_EQ(b17["All"]["gt_only_joints"], 116);
  EXPECT_EQ(b17["Body"]["gt_only_joints"], 6) << "the feet";
  EXPECT_EQ(b17["Face"]["gt_only_joints"], 68);
  EXPECT_EQ(counts["Face"]["gt_only_joints"], 0);
  EXPECT_EQ(whole.err.find("is not measured"), std::string::npos) << whole.err;
  EXPECT_EQ(body.err.find("is not measured"), std::string::npos) << "body-only GT: nothing to say";
  fs::remove_all(out);
}

// A dataset read from disk without --root says what is missing (it said "root '' is not a directory").
TEST(EvalCommand, ADatasetWithoutRootSaysSo) {
  const test::CommandResult r = test::RunRpt("eval --dataset mvor");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--dataset mvor needs --root DIR"), std::string::npos) << r.err;
  EXPECT_EQ(test::RunRpt("eval --dataset synthetic --param frames=2 --quiet --out " +
                         (test::TempDir("no_root") / "out").string())
                .exit_code,
            0)
      << "the generated scene reads no files";
}

// A --list file's typos are errors that name the file and the place, not rows of defaults.
TEST(SweepCommand, ListFileTyposNameTheFileAndTheConfiguration) {
  const fs::path out = test::TempDir("sweep_list");
  const auto run = [&](const std::string& list) {
    std::ofstream(out / "list.json") << list;
    return test::RunRpt("sweep --dataset synthetic --param frames=5 --list " + (out / "list.json").string() +
                        " --out " + (out / "s").string());
  };
  const test::CommandResult key = run(R"([{"name": "a"}, {"name": "b", "sett": {"merge.top_k": 0}}])");
  EXPECT_EQ(key.exit_code, 2);
  EXPECT_NE(key.err.find("list.json: /1/sett: unknown key 'sett' (did you mean 'set'?)"), std::string::npos) << key.err;
  const test::CommandResult twice = run(R"([{"name": "a"}, {"name": "a", "set": {"merge.top_k": 0}}])");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("list.json: /1/name: 'a' names configuration 1 too"), std::string::npos) << twice.err;
  const test::CommandResult option = run(R"({"configurations": [{"name": "a"}, {"name": "b", "set": {"merge.topk": 0}}]})");
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_NE(option.err.find("list.json: /configurations/1 (configuration 'b'): "), std::string::npos) << option.err;
  EXPECT_NE(option.err.find("merge.topk"), std::string::npos) << option.err;
  const test::CommandResult empty = run("[]");
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("list.json: no configurations: the sweep would run nothing"), std::string::npos) << empty.err;
  // A configuration that fails only when it runs is named with its place in the file.
  const test::CommandResult fails =
      run(R"([{"name": "ok"}, {"name": "bad joints", "set": {"triangulate.core_joints": ["foo", "bar", "baz"]}}])");
  EXPECT_EQ(fails.exit_code, 2);
  EXPECT_NE(fails.err.find("list.json: /1 (configuration 'bad joints', 2 of the sweep): triangulate.core_joints: joint 'foo'"),
            std::string::npos)
      << fails.err;
  const test::CommandResult grid =
      test::RunRpt("sweep --dataset synthetic --param frames=5 --grid merge.top_k=3,3 --out " + (out / "g").string());
  EXPECT_EQ(grid.exit_code, 2);
  EXPECT_NE(grid.err.find("--grid: configuration 'merge.top_k=3' twice"), std::string::npos) << grid.err;
  fs::remove_all(out);
}

// A shard file damaged or edited by hand (wrong types, missing keys, truncated) makes `rpt merge`
// exit 2 with one message naming the file and the JSON pointer. Before, the unchecked reads gave
// "internal error" (exit 1), or took a row with an index beyond the sweep into the table.
TEST(SweepCommand, DamagedShardFileIsAnErrorNamingFileAndPointer) {
  const fs::path out = test::TempDir("damaged_shard");
  const test::CommandResult sweep = test::RunRpt("sweep --dataset synthetic --param frames=5 --grid "
                                                 "filter.min_match_score=0.8,0.9 --out " + (out / "sweep").string());
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const std::string text = test::ReadAll(out / "sweep" / "sweep.json");
  const nlohmann::json good = nlohmann::json::parse(text);
  ASSERT_EQ(good["rows"].size(), 2u);
  const fs::path shard = out / "shard.json";
  auto merge = [&] { return test::RunRpt("merge " + shard.string() + " --out " + (out / "merged").string()); };
  std::ofstream(shard) << text;
  const test::CommandResult intact = merge();
  ASSERT_EQ(intact.exit_code, 0) << intact.err;

  using Edit = std::function<void(nlohmann::json&)>;
  struct Case {
    Edit edit;
    std::string expected;  // after "error: <file>: "
  };
  const std::vector<Case> cases = {
      {[](nlohmann::json& j) { j["rows"][0]["index"] = "0"; }, "/rows/0/index: expected an integer, got string"},
      {[](nlohmann::json& j) { j["rows"][1]["index"] = 7; }, "/rows/1/index: 7 is not an integer in [0, 1]"},
      {[](nlohmann::json& j) { j["rows"][0].erase("index"); }, "/rows/0/index: missing"},
      {[](nlohmann::json& j) { j["rows"][0]["name"] = 5; }, "/rows/0/name: expected a string, got number"},
      {[](nlohmann::json& j) { j["rows"][1].erase("summary"); }, "/rows/1/summary: missing"},
      {[](nlohmann::json& j) { j["rows"][0]["summary"] = "good"; }, "/rows/0/summary: expected an object of metrics"},
      {[](nlohmann::json& j) { j["rows"][0]["summary"]["mpjpe_mm"] = "12.5"; },
       "/rows/0/summary/mpjpe_mm: expected a number or null, got string"},
      {[](nlohmann::json& j) { j["rows"][0]["default"] = "yes"; }, "/rows/0/default: expected true or false, got string"},
      {[](nlohmann::json& j) { j["rows"][0]["set"] = nlohmann::json::array({1}); },
       "/rows/0/set: expected an object {option: value}, got array"},
      {[](nlohmann::json& j) { j["rows"][0] = 3; }, "/rows/0: expected a row"},
      {[](nlohmann::json& j) { j["rows"] = nlohmann::json::object(); }, "/rows: expected a list of rows, got object"},
      {[](nlohmann::json& j) { j["total"] = "2"; }, "/total: expected an integer, got string"},
      {[](nlohmann::json& j) { j["total"] = -2; }, "/total: -2 is not an integer in [0, 2147483647]"},
      {[](nlohmann::json& j) { j["base"] = nlohmann::json::array(); }, "/base: expected an object {option: base value}"},
      // Rows that are not what the shard's sweep says they are, numbers no run writes.
      {[](nlohmann::json& j) { j["rows"][0]["name"] = "other"; }, "/rows/0: is not configuration 1 of the shard's sweep"},
      {[](nlohmann::json& j) { j["rows"][1]["set"] = {{"filter.min_match_score", "0.1"}}; },
       "/rows/1: is not configuration 2 of the shard's sweep"},
      {[](nlohmann::json& j) { j["rows"][0]["summary"]["pcp"] = -50; },
       "/rows/0/summary/pcp: -50.0 is not a percentage in [0, 100]"},
      {[](nlohmann::json& j) { j["rows"][0]["summary"]["f1"] = 100.5; },
       "/rows/0/summary/f1: 100.5 is not a percentage in [0, 100]"},
      {[](nlohmann::json& j) { j["rows"][1]["summary"]["frames"] = -3; },
       "/rows/1/summary/frames: -3.0 is not a count or measure >= 0"},
      {[](nlohmann::json& j) { j.erase("rows"); }, "not a sweep shard file"},
      {[](nlohmann::json& j) { j = nlohmann::json::array({j}); }, "not a sweep shard file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expected);
    nlohmann::json damaged = good;
    c.edit(damaged);
    std::ofstream(shard) << damaged.dump(2);
    const test::CommandResult r = merge();
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("error: " + shard.string() + ": " + c.expected), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
  // Truncated (a copy cut off while written): the parse error names file, line and column.
  std::ofstream(shard, std::ios::trunc) << text.substr(0, text.size() / 2);
  const test::CommandResult truncated = merge();
  EXPECT_EQ(truncated.exit_code, 2) << truncated.err;
  EXPECT_NE(truncated.err.find("error: " + shard.string() + ":"), std::string::npos) << truncated.err;
  EXPECT_NE(truncated.err.find("JSON parse error"), std::string::npos) << truncated.err;
  // The merged output of the intact file is still the one in place.
  EXPECT_EQ(nlohmann::json::parse(test::ReadAll(out / "merged" / "sweep.json"))["rows"].size(), 2u);
  fs::remove_all(out);
}

// The same for the --list file of `rpt sweep` (a name that is not a string used to be an
// "internal error"; a "set" that is a list was read as options "0", "1", ...).
TEST(SweepCommand, DamagedListFileIsAnErrorNamingFileAndPointer) {
  const fs::path dir = test::TempDir("damaged_list");
  const fs::path list = dir / "list.json";
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {R"([{"name": 5, "set": {}}])", "/0/name: expected a string, got number"},
      {R"({"configurations": [{"name": "a"}, {"name": "b", "set": [1]}]})",
       "/configurations/1/set: expected an object {option: value}, got array"},
      {R"({"configurations": [{"name": "a"}, 7]})", "/configurations/1: expected {\"name\", \"set\"}, got number"},
      {R"({"configurations": {"name": "a"}})", "/configurations: expected a list of"},
      {R"({"configs": []})", "/configurations: expected a list of"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    std::ofstream(list, std::ios::trunc) << c.text;
    const test::CommandResult r = test::RunRpt("sweep --dataset synthetic --param frames=2 --list " + list.string() +
                                               " --out " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("error: " + list.string() + ": " + c.expected), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt
