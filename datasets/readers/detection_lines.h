// SPDX-License-Identifier: MIT
// Detections as JSON lines, one frame per line, read as they arrive: the live input of
// `rpt triangulate --follow` (docs/own_data.md, "Live input"). The first line names the joints,
// every other line is one frame in the layout of a frame of the generic detections JSON
// (datasets/readers/generic_detections.h) plus its time:
//
//   {"joints": ["nose", "eye_left", ...]}
//   {"id": "f000001", "time": 0.04, "views": [{"camera": "cam0", "poses": [[[u, v, score], ...], ...]}, ...]}
//
// "id" (a string or an integer; default: the line number) and "time" (seconds; null = unknown;
// default: the frame's index / fps, or unknown without a rate) are optional, "views" is required
// ([] = nothing detected). Cameras are matched by name with the calibration's; a camera a line
// does not list has no persons in that frame. Pixels of the original (distorted) image, scores in
// [0, 1] ((1, 1.5] clamped and counted), a joint null or of score 0 is missing.
//
// Each line is parsed straight into the frame buffer (io::JsonPull): no document is built and a
// warm source allocates nothing. A bad line (not JSON, another shape, an unknown camera, a frame id
// seen in the last kRecentIds frames, a line above the length limit, a frame above the size
// limits) is an InputError
// "<source>:<line>: <place>: <what>"; with skip_bad_lines it is skipped and counted instead
// (reported once the stream ends, as unused input). Blank lines are ignored.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/frame_source.h"
#include "datasets/io/line_reader.h"

namespace rpt {

// Frame ids are checked for repeats against this many frames before (memory flat over an endless
// stream).
inline constexpr std::size_t kRecentIds = 1024;

struct DetectionLinesOptions {
  std::string name;  // the sequence's name
  double fps = 0;    // rate of the lines without "time"; 0 = their times are unknown
  bool skip_bad_lines = false;
  // A frame larger than these (core/pipeline/frame_size.h; the triangulator's options) is a bad
  // line: with skip_bad_lines one burst of false detections does not end the stream.
  int max_persons_per_view = std::numeric_limits<int>::max();
  long long max_pairs_per_frame = std::numeric_limits<long long>::max();
  // With skip_bad_lines: called with the first bad line's error as soon as it is skipped (a live
  // stream's end, where the count is printed, may be hours away); may be empty.
  std::function<void(const std::string& error)> on_first_bad_line;
  // Called with a warning as soon as the stream shows it, for what is otherwise counted only at its
  // end (hours away): the first frame line with an unknown key (a "timestamp" instead of "time"),
  // the first frame without a time when there is no fps (no tracking); may be empty.
  std::function<void(const std::string& warning)> on_early_warning;
};

// What the stream held, kept up to date by the source (read it once the run is over).
struct DetectionLinesCounts {
  long lines = 0;              // every line read, the joints line, blank and bad lines included
  long frames = 0;             // frames handed out
  long bad_lines = 0;          // skipped (with skip_bad_lines)
  std::string first_bad_line;  // the error of the first one
  // When the line of the last frame handed out was read (io::LineReader::line_time): where the
  // latency of its output starts.
  io::LineReader::Clock::time_point frame_line_time{};
};

// Reads the joints line (waiting for it) and returns the source of the frames after it, on the
// `cameras` of `calibration_file` (named in messages). Throws InputError naming the source and
// line 1 when the joints line is missing or bad (even with skip_bad_lines: the frames cannot be
// read without it). `counts` (may be null) must outlive the source.
std::unique_ptr<FrameSource> OpenDetectionLines(std::vector<Camera> cameras, std::unique_ptr<io::LineReader> lines,
                                                const DetectionLinesOptions& options,
                                                const std::filesystem::path& calibration_file,
                                                DetectionLinesCounts* counts = nullptr);

}  // namespace rpt
