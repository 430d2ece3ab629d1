// SPDX-License-Identifier: MIT
// A labels and detections pair (generic JSON, written by the project's writers) whose camera,
// sequence and frame names are hostile strings (tests/hostile_strings.h), and whose labels path
// holds an escape sequence and "<!--<script>": for the tests that run every command on them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "datasets/io/json_output.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/synthetic/synthetic_sequence.h"
#include "tests/hostile_strings.h"

namespace rpt::test {

inline const std::string kHostileSequenceName = "scene <!--<script> \x1b[2J, =cmd|' /C calc'!A0 `x`";

struct HostileInput {
  std::filesystem::path labels, detections;
  std::vector<std::string> cameras;
  // The input options, quoted for the shell.
  std::string args() const { return "--labels '" + labels.string() + "' --detections '" + detections.string() + "'"; }
};

// A generated scene of 4 frames whose names are replaced by hostile ones (frame ids: the first
// hostile strings, made valid UTF-8, each with its index).
inline HostileInput MakeHostileInput(const std::filesystem::path& dir) {
  synthetic::SceneOptions options;
  options.num_frames = 4;
  options.num_people = 2;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  Sequence sequence = synthetic::MakeSyntheticSequence(scene, synthetic::DetectorOptions::Realistic(), 5, "x");
  HostileInput input;
  const std::vector<std::string> names = {"<!--<script>", "cam a", "cam/a", "cam_a",
                                          "\x1b[31mred\x1b]0;title\x07 \xc2\x9b"
                                          "2J =1+2"};
  for (size_t c = 0; c < sequence.cameras.size(); ++c) {
    input.cameras.push_back(c < names.size() ? names[c] : "cam `" + std::to_string(c) + "` | <b>");
    sequence.cameras[c].name = input.cameras[c];
  }
  sequence.name = kHostileSequenceName;
  const std::vector<std::string>& hostile = HostileStrings();
  for (size_t f = 0; f < sequence.frames.size(); ++f) {
    sequence.frames[f].id = io::ValidUtf8(hostile[f % hostile.size()]) + " " + std::to_string(f);
  }
  input.labels = dir / "labels \x1b[1m<!--<script>.json";
  input.detections = dir / "detections.json";
  WriteLabels(input.labels, {sequence});
  Detections detections;
  detections.joints = sequence.detection_joints;
  for (const SequenceFrame& f : sequence.frames) {
    FrameDetections frame{f.id, {}, f.views};
    for (const Camera& c : sequence.cameras) frame.cameras.push_back(c.name);
    detections.frames.push_back(frame);
  }
  WriteGenericDetections(input.detections, detections);
  return input;
}

}  // namespace rpt::test
