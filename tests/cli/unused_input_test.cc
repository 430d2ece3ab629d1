// SPDX-License-Identifier: MIT
// Nothing dropped silently, end to end: a labels file of several scenes attaches one detections
// file like a single scene does (an unknown camera is an error, exit 2), detection frames that
// match no label and label frames the detections lack are counted warnings (stderr and
// run.json), `--strict` turns them into exit 2, and inspect / convert count the frames that
// have at least one detection.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/synthetic/synthetic_sequence.h"
#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> WarningLines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("warning: ", 0) == 0) lines.push_back(line);
  }
  return lines;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Labels of two scenes ("a", "b"; 8 frames each, 4 cameras, perfect detections) and one
// detections file (generic JSON) for both, as JSON to edit.
struct TestInput {
  fs::path dir, labels, detections;
  nlohmann::json detections_json;

  void WriteDetections() const { std::ofstream(detections) << detections_json.dump(); }
  std::string Args() const { return "--labels " + labels.string() + " --detections " + detections.string(); }
  // The frame object with this id in detections_json.
  nlohmann::json& Frame(const std::string& id) {
    for (nlohmann::json& frame : detections_json["frames"]) {
      if (frame["id"] == id) return frame;
    }
    throw std::runtime_error("no frame " + id);
  }
};

TestInput WriteInput(const std::string& name) {
  TestInput input;
  input.dir = test::TempDir(name);
  input.labels = input.dir / "labels.json";
  input.detections = input.dir / "detections.json";
  synthetic::SceneOptions options;
  options.num_frames = 8;
  options.num_people = 2;
  options.rig.num_cameras = 4;
  std::vector<Sequence> sequences;
  Detections detections;
  for (const char* scene : {"a", "b"}) {
    sequences.push_back(synthetic::MakeSyntheticSequence(synthetic::GenerateScene(options),
                                                         synthetic::DetectorOptions::Perfect(), 1, scene));
    const Sequence& s = sequences.back();
    detections.joints = s.detection_joints;
    for (const SequenceFrame& f : s.frames) {
      FrameDetections frame{f.id, {}, f.views};
      for (const Camera& c : s.cameras) frame.cameras.push_back(c.name);
      detections.frames.push_back(frame);
    }
  }
  WriteLabels(input.labels, sequences);
  WriteGenericDetections(input.detections, detections);
  input.detections_json = nlohmann::json::parse(test::ReadAll(input.detections));
  return input;
}

TEST(UnusedInput, AnUnknownCameraInOneSceneOfSeveralIsAnErrorAsForOneScene) {
  TestInput input = WriteInput("unused_camera");
  const std::string camera = input.Frame("b_000003")["views"][1]["camera"];
  input.Frame("b_000003")["views"][1]["camera"] = "cam_typo";
  input.WriteDetections();
  // Before: the error was swallowed for multi-scene labels, exit 0, b_000003's detections gone.
  const test::CommandResult r = test::RunRpt("eval --quiet " + input.Args() + " --out " + (input.dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_TRUE(Contains(r.err, input.detections.string() + ": frame 'b_000003': camera 'cam_typo' is not a camera of "
                                                          "sequence 'b'"))
      << r.err;
  // The same for inspect and convert, which load the same way.
  EXPECT_EQ(test::RunRpt("inspect " + input.Args()).exit_code, 2);
  EXPECT_EQ(test::RunRpt("convert " + input.Args() + " --out " + (input.dir / "c.h5").string()).exit_code, 2);
  fs::remove_all(input.dir);
}

TEST(UnusedInput, UnmatchedFramesAreCountedWarningsInStderrAndRunJson) {
  TestInput input = WriteInput("unused_frames");
  nlohmann::json& frames = input.detections_json["frames"];
  // Two detection frames whose ids are no label (a typo'd scene), and label a_000005 dropped.
  nlohmann::json stray = input.Frame("a_000001");
  stray["id"] = "c_000001";
  frames.push_back(stray);
  stray["id"] = "c_000002";
  frames.push_back(stray);
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i]["id"] == "a_000005") frames.erase(i);
  }
  input.WriteDetections();
  const fs::path out = input.dir / "out";
  const test::CommandResult r = test::RunRpt("eval --quiet " + input.Args() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> expected = {
      "warning: " + input.detections.string() +
          ": 2 detection frames whose id is no frame of the input, ignored (first 'c_000001')",
      "warning: " + input.detections.string() +
          ": 1 frames of the input absent from it, triangulated without detections (first 'a_000005')"};
  EXPECT_EQ(WarningLines(r.err), expected) << r.err;
  const nlohmann::json run = nlohmann::json::parse(test::ReadAll(out / "run.json"));
  ASSERT_EQ(run["input_warnings"].size(), 2u) << run.dump();
  EXPECT_EQ("warning: " + run["input_warnings"][0].get<std::string>(), expected[0]);
  EXPECT_EQ("warning: " + run["input_warnings"][1].get<std::string>(), expected[1]);

  // --strict: the same lines, as an error (exit 2), on every command that reads input.
  for (const std::string& command : {"eval --quiet --out " + out.string(), std::string("inspect"),
                                     "convert --out " + (input.dir / "c.h5").string(), std::string("detector-stats")}) {
    const test::CommandResult strict = test::RunRpt(command + " --strict " + input.Args());
    EXPECT_EQ(strict.exit_code, 2) << command << "\n" << strict.err;
    EXPECT_TRUE(Contains(strict.err, "--strict")) << strict.err;
    EXPECT_TRUE(Contains(strict.err, expected[0].substr(9))) << strict.err;
    EXPECT_TRUE(Contains(strict.err, expected[1].substr(9))) << strict.err;
  }
  EXPECT_FALSE(fs::exists(input.dir / "c.h5"));
  fs::remove_all(input.dir);
}

TEST(UnusedInput, StrictAcceptsCorrectionsAndCompleteInput) {
  TestInput input = WriteInput("unused_strict_ok");
  // A score of 1.01 is corrected (clamped to 1) and reported, but nothing is unused.
  input.Frame("a_000002")["views"][0]["poses"][0][0][2] = 1.01;
  input.WriteDetections();
  const test::CommandResult r =
      test::RunRpt("eval --quiet --strict " + input.Args() + " --out " + (input.dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = WarningLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_TRUE(Contains(lines[0], "1 scores above 1 clamped to 1")) << lines[0];
  fs::remove_all(input.dir);
}

// A detections file of every frame with a dataset whose selection leaves some out (MVOR days=1,
// Panoptic's every=12): the frames of the dataset's id form that no selected frame uses were left
// out on purpose, not unused input, also under --strict; a frame of another form is unused.
TEST(UnusedInput, FramesTheSelectionLeavesOutAreNotUnusedInput) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const fs::path dir = test::TempDir("unused_selection");
  const std::string root = test::SharedData("mvor").string();
  const fs::path all = dir / "all.json";
  ASSERT_EQ(test::RunRpt("convert --dataset mvor --root " + root + " --detections-out " + all.string()).exit_code, 0);
  const std::string day1 = "eval --quiet --strict --dataset mvor --root " + root +
                           " --param detections=none --param days=1 --out " + (dir / "out").string() + " --detections ";
  const test::CommandResult selected = test::RunRpt(day1 + all.string());
  EXPECT_EQ(selected.exit_code, 0) << selected.err;
  EXPECT_FALSE(Contains(selected.err, "detection frames whose id is no frame of the input")) << selected.err;
  nlohmann::json json = nlohmann::json::parse(test::ReadAll(all));
  json["frames"].push_back(json["frames"][0]);
  json["frames"].back()["id"] = "take_000001";
  const fs::path foreign = dir / "foreign.json";
  std::ofstream(foreign) << json.dump();
  const test::CommandResult unused = test::RunRpt(day1 + foreign.string());
  EXPECT_EQ(unused.exit_code, 2);
  EXPECT_TRUE(Contains(unused.err, ": 1 detection frames whose id is no frame of the input, ignored (first 'take_000001')"))
      << unused.err;
  fs::remove_all(dir);
}

TEST(UnusedInput, StrictOnCheckAndSweep) {
  TestInput input = WriteInput("unused_check");
  nlohmann::json stray = input.Frame("a_000001");
  stray["id"] = "c_000001";
  input.detections_json["frames"].push_back(stray);
  input.WriteDetections();
  std::ofstream(input.dir / "thresholds.json") << R"({"evaluations": [
      {"name": "one", "labels": "labels.json", "detections": "detections.json", "min": {"recall500": 50}}]})";
  const std::string check = "check --thresholds " + (input.dir / "thresholds.json").string();
  const test::CommandResult loose = test::RunRpt(check);
  EXPECT_EQ(loose.exit_code, 0) << loose.out << loose.err;
  EXPECT_EQ(WarningLines(loose.err).size(), 1u) << loose.err;
  // check's contract: an evaluation that fails to run is exit 1, with the reason in its row.
  const test::CommandResult strict = test::RunRpt(check + " --strict");
  EXPECT_EQ(strict.exit_code, 1) << strict.out << strict.err;
  EXPECT_TRUE(Contains(strict.out + strict.err, "1 detection frames whose id is no frame of the input"))
      << strict.out << strict.err;

  const std::string sweep =
      "sweep " + input.Args() + " --grid filter.min_match_score=0.5,0.7 --out " + (input.dir / "sweep").string();
  EXPECT_EQ(test::RunRpt(sweep).exit_code, 0);
  const test::CommandResult strict_sweep = test::RunRpt(sweep + " --strict");
  EXPECT_EQ(strict_sweep.exit_code, 2) << strict_sweep.err;
  EXPECT_TRUE(Contains(strict_sweep.err, "first 'c_000001'")) << strict_sweep.err;
  fs::remove_all(input.dir);
}

TEST(UnusedInput, InspectAndConvertCountFramesWithAtLeastOneDetection) {
  TestInput input = WriteInput("unused_counts");
  // a_000002: listed, but no camera detected anyone; a_000004: absent from the file.
  for (nlohmann::json& view : input.Frame("a_000002")["views"]) view["poses"] = nlohmann::json::array();
  nlohmann::json& frames = input.detections_json["frames"];
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i]["id"] == "a_000004") frames.erase(i);
  }
  input.WriteDetections();
  // Before: "8 frames (8 with detections)" for scene a, every frame counted once attached.
  const test::CommandResult inspect = test::RunRpt("inspect --json " + input.Args());
  ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
  const nlohmann::json report = nlohmann::json::parse(inspect.out);
  ASSERT_EQ(report.size(), 2u);
  EXPECT_EQ(report[0]["sequence"], "a");
  EXPECT_EQ(report[0]["frames"], 8);
  EXPECT_EQ(report[0]["frames_with_detections"], 6);
  EXPECT_EQ(report[1]["frames_with_detections"], 8);
  const test::CommandResult text = test::RunRpt("inspect " + input.Args());
  EXPECT_TRUE(Contains(text.out, "sequence a: 8 frames (6 with detections)")) << text.out;

  const test::CommandResult convert =
      test::RunRpt("convert " + input.Args() + " --out " + (input.dir / "c.h5").string());
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_TRUE(Contains(convert.out, "converted 2 sequence(s), 16 frames, 14 frames with detections")) << convert.out;
  fs::remove_all(input.dir);
}

}  // namespace
}  // namespace rpt
