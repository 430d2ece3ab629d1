// SPDX-License-Identifier: MIT
// The live input of `rpt triangulate --follow`: the cameras of a calibration and the frames of a
// stream of detection lines (datasets/readers/detection_lines.h) read as they arrive, opened as an
// Input like every other (engine/input.h), so the one run loop (engine/run.h) triangulates, tracks
// and smooths them exactly as it does a file. Memory stays flat however long the stream runs:
// frame ids are checked for repeats by the source within a window of recent frames, not kept.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "datasets/io/line_reader.h"
#include "datasets/readers/detection_lines.h"
#include "engine/input.h"

namespace rpt::engine {

// How long the live input polls for the next line without sleeping (io::LineReader::set_spin):
// a line that comes within this time of the last read is taken without a thread wake-up, which is
// slow on an idle machine (docs/own_data.md, Latency). At 30 frames a second it costs at most 0.6 %
// of a core; `--spin-us 0` sleeps at once.
constexpr int kDefaultSpinUs = 200;

struct LiveInputOptions {
  std::string path;             // "-" = standard input; else a named pipe or a file
  bool skip_bad_lines = false;  // count bad lines instead of stopping at the first
  int spin_us = kDefaultSpinUs;  // polling without sleeping before each wait for input, in microseconds
  // At the end of a regular file, seconds to wait for more lines (a detector still writing it;
  // infinity: until the stop request) before the run ends (io::LineReader::set_wait_at_end). 0: the
  // file's end ends the run. A pipe or standard input from a pipe with a wait is a ConfigError.
  double wait_for_lines_s = 0;
  // The triangulator's triangulate.max_persons_per_view and max_pairs_per_frame: a larger frame is
  // a bad line (skipped with skip_bad_lines).
  int max_persons_per_view = std::numeric_limits<int>::max();
  long long max_pairs_per_frame = std::numeric_limits<long long>::max();
  // With skip_bad_lines: the first bad line's error as soon as it is skipped; may be empty.
  std::function<void(const std::string& error)> on_first_bad_line;
  // DetectionLinesOptions::on_early_warning; may be empty.
  std::function<void(const std::string& warning)> on_early_warning;
};

// Opens the stream and reads its joints line (waiting for it), on the calibration spec.cameras
// (any format datasets/calibration reads) with spec.fps for the lines without "time"; the other
// input options must be empty (ConfigError naming them). `stop` ends the wait for input (may be
// null); `counts` (may be null) is kept up to date while the stream is read and must outlive the
// run. Throws InputError naming the file and the line.
Input OpenLiveInput(const InputSpec& spec, const LiveInputOptions& options, std::shared_ptr<const io::StopRequest> stop,
                    DetectionLinesCounts* counts);

// The same on cameras in memory and a reader already open (the latency benchmark feeds a pipe):
// `calibration_name` names the cameras in messages.
Input OpenLiveInput(std::vector<Camera> cameras, std::unique_ptr<io::LineReader> lines,
                    const DetectionLinesOptions& options, const std::string& calibration_name,
                    DetectionLinesCounts* counts, InputWarnings opened = {}, bool strict = false);

}  // namespace rpt::engine
