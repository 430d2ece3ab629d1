// SPDX-License-Identifier: MIT
#include "datasets/readers/detection_frames.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/image_range_check.h"

namespace rpt {
namespace {

// The number an id ends in ("000040", "take1_000040" -> 40); -1 for an id without one (or with
// more than 15 digits).
long long TrailingNumber(const std::string& id) {
  size_t first = id.size();
  while (first > 0 && id[first - 1] >= '0' && id[first - 1] <= '9') --first;
  const size_t digits = id.size() - first;
  if (digits == 0 || digits > 15) return -1;
  return std::stoll(id.substr(first));
}

// Frame times at `fps` (> 0). When every frame id ends in a number, the numbers increase, and most
// steps between them are 1 (a frame counter), frame f is at (its number - the first frame's) / fps,
// so frames missing from the file (a detector that skipped some, files deleted from an OpenPose
// folder) leave a gap in time instead of shifting the frames after them; the skipped numbers are
// counted in a warning. Otherwise frame f is at f / fps (the file's order), and ids whose numbers
// do not increase (frames out of order) are counted.
std::vector<double> FrameTimes(const std::vector<FrameDetections>& frames, double fps, const std::string& source,
                               InputWarnings* warnings) {
  std::vector<double> times(frames.size());
  std::vector<long long> numbers(frames.size());
  bool numbered = true;
  long not_increasing = 0;
  long long skipped = 0;
  std::string first_back;
  for (size_t f = 0; f < frames.size(); ++f) {
    numbers[f] = TrailingNumber(frames[f].frame_id);
    numbered = numbered && numbers[f] >= 0;
    if (!numbered || f == 0) continue;
    if (numbers[f] <= numbers[f - 1]) {
      if (not_increasing++ == 0) first_back = QuoteName(frames[f].frame_id) + " after " + QuoteName(frames[f - 1].frame_id);
    } else {
      skipped += numbers[f] - numbers[f - 1] - 1;
    }
  }
  // Frame counters step by 1 between most frames; other numbers (capture times in milliseconds,
  // every 10th frame exported) are not frame indices at --fps.
  bool by_number = false;
  if (numbered && not_increasing == 0 && frames.size() >= 2) {
    long ones = 0;
    for (size_t f = 1; f < frames.size(); ++f) ones += numbers[f] - numbers[f - 1] == 1 ? 1 : 0;
    by_number = 2 * ones > static_cast<long>(frames.size() - 1);
  }
  for (size_t f = 0; f < frames.size(); ++f) {
    times[f] = by_number ? static_cast<double>(numbers[f] - numbers[0]) / fps : static_cast<double>(f) / fps;
  }
  if (by_number) {
    warnings->AddMissing(source,
                         "frame numbers missing between the frame ids (frames the detections skip): the times follow "
                         "the ids' numbers at --fps, with a gap there",
                         static_cast<long>(skipped));
  } else if (numbered && not_increasing == 0 && frames.size() >= 3) {
    // Every id a constant k > 1 after the one before (a detector run on every k-th frame): at
    // --fps the frames are 1 / fps apart, not k / fps, which halves speeds for k = 2 unseen.
    const long long step = numbers[1] - numbers[0];
    bool constant = step > 1 && step <= 10;  // larger steps: capture times (ms), not a frame skip
    for (size_t f = 2; f < frames.size() && constant; ++f) constant = numbers[f] - numbers[f - 1] == step;
    if (constant) {
      warnings->AddMissing(source,
                           "frames whose id's number is " + std::to_string(step) +
                               " after the previous frame's (a counter's frames, " + std::to_string(step) +
                               " apart?): the times follow the file's order, frame i at i / --fps; "
                               "if the ids count the camera's frames, give --fps as its rate / " +
                               std::to_string(step),
                           static_cast<long>(frames.size() - 1));
    }
  } else if (numbered && not_increasing > 0) {
    warnings->AddMissing(source,
                         "frames whose id's number is not after the previous frame's (first " + first_back +
                             "): out of order, so the times follow the file's order (frame i at i / --fps) and "
                             "tracks jump there; sort the frames by time",
                         not_increasing);
  }
  return times;
}

}  // namespace

std::unique_ptr<FrameSource> OpenDetectionFrames(std::vector<Camera> cameras, Detections detections,
                                                 const DetectionFramesOptions& options,
                                                 const std::filesystem::path& calibration_file,
                                                 const std::filesystem::path& detections_file) {
  const std::string source = detections_file.string();
  std::unordered_map<std::string, int> camera_idx;
  std::vector<std::string> names;
  for (size_t c = 0; c < cameras.size(); ++c) {
    camera_idx.emplace(cameras[c].name, static_cast<int>(c));
    names.push_back(cameras[c].name);
  }
  // Per detection frame and view: the calibration camera it belongs to (checked before any frame).
  auto view_camera = std::make_shared<std::vector<std::vector<int>>>(detections.frames.size());
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    for (const std::string& name : frame.cameras) {
      const auto it = camera_idx.find(name);
      if (it == camera_idx.end()) {
        throw InputError(source + ": frame " + QuoteName(frame.frame_id) + ": camera " + QuoteName(name) +
                         DidYouMeanSpelling(name, names) + " is not in the calibration " + calibration_file.string() +
                         " (cameras: " + JoinNames(names, ", ") +
                         "); when it is one of those under another name, "
                         "--rename-camera " +
                         name + "=NAME maps it");
      }
      (*view_camera)[f].push_back(it->second);
    }
  }
  {
    ImageRangeCheck image_range(cameras);
    for (size_t f = 0; f < detections.frames.size(); ++f) {
      for (size_t v = 0; v < detections.frames[f].views.size(); ++v) {
        image_range.Add((*view_camera)[f][v], detections.frames[f].views[v]);
      }
    }
    image_range.AddWarnings(source, &detections.warnings);
  }
  SequenceHeader header;
  header.name = options.name;
  header.cameras = std::move(cameras);
  header.detection_joints = detections.joints;
  header.fps = options.fps;
  InputWarnings warnings = detections.warnings;
  // The file's own times ("time" of generic JSON) where it gives any; else from --fps.
  const long frames_with_time = std::count_if(detections.frames.begin(), detections.frames.end(),
                                              [](const FrameDetections& frame) { return std::isfinite(frame.time_s); });
  if (frames_with_time > 0) {
    warnings.AddMissing(source, "frames without a \"time\" where other frames have one: their times are unknown",
                        static_cast<long>(detections.frames.size()) - frames_with_time);
    // --fps as well: it is the rate exports state (TRC's DataRate, "fps"); say when the times differ.
    std::vector<double> steps;
    double last = kUnknownTime;
    for (const FrameDetections& frame : detections.frames) {
      if (std::isfinite(frame.time_s) && std::isfinite(last) && frame.time_s > last) steps.push_back(frame.time_s - last);
      if (std::isfinite(frame.time_s)) last = frame.time_s;
    }
    if (options.fps > 0 && !steps.empty()) {
      const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
      std::nth_element(steps.begin(), middle, steps.end());
      const double rate = 1.0 / *middle;
      if (std::abs(rate - options.fps) > 0.1 * options.fps) {
        warnings.Add(source,
                     "frame rates given with --fps (" + FormatNumber(options.fps) +
                         ") that the frames' \"time\" contradict: the times are used, --fps is the rate the exports "
                         "state (TRC DataRate, \"fps\"); leave it out or give the recording's rate",
                     "frames per second of the median time step", rate, 1);
      }
    }
  } else if (options.fps <= 0 && !detections.frames.empty()) {
    warnings.AddMissing(source,
                        "frames without times: nothing is carried between frames (no tracking, no smoothing); "
                        "give the frame rate with --fps (or a \"time\" per frame)",
                        static_cast<long>(detections.frames.size()));
  }
  const size_t num_frames = detections.frames.size();
  const int num_cameras = static_cast<int>(header.cameras.size());
  const int num_joints = static_cast<int>(detections.joints.size());
  auto held = std::make_shared<Detections>(std::move(detections));
  held->warnings = {};  // in the source's warnings
  std::vector<double> frame_times;
  if (frames_with_time > 0) {
    for (const FrameDetections& frame : held->frames) frame_times.push_back(frame.time_s);
  } else if (options.fps > 0) {
    frame_times = FrameTimes(held->frames, options.fps, source, &warnings);
  }
  auto times = std::make_shared<const std::vector<double>>(std::move(frame_times));
  auto mentioned = std::make_shared<const std::vector<char>>(CamerasMentioned(*held, names));
  // A camera the file never names gave nothing in the whole take (its OpenPose folder absent, a
  // detector that did not run for it): said, as the most common failure of a multi-camera rig.
  std::vector<std::string> never;
  for (size_t c = 0; c < names.size(); ++c) {
    if (!(*mentioned)[c]) never.push_back(names[c]);
  }
  if (!held->frames.empty() && !never.empty()) {
    warnings.AddMissing(source,
                        "cameras of the calibration the detections never name, so nothing of theirs in any frame "
                        "(cameras " + JoinNames(never, ", ") + "): triangulated from the others",
                        static_cast<long>(never.size()));
  }
  return std::make_unique<IndexedFrameSource>(
      std::move(header), num_frames,
      [held, view_camera, times, mentioned, num_cameras, num_joints](size_t f, SequenceFrame* frame, InputWarnings*) {
        const FrameDetections& in = held->frames[f];
        frame->id = in.frame_id;
        frame->timestamp_s = times->empty() ? kUnknownTime : (*times)[f];
        frame->views.resize(static_cast<size_t>(num_cameras));
        for (Poses2D& view : frame->views) view.Clear(num_joints);
        std::vector<char> listed(static_cast<size_t>(num_cameras), 0);
        for (size_t v = 0; v < in.views.size(); ++v) {
          frame->views[(*view_camera)[f][v]] = in.views[v];
          listed[(*view_camera)[f][v]] = 1;
        }
        MarkUnavailableViews(*held, /*frame_in_file=*/true, listed, *mentioned, frame->views);
      },
      std::move(warnings));
}

}  // namespace rpt
