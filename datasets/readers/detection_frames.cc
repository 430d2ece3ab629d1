// SPDX-License-Identifier: MIT
#include "datasets/readers/detection_frames.h"

#include <cmath>
#include <unordered_map>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt {

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
