// SPDX-License-Identifier: MIT
#include "datasets/readers/detection_frames.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt {
namespace {

// Detected joints further outside their camera's image than this share of its width (u) or
// height (v): detectors place joints inside the image, or a little beyond its edge.
constexpr double kMaxOutsideShare = 0.1;

// Counts, per camera, the detected joints (score > 0) beyond its image by more than
// kMaxOutsideShare of a side: detections of another image size or pixel scale than the
// calibration's (half-resolution video, normalised coordinates read as pixels) or a wrong image size.
void CountJointsOutsideImages(const Detections& detections, const std::vector<std::vector<int>>& view_camera,
                              const std::vector<Camera>& cameras, const std::string& source, InputWarnings* warnings) {
  std::vector<long> outside(cameras.size(), 0);
  std::vector<double> farthest(cameras.size(), 0.0);
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    for (size_t v = 0; v < frame.views.size(); ++v) {
      const int c = view_camera[f][v];
      const double width = cameras[c].width, height = cameras[c].height;
      const Poses2D& view = frame.views[v];
      for (int p = 0; p < view.num_persons(); ++p) {
        const auto person = view.Person(p);
        for (int j = 0; j < view.num_joints; ++j) {
          if (!(person(2, j) > 0)) continue;
          const double beyond = std::max({-person(0, j) / width, (person(0, j) - width) / width,
                                          -person(1, j) / height, (person(1, j) - height) / height});
          if (!(beyond > kMaxOutsideShare)) continue;
          ++outside[c];
          farthest[c] = std::max(farthest[c], beyond);
        }
      }
    }
  }
  for (size_t c = 0; c < cameras.size(); ++c) {
    warnings->Add(source,
                  "detected joints beyond the " + std::to_string(cameras[c].width) + "x" +
                      std::to_string(cameras[c].height) + " image of camera " + QuoteName(cameras[c].name) +
                      " by more than a tenth of its side (the calibration's image size, or the detections' pixel "
                      "scale, wrong?)",
                  "farthest beyond the edge, in image sides", farthest[c], outside[c]);
  }
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
        throw InputError(source + ": frame " + QuoteName(frame.frame_id) + ": camera " + QuoteName(name) + " is not in the calibration " +
                         calibration_file.string() + " (cameras: " + Join(names, ", ") + ")");
      }
      (*view_camera)[f].push_back(it->second);
    }
  }
  CountJointsOutsideImages(detections, *view_camera, cameras, source, &detections.warnings);
  SequenceHeader header;
  header.name = options.name;
  header.cameras = std::move(cameras);
  header.detection_joints = detections.joints;
  header.fps = options.fps;
  InputWarnings warnings = detections.warnings;
  if (options.fps <= 0 && !detections.frames.empty()) {
    warnings.AddMissing(source,
                        "frames without times: nothing is carried between frames (no tracking, no smoothing); "
                        "give the frame rate with --fps",
                        static_cast<long>(detections.frames.size()));
  }
  const size_t num_frames = detections.frames.size();
  const int num_cameras = static_cast<int>(header.cameras.size());
  const int num_joints = static_cast<int>(detections.joints.size());
  auto held = std::make_shared<Detections>(std::move(detections));
  held->warnings = {};  // in the source's warnings
  const double fps = options.fps;
  return std::make_unique<IndexedFrameSource>(
      std::move(header), num_frames,
      [held, view_camera, fps, num_cameras, num_joints](size_t f, SequenceFrame* frame, InputWarnings*) {
        const FrameDetections& in = held->frames[f];
        frame->id = in.frame_id;
        frame->timestamp_s = fps > 0 ? static_cast<double>(f) / fps : kUnknownTime;
        frame->views.resize(static_cast<size_t>(num_cameras));
        for (Poses2D& view : frame->views) view.Clear(num_joints);
        for (size_t v = 0; v < in.views.size(); ++v) frame->views[(*view_camera)[f][v]] = in.views[v];
      },
      std::move(warnings));
}

}  // namespace rpt
