// SPDX-License-Identifier: MIT
// One fuzz target per input format: a function that hands arbitrary bytes to that format's
// reader the way rpt does (through a file when the reader takes a path, in a scratch folder of
// this process). Bad bytes must end in InputError or ConfigError; anything else (another
// exception, a crash, a sanitizer report, a hang, unbounded memory) escapes and is a finding.
// Used by the libFuzzer executables (fuzz/fuzzer_main.cc, RPT_BUILD_FUZZERS) and by the seed and
// regression tests of the ordinary test suite (fuzz/fuzz_targets_test.cc).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rpt::fuzz {

struct FuzzTarget {
  std::string name;  // "labels", "coco", ... (the fuzzer executable is rpt_fuzz_<name>)
  std::string what;  // the format, for docs and messages
  // Reads `bytes` as this format; throws whatever the reader throws.
  void (*read)(std::span<const std::uint8_t> bytes);
};

const std::vector<FuzzTarget>& FuzzTargets();
// The target called `name`, or nullptr.
const FuzzTarget* FindFuzzTarget(std::string_view name);

// Runs `target` on `bytes`: true when the reader accepted them, false when it refused them with
// InputError or ConfigError. Any other exception propagates.
bool RunFuzzTarget(const FuzzTarget& target, std::span<const std::uint8_t> bytes);

// The valid companion files of the two Panoptic targets (each fuzzes one file and keeps the
// other fixed): a calibration with one HD camera 00_00, a body file with one person.
std::string PanopticCalibrationText();
std::string PanopticBodiesText();

// The fixed companion of the h3wb_json target: a Human3.6M metadata.xml (its cameras differ per
// subject, so the views of a frame agree for one subject only).
std::string H36mMetadataXmlText();
// The fixed COLMAP files of the EgoHumans targets (each target fuzzes one file of the sequence and
// keeps the others): exo cameras cam01 (fisheye) and cam02 (pinhole) and an Aria camera.
std::string EgohumansCamerasText();
std::string EgohumansImagesText();
// The fixed cameras.txt of the calibration_colmap target: a pinhole, an OPENCV and a fisheye
// camera (ids 1, 2, 3).
std::string ColmapCalibrationCamerasText();

}  // namespace rpt::fuzz
