// SPDX-License-Identifier: MIT
#include "engine/live_input.h"

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/option_codec.h"
#include "datasets/calibration/calibration.h"
#include "datasets/io/input_limits.h"
#include "engine/checked_source.h"

namespace rpt::engine {
namespace {

void CheckLiveSpec(const InputSpec& spec) {
  if (spec.cameras.empty())
    throw ConfigError("--follow needs --cameras FILE (the calibration of the stream's cameras)");
  const auto refuse = [](bool given, const std::string& option) {
    if (given)
      throw ConfigError(option + ": not with --follow (the frames come from the stream; --cameras gives the cameras)");
  };
  refuse(!spec.detections.empty(), "--detections");
  refuse(!spec.dataset.empty(), "--dataset");
  refuse(!spec.labels.empty(), "--labels");
  refuse(!spec.root.empty(), "--root");
  refuse(!spec.params.empty(), "--param");
  refuse(spec.simulate, "--simulate");
  refuse(!spec.mapping.empty(), "the detection mapping flags (--map-*, --coco-*, --openpose-joints, --rename-camera, ...)");
  if (!(spec.fps >= 0)) throw ConfigError("--fps " + std::to_string(spec.fps) + ": expected a rate >= 0");
}

}  // namespace

Input OpenLiveInput(const InputSpec& spec, const LiveInputOptions& options, std::shared_ptr<const io::StopRequest> stop,
                    DetectionLinesCounts* counts) {
  CheckLiveSpec(spec);
  if (options.path.empty()) throw ConfigError("--follow: give a path (a named pipe or a file) or - for standard input");
  InputWarnings opened;
  Calibration calibration = ReadCalibration(spec.cameras, spec.camera_read, &opened);
  // A line is read whole, like a file: the same limit bounds it.
  if (options.spin_us < 0) throw ConfigError("--spin-us " + std::to_string(options.spin_us) + ": expected a time >= 0");
  if (!(options.wait_for_lines_s >= 0))
    throw ConfigError("--wait-for-lines " + FormatNumber(options.wait_for_lines_s) +
                      ": expected seconds >= 0 (inf = until Ctrl-C)");
  auto lines = std::make_unique<io::LineReader>(options.path, io::MaxInputBytes(), std::move(stop));
  lines->set_spin(std::chrono::microseconds(options.spin_us));
  if (options.wait_for_lines_s > 0 && !lines->regular_file())
    throw ConfigError("--wait-for-lines: " + lines->source() +
                      " is not a regular file (a pipe or a terminal ends when its writer closes it); it waits at the "
                      "end of a file only");
  lines->set_wait_at_end(std::chrono::duration<double>(options.wait_for_lines_s));
  DetectionLinesOptions lines_options;
  lines_options.name = options.path == "-" ? "stdin" : std::filesystem::path(options.path).stem().string();
  lines_options.fps = spec.fps;
  lines_options.skip_bad_lines = options.skip_bad_lines;
  lines_options.max_persons_per_view = options.max_persons_per_view;
  lines_options.max_pairs_per_frame = options.max_pairs_per_frame;
  lines_options.on_first_bad_line = options.on_first_bad_line;
  lines_options.on_early_warning = options.on_early_warning;
  return OpenLiveInput(std::move(calibration.cameras), std::move(lines), lines_options, spec.cameras, counts,
                       std::move(opened), spec.strict);
}

Input OpenLiveInput(std::vector<Camera> cameras, std::unique_ptr<io::LineReader> lines,
                    const DetectionLinesOptions& options, const std::string& calibration_name,
                    DetectionLinesCounts* counts, InputWarnings opened, bool strict) {
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(std::make_unique<CheckedSource>(
      OpenDetectionLines(std::move(cameras), std::move(lines), options, calibration_name, counts),
      /*check_ids=*/false));
  Input input(std::move(sources), std::move(opened), strict);
  input.CheckStrict();
  return input;
}

}  // namespace rpt::engine
