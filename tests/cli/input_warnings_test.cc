// SPDX-License-Identifier: MIT
// Real-world tolerance end to end: the commands accept near-orthonormal rotations and scores
// slightly above 1 in the files a user gives them, and report each correction once on stderr as
// "warning: <file>: ..." (and in run.json), one line per file and kind.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/synthetic/synthetic_sequence.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

double SixDigits(double v) {
  char text[40];
  std::snprintf(text, sizeof(text), "%.6g", v);
  return std::stod(text);
}

// The "warning: " lines of a command's stderr.
std::vector<std::string> WarningLines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("warning: ", 0) == 0) lines.push_back(line);
  }
  return lines;
}

// Generic labels (5 cameras, R written with 6 significant digits as real calibration files do)
// and detections of a small synthetic scene; `scores_above_one` joint scores become 1.008 / 1.018.
struct Files {
  fs::path labels, detections;
};

Files WriteFiles(const fs::path& dir, int scores_above_one) {
  synthetic::SceneOptions options;
  options.num_frames = 12;
  options.num_people = 2;
  const Sequence sequence =
      synthetic::MakeSyntheticSequence(synthetic::GenerateScene(options), synthetic::DetectorOptions::Realistic(), 5, "mine");
  Files files{dir / "labels.json", dir / "detections.json"};
  WriteLabels(files.labels, {sequence});
  nlohmann::json labels = nlohmann::json::parse(test::ReadAll(files.labels));
  for (nlohmann::json& label : labels) {
    for (nlohmann::json& camera : label["cameras"]) {
      for (nlohmann::json& row : camera["R"]) {
        for (nlohmann::json& value : row) value = SixDigits(value.get<double>());
      }
    }
  }
  std::ofstream(files.labels) << labels.dump();

  Detections detections;
  detections.joints = sequence.detection_joints;
  for (const SequenceFrame& f : sequence.frames) {
    FrameDetections frame{f.id, {}, f.views};
    for (const Camera& c : sequence.cameras) frame.cameras.push_back(c.name);
    detections.frames.push_back(frame);
  }
  WriteGenericDetections(files.detections, detections);
  nlohmann::json d = nlohmann::json::parse(test::ReadAll(files.detections));
  int changed = 0;
  for (nlohmann::json& frame : d["frames"]) {
    for (nlohmann::json& view : frame["views"]) {
      for (nlohmann::json& person : view["poses"]) {
        for (nlohmann::json& joint : person) {
          if (changed < scores_above_one && joint[2].get<double>() > 0) joint[2] = changed++ % 2 ? 1.018 : 1.008;
        }
      }
    }
  }
  EXPECT_EQ(changed, scores_above_one);
  std::ofstream(files.detections) << d.dump();
  return files;
}

TEST(InputWarnings, EvalPrintsOneLineForTheLabelFileAndRecordsItInRunJson) {
  const fs::path dir = test::TempDir("tolerance_eval");
  const Files files = WriteFiles(dir, 0);
  const test::CommandResult r = test::RunRpt("eval --quiet --json --labels " + files.labels.string() + " --detections " +
                                             files.detections.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = WarningLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  // 12 labels repeat the same 5 cameras: each rotation is corrected and counted once.
  EXPECT_EQ(lines[0].rfind("warning: " + files.labels.string() + ": 5 rotations re-orthonormalised (max |R^T R - I| = ", 0), 0u)
      << lines[0];
  EXPECT_GT(nlohmann::json::parse(r.out)["recall500"].get<double>(), 90.0);
  const nlohmann::json run = nlohmann::json::parse(test::ReadAll(dir / "out" / "run.json"));
  ASSERT_EQ(run["input_warnings"].size(), 1u);
  EXPECT_EQ("warning: " + run["input_warnings"][0].get<std::string>(), lines[0]);
  fs::remove_all(dir);
}

TEST(InputWarnings, ScoresAboveOneGiveALineForTheDetectionFile) {
  const fs::path dir = test::TempDir("tolerance_scores");
  const Files files = WriteFiles(dir, 7);
  const test::CommandResult r = test::RunRpt("eval --quiet --labels " + files.labels.string() + " --detections " +
                                             files.detections.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = WarningLines(r.err);
  ASSERT_EQ(lines.size(), 2u) << r.err;
  EXPECT_EQ(lines[1], "warning: " + files.detections.string() + ": 7 scores above 1 clamped to 1 (largest = 1.018)");
  EXPECT_EQ(nlohmann::json::parse(test::ReadAll(dir / "out" / "run.json"))["input_warnings"].size(), 2u);

  // A score of 1.6 is an error naming the file and the place (exit 2), not a warning.
  std::string text = test::ReadAll(files.detections);
  text.replace(text.find("1.018"), 5, "1.6");
  std::ofstream(files.detections) << text;
  const test::CommandResult bad = test::RunRpt("eval --quiet --labels " + files.labels.string() + " --detections " +
                                               files.detections.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(files.detections.string() + ": /frames/"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("score 1.6 outside [0, 1]"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

// --simulate replaces the synthetic dataset's detector with its own (--detector): a --param noise
// beside it, with no --detector, used to be ignored without a word (the numbers were the
// realistic detector's).
TEST(InputWarnings, SyntheticNoiseWithSimulateIsAnErrorNotIgnored) {
  const fs::path dir = test::TempDir("noise_with_simulate");
  const test::CommandResult r =
      test::RunRpt("eval --quiet --dataset synthetic --param frames=2 --param noise=clean --simulate --out " +
                   (dir / "refused").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--param noise=clean has no effect with --simulate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give --detector clean with --simulate, or --param noise=clean without it"), std::string::npos)
      << r.err;
  EXPECT_EQ(test::RunRpt("eval --quiet --dataset synthetic --param frames=2 --simulate --detector clean --out " +
                         (dir / "detector").string())
                .exit_code,
            0);
  // A --detector of another profile beside it: the noise asked for would be ignored as well.
  const test::CommandResult other =
      test::RunRpt("eval --quiet --dataset synthetic --param frames=2 --param noise=clean --simulate --detector hard "
                   "--out " + (dir / "noise_and_detector").string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("--param noise=clean has no effect with --simulate, whose detector (--detector hard) replaces "
                           "the dataset's"),
            std::string::npos)
      << other.err;
  EXPECT_EQ(test::RunRpt("eval --quiet --dataset synthetic --param frames=2 --param noise=hard --simulate --detector "
                         "hard --out " +
                         (dir / "same").string())
                .exit_code,
            0);
  fs::remove_all(dir);
}

TEST(InputWarnings, ConvertCarriesTheCorrectedValuesIntoTheCacheAndWarns) {
  const fs::path dir = test::TempDir("tolerance_convert");
  const Files files = WriteFiles(dir, 3);
  const fs::path cache = dir / "new" / "cache.h5";  // its folder is created
  const test::CommandResult r = test::RunRpt("convert --labels " + files.labels.string() + " --detections " +
                                             files.detections.string() + " --out " + cache.string() +
                                             " --detections-out " + (dir / "other" / "d.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "other" / "d.json"));
  EXPECT_EQ(WarningLines(r.err).size(), 2u) << r.err;
  // The cache holds the corrected values: it reads back without any correction left to make.
  const Detections detections = ReadDetectionsHdf5(cache);
  EXPECT_TRUE(detections.warnings.empty());
  int ones = 0;
  for (const FrameDetections& frame : detections.frames) {
    for (const Poses2D& view : frame.views) {
      for (size_t i = 2; i < view.data.size(); i += 3) {
        EXPECT_LE(view.data[i], 1.0);
        ones += view.data[i] == 1.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GE(ones, 3);
  EXPECT_TRUE(MaterializeAll(OpenSequencesHdf5(cache))[0].warnings.empty());
  const test::CommandResult again = test::RunRpt("inspect --labels " + cache.string() + " --detections " + cache.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(WarningLines(again.err).empty()) << again.err;
  // inspect on the original files reports the same two lines.
  const test::CommandResult inspect =
      test::RunRpt("inspect --labels " + files.labels.string() + " --detections " + files.detections.string());
  ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
  EXPECT_EQ(WarningLines(inspect.err), WarningLines(r.err));
  fs::remove_all(dir);
}

TEST(InputWarnings, SweepAndCheckReportEachFileOnceNotOncePerConfiguration) {
  const fs::path dir = test::TempDir("tolerance_sweep");
  const Files files = WriteFiles(dir, 0);
  // param.* axes make every configuration load its own input.
  const test::CommandResult sweep = test::RunRpt("sweep --dataset generic --root " + files.labels.string() +
                                                 " --simulate --grid param.fps=20,25,30 --out " + (dir / "sweep").string());
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const std::vector<std::string> sweep_lines = WarningLines(sweep.err);
  ASSERT_EQ(sweep_lines.size(), 1u) << sweep.err;
  EXPECT_NE(sweep_lines[0].find(": 5 rotations re-orthonormalised"), std::string::npos) << sweep_lines[0];
  const nlohmann::json sweep_json = nlohmann::json::parse(test::ReadAll(dir / "sweep" / "sweep.json"));
  EXPECT_EQ(sweep_json["run"]["input_warnings"].size(), 1u);

  std::ofstream(dir / "thresholds.json") << R"({"evaluations": [
      {"name": "one", "labels": "labels.json", "detections": "detections.json", "min": {"recall500": 50}},
      {"name": "two", "labels": "labels.json", "simulate": true, "min": {"recall500": 50}}]})";
  const test::CommandResult check = test::RunRpt("check --thresholds " + (dir / "thresholds.json").string());
  ASSERT_EQ(check.exit_code, 0) << check.out << check.err;
  const std::vector<std::string> check_lines = WarningLines(check.err);
  ASSERT_EQ(check_lines.size(), 1u) << check.err;
  EXPECT_NE(check_lines[0].find(": 5 rotations re-orthonormalised"), std::string::npos) << check_lines[0];
  fs::remove_all(dir);
}

TEST(InputWarnings, ExactInputPrintsNothing) {
  const fs::path out = test::TempDir("tolerance_none");
  const test::CommandResult r = test::RunRpt("eval --quiet --dataset synthetic --param frames=5 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(WarningLines(r.err).empty()) << r.err;
  const nlohmann::json run = nlohmann::json::parse(test::ReadAll(out / "run.json"));
  ASSERT_TRUE(run.contains("input_warnings"));
  EXPECT_TRUE(run["input_warnings"].empty());
  fs::remove_all(out);
}

}  // namespace
}  // namespace rpt
