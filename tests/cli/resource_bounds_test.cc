// SPDX-License-Identifier: MIT
// Bounds on what one run may take (issue 10): --threads clamped to the cores and the work, the
// global --max-inflate-mb, the persons-per-view cap reaching the command line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>

#include "engine/thread_count.h"
#include "core/errors.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

TEST(ClampThreads, AtMostTheHardwareAndTheWork) {
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(engine::ClampThreads(100000, 1000000), hardware);
  EXPECT_EQ(engine::ClampThreads(100000, 1), 1);
  EXPECT_EQ(engine::ClampThreads(1, 50), 1);
  EXPECT_EQ(engine::ClampThreads(0, 0), 1) << "no work still runs the (empty) loop on one thread";
  EXPECT_GE(engine::ClampThreads(0, 1000000), 1);
  EXPECT_LE(engine::ClampThreads(0, 1000000), hardware);
  EXPECT_THROW(engine::ClampThreads(-4, 10), ConfigError);
}

// `--threads 100000` segfaulted in libgomp; `--threads -4` was accepted.
TEST(ThreadsOption, NegativeIsAUsageErrorAndHugeIsClampedWithANote) {
  const fs::path out = test::TempDir("threads");
  const test::CommandResult negative =
      test::RunRpt("eval --dataset synthetic --param frames=5 --quiet --threads -4 --out " + out.string());
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_NE(negative.err.find("--threads"), std::string::npos) << negative.err;
  EXPECT_EQ(test::RunRpt("sweep --dataset synthetic --param frames=5 --threads -1 --grid merge.top_k=0,2 --out " +
                         out.string())
                .exit_code,
            2);

  const test::CommandResult huge =
      test::RunRpt("eval --dataset synthetic --param frames=5 --quiet --json --threads 100000 --out " + out.string());
  ASSERT_EQ(huge.exit_code, 0) << huge.err;
  EXPECT_NE(huge.err.find("note: --threads 100000 is more than the "), std::string::npos) << huge.err;
  const std::string run = test::ReadAll(out / "run.json");
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int stages = std::min(hardware, 8);  // one sequence: its stages on at most 8 threads (engine/run.h)
  EXPECT_NE(run.find("\"threads\": " + std::to_string(stages)), std::string::npos)
      << "one sequence: " << stages << " thread(s)\n" << run;
  const test::CommandResult sweep = test::RunRpt(
      "sweep --dataset synthetic --param frames=5 --threads 100000 --grid merge.top_k=0,2 --out " + out.string());
  EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
  fs::remove_all(out);
}

TEST(MaxInflateMb, IsAGlobalOptionBeforeOrAfterTheSubcommand) {
  EXPECT_EQ(test::RunRpt("--max-inflate-mb 100 config --dump").exit_code, 0);
  EXPECT_EQ(test::RunRpt("config --dump --max-inflate-mb 100").exit_code, 0);
  const test::CommandResult zero = test::RunRpt("config --dump --max-inflate-mb 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--max-inflate-mb"), std::string::npos) << zero.err;
}

// 1600 persons per view took 4.7 s and 1 GB for one frame; a cap below the scene's persons stops
// the run with exit code 2 and names the option.
TEST(MaxPersonsPerView, AFrameAboveTheCapIsAnInputError) {
  const fs::path out = test::TempDir("persons");
  const test::CommandResult r = test::RunRpt(
      "eval --dataset synthetic --param frames=3 --param people=3 --quiet --set triangulate.max_persons_per_view=1 "
      "--out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("above triangulate.max_persons_per_view (1)"), std::string::npos) << r.err;
  // From a detections file, the error names it first (it named the sequence and frame only).
  const std::string labels = (out / "labels.json").string(), detections = (out / "detections.json").string();
  ASSERT_EQ(test::RunRpt("convert --dataset synthetic --simulate --param frames=3 --param people=3 --labels-out " + labels +
                         " --detections-out " + detections)
                .exit_code,
            0);
  const test::CommandResult file = test::RunRpt("eval --labels " + labels + " --detections " + detections +
                                                " --quiet --set triangulate.max_persons_per_view=1 --out " +
                                                (out / "run").string());
  EXPECT_EQ(file.exit_code, 2) << file.err;
  EXPECT_EQ(file.err.rfind("error: " + detections + ": synthetic: frame 'synthetic_000000': view 0 (camera ", 0), 0u)
      << file.err;
  fs::remove_all(out);
}

}  // namespace
}  // namespace rpt
