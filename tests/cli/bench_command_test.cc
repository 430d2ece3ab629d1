// SPDX-License-Identifier: MIT
// rpt bench: structure of its JSON, the in-run baseline and the HDF5 loading mode (speed goals
// live in results/bench.md, not in tests).
#include <gtest/gtest.h>

#include <chrono>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

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
  // The instruction set the SIMD kernels ran on (chosen at run time), in the JSON and the header.
  const std::string simd = j["simd"].get<std::string>();
  EXPECT_TRUE(simd == "scalar" || simd == "SSE4" || simd == "AVX2" || simd == "AVX-512") << simd;
  const test::CommandResult text = test::RunRpt("bench --scene few-views --frames 5 --repeat 1 --no-baseline");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("; SIMD " + simd + "\n"), std::string::npos) << text.out;
  // A scene without a target says so in both target rows (not "0", which read as a 0 us target).
  const auto row = [&](const std::string& label) {
    const size_t at = text.out.find("\n" + label + " ");
    return at == std::string::npos ? std::string() : text.out.substr(at + 1, text.out.find('\n', at + 1) - at - 1);
  };
  for (const std::string label : {"target (us)", "target met"}) {
    const std::string line = row(label);
    ASSERT_FALSE(line.empty()) << label << " missing:\n" << text.out;
    EXPECT_EQ(line.back(), '-') << line;
  }
  EXPECT_EQ(test::RunRpt("bench --scene nosuch").exit_code, 2);
  // Counts below 1 were read as "the scene's frames" (0, -5) or as a baseline of 0 frames (a 0.0x
  // speed-up): refused, a baseline is left out with --no-baseline.
  for (const char* bad : {"--frames 0", "--frames -5", "--baseline-frames 0", "--baseline-frames -3"}) {
    const test::CommandResult r = test::RunRpt(std::string("bench --scene few-views --repeat 1 ") + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("not in range 1 to"), std::string::npos) << bad << ": " << r.err;
  }
}

// rpt bench --dataset: a dataset's real frames as a column. Its accuracy is `rpt eval`'s on the same
// frames (the same pipeline on the same input); the shelf-4da reader's part-affinity grouping is a
// row of its own (done again in every pass) and the target (30 us) is about the frame with it.
TEST(BenchCommand, ADatasetsFramesWithTheReadersGroupingAsARow) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  const std::string input =
      "--dataset shelf-4da --root " + test::SharedData("shelf/4d_association").string() + " --param frames=0-19";
  const test::CommandResult r = test::RunRpt("bench " + input + " --repeat 2 --baseline-frames 3 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["scenes"].size(), 1u) << "a dataset alone: no generated scenes";
  const nlohmann::json& s = j["scenes"][0];
  EXPECT_EQ(s["name"], "shelf-4da");
  EXPECT_EQ(s["frames"], 20);
  const double pipeline = s["frame_time_us_median"].get<double>();
  const double grouping = s["step_time_us_median"]["paf_grouping (reader)"].get<double>();
  const double with_grouping = s["frame_with_grouping_us_median"].get<double>();
  EXPECT_GT(grouping, 0.0);
  EXPECT_GT(with_grouping, pipeline);
  EXPECT_EQ(s["target_us"], 30.0);
  EXPECT_EQ(s["meets_target"], with_grouping <= 30.0);
  EXPECT_GT(s["speedup"].get<double>(), 1.0);
  const test::CommandResult eval =
      test::RunRpt("eval " + input + " --json --quiet --no-predictions --out " +
                   (std::filesystem::temp_directory_path() / "rpt_bench_dataset_eval").string());
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  const nlohmann::json e = nlohmann::json::parse(eval.out);
  EXPECT_DOUBLE_EQ(s["mpjpe_mm"].get<double>(), e["mpjpe_mm"].get<double>());
  EXPECT_DOUBLE_EQ(s["recall500"].get<double>(), e["recall500"].get<double>());
  EXPECT_DOUBLE_EQ(s["invalid"].get<double>(), e["invalid"].get<double>());
  // eval's summary has the frame with the grouping too (it had only the grouping's row).
  EXPECT_GT(e["frame_with_grouping_us_median"].get<double>(), e["frame_time_us_median"].get<double>());
  std::filesystem::remove_all(std::filesystem::temp_directory_path() / "rpt_bench_dataset_eval");

  // The table: the grouping row and the frame with it, "-" in a generated scene's column.
  const test::CommandResult text =
      test::RunRpt("bench --scene few-views --frames 5 " + input + " --repeat 1 --no-baseline");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  for (const std::string label : {"paf_grouping (reader)", "frame + grouping"}) {
    const size_t at = text.out.find("\n" + label + " ");
    ASSERT_NE(at, std::string::npos) << label << ":\n" << text.out;
    const std::string line = text.out.substr(at + 1, text.out.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find(" - "), std::string::npos) << "few-views has no grouping: " << line;
  }
  EXPECT_NE(text.err.find("rotations re-orthonormalised"), std::string::npos) << "the input's warnings, once";
}

// The baseline runs on the first --baseline-frames frames; the speed-up and the MPJPE beside it are
// rpt's on those same frames (they were rpt's over all frames: Shelf-4DA's first 30 frames are not
// its median frame, 37x against 45x on the same frames); the JSON says how many and the run's input
// (settings, warnings, digests) as eval's run.json does; a run that triangulates nobody meets no
// target.
TEST(BenchCommand, TheBaselineIsComparedOnItsOwnFrames) {
  const test::CommandResult r =
      test::RunRpt("bench --scene few-views --frames 20 --repeat 1 --baseline-frames 5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(r.out)["scenes"][0];
  EXPECT_EQ(s["baseline_frames"], 5);
  EXPECT_DOUBLE_EQ(s["speedup"].get<double>(), s["baseline_frame_time_us_median"].get<double>() /
                                                   s["frame_time_us_median_on_baseline_frames"].get<double>());
  EXPECT_NE(s["mpjpe_mm_on_baseline_frames"], s["mpjpe_mm"]) << "5 of 20 frames";
  const test::CommandResult all =
      test::RunRpt("bench --scene few-views --frames 5 --repeat 1 --baseline-frames 5 --json");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const nlohmann::json a = nlohmann::json::parse(all.out)["scenes"][0];
  EXPECT_DOUBLE_EQ(a["mpjpe_mm_on_baseline_frames"].get<double>(), a["mpjpe_mm"].get<double>()) << "the same 5 frames";
  EXPECT_DOUBLE_EQ(a["mpjpe_mm_on_baseline_frames"].get<double>(), s["mpjpe_mm_on_baseline_frames"].get<double>());
  const test::CommandResult nobody = test::RunRpt(
      "bench --scene shelf-like --frames 10 --repeat 1 --no-baseline --set postprocess.min_valid_joints=60");
  ASSERT_EQ(nobody.exit_code, 0) << nobody.err;
  EXPECT_NE(nobody.out.find("target met                NO (nobody)"), std::string::npos) << nobody.out;
}

TEST(BenchCommand, ADatasetsRunRecordsItsInput) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  const test::CommandResult r =
      test::RunRpt("bench --dataset shelf-4da --root " + test::SharedData("shelf/4d_association").string() +
                   " --param frames=0-9 --repeat 1 --no-baseline --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json run = nlohmann::json::parse(r.out)["run"];
  EXPECT_EQ(run["input_settings"]["reader"], "shelf-4da");
  EXPECT_EQ(run["input_settings"]["param.frames"], "0-9");
  EXPECT_FALSE(run["input_warnings"].empty()) << "the rotations re-orthonormalised";
  EXPECT_FALSE(run["input_digests"].empty());
  const nlohmann::json s = nlohmann::json::parse(r.out)["scenes"][0];
  EXPECT_EQ(s["target_compares"], "frame_with_grouping_us_median");
}

TEST(BenchCommand, DatasetOptionsAreCheckedBeforeAnythingRuns) {
  // One mode per run: each was silently given up for another.
  for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
           {"--io --scene few-views", "--io times reading an HDF5 detection cache: not with"},
           {"--io --dataset synthetic", "--io times reading an HDF5 detection cache: not with"},
           {"--io-frames 5", "--io-frames sets the --io cache's frames: add --io"},
           {"--follow --scaling", "--follow times the live input on one scene: not with --scaling"},
           {"--dataset synthetic --frames 5", "--frames sets the generated scenes' frames"},
           {"--dataset synthetic --detector hard", "--detector sets the simulated detector of the generated scenes"},
           {"--simulate", "add --dataset NAME"}}) {
    const test::CommandResult r = test::RunRpt("bench " + options + " --repeat 1");
    EXPECT_EQ(r.exit_code, 2) << options;
    EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
  }
  // A dataset without detections of its own is timed on simulated ones (--simulate, --detector).
  const test::CommandResult simulated = test::RunRpt(
      "bench --dataset synthetic --param frames=5 --simulate --detector hard --repeat 1 --no-baseline --json");
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  EXPECT_EQ(nlohmann::json::parse(simulated.out)["run"]["input_settings"]["detector"], "hard");
  const test::CommandResult root = test::RunRpt("bench --root /tmp --repeat 1");
  EXPECT_EQ(root.exit_code, 2);
  EXPECT_NE(root.err.find("add --dataset NAME"), std::string::npos) << root.err;
  const test::CommandResult follow = test::RunRpt("bench --dataset synthetic --follow --repeat 1");
  EXPECT_EQ(follow.exit_code, 2);
  EXPECT_NE(follow.err.find("not with --follow"), std::string::npos) << follow.err;
  const test::CommandResult missing = test::RunRpt("bench --dataset mvor --root /nonexistent/mvor --repeat 1");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/mvor"), std::string::npos) << missing.err;
  // A generated dataset has no grouping: no grouping keys.
  const test::CommandResult synthetic =
      test::RunRpt("bench --dataset synthetic --param frames=10 --repeat 1 --no-baseline --json");
  ASSERT_EQ(synthetic.exit_code, 0) << synthetic.err;
  const nlohmann::json s = nlohmann::json::parse(synthetic.out)["scenes"][0];
  EXPECT_EQ(s["name"], "synthetic");
  EXPECT_EQ(s["frames"], 10);
  EXPECT_FALSE(s["step_time_us_median"].contains("paf_grouping (reader)"));
  const test::CommandResult eval =
      test::RunRpt("eval --dataset synthetic --param frames=3 --json --quiet --no-predictions --out " +
                   (std::filesystem::temp_directory_path() / "rpt_bench_synthetic_eval").string());
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  EXPECT_FALSE(nlohmann::json::parse(eval.out).contains("frame_with_grouping_us_median")) << "no reader grouping";
  std::filesystem::remove_all(std::filesystem::temp_directory_path() / "rpt_bench_synthetic_eval");
  EXPECT_FALSE(s.contains("frame_with_grouping_us_median"));
  EXPECT_FALSE(s.contains("target_us"));
}

// rpt bench --follow: each scene with numbers at full precision and with 3 decimals, each with the
// live input's default polling before it sleeps (--spin-us) and with none; every timed frame counted.
TEST(BenchCommand, FollowTimesEachWayOfWaiting) {
  const test::CommandResult r = test::RunRpt("bench --follow --scene few-views --frames 20 --repeat 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["lines_per_s"].is_null()) << "back to back";
  ASSERT_EQ(j["scenes"].size(), 4u);
  const std::vector<std::pair<int, std::string>> expected = {
      {200, "full precision"}, {200, "3 decimals"}, {0, "full precision"}, {0, "3 decimals"}};
  for (size_t i = 0; i < expected.size(); ++i) {
    const nlohmann::json& s = j["scenes"][i];
    EXPECT_EQ(s["name"], "few-views");
    EXPECT_EQ(s["spin_us"], expected[i].first) << i;
    EXPECT_EQ(s["numbers"], expected[i].second) << i;
    EXPECT_EQ(s["frames"], 40) << "2 passes of 20 frames after the warm-up pass";
    // Per frame, the latency holds the triangulation: so do the medians.
    EXPECT_GE(s["latency_in_process_us_median"].get<double>(), s["triangulation_us_median"].get<double>()) << i;
    EXPECT_GE(s["added_in_process_us_median"].get<double>(), 0.0) << i;
  }
}

// --follow-rate paces the lines as a camera does: 4 runs of 20 lines at 100 per second take at least
// 4 x 19 / 100 s; back to back is the default (null in the JSON).
TEST(BenchCommand, FollowRatePacesTheLines) {
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult paced =
      test::RunRpt("bench --follow --follow-rate 100 --scene few-views --frames 10 --repeat 1 --json");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(paced.exit_code, 0) << paced.err;
  EXPECT_EQ(nlohmann::json::parse(paced.out)["lines_per_s"], 100.0);
  EXPECT_GE(seconds, 4 * 19 / 100.0);
  const test::CommandResult text = test::RunRpt("bench --follow --follow-rate 100 --scene few-views --frames 5 --repeat 1");
  EXPECT_NE(text.out.find("at 100 lines per second (--follow-rate)"), std::string::npos) << text.out;
  const test::CommandResult alone = test::RunRpt("bench --follow-rate 30 --scene few-views --frames 5");
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--follow-rate paces the lines of --follow"), std::string::npos) << alone.err;
}

TEST(BenchCommand, HdfCacheRoundTripTiming) {
  const test::CommandResult r = test::RunRpt("bench --io --io-frames 200 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 200);
  EXPECT_EQ(j["views"], 5);
  EXPECT_GT(j["read_s_median"].get<double>(), 0.0);
  EXPECT_GT(j["preflight_s_median"].get<double>(), 0.0);  // the walk in a child process ran
  EXPECT_GT(j["persons"].get<long>(), 200);
}

// The --io round trip's scratch HDF5 file (in TMPDIR) is removed when an exception ends the run:
// here the write fails at a file size limit of 32 KiB (SIGXFSZ ignored, so write() fails with
// EFBIG). It used to stay behind, and HDF5's clean-up at exit then crashed (signal 11, not exit 2).
// The Ctrl-C path: AtomicOutputs.InterruptedBenchIoRemovesItsScratchFile.
TEST(BenchCommand, IoScratchFileIsRemovedWhenTheWriteFails) {
  const std::filesystem::path tmp = test::TempDir("bench_scratch");
  const test::CommandResult r =
      test::RunRpt("bench --io --io-frames 2000 --json", "trap '' XFSZ; ulimit -f 64; TMPDIR=" + tmp.string() + " ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + (tmp / "rpt_bench_io.h5").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("write failed"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(std::filesystem::is_empty(tmp)) << "scratch file left in " << tmp;
  std::filesystem::remove_all(tmp);
}

}  // namespace
}  // namespace rpt
