// SPDX-License-Identifier: MIT
#include "datasets/detections.h"

#include <unordered_map>

#include "core/errors.h"
#include "datasets/synthetic/detector_simulator.h"

namespace rpt {

AttachReport AttachDetections(const Detections& detections, const std::string& source, Sequence* sequence) {
  std::unordered_map<std::string, int> camera_index;
  for (size_t c = 0; c < sequence->cameras.size(); ++c) camera_index[sequence->cameras[c].name] = static_cast<int>(c);
  std::unordered_map<std::string, const FrameDetections*> by_id;
  for (const FrameDetections& frame : detections.frames) by_id[frame.frame_id] = &frame;

  AttachReport report;
  const int num_joints = static_cast<int>(detections.joints.size());
  sequence->detection_joints = detections.joints;
  for (SequenceFrame& frame : sequence->frames) {
    frame.views.assign(sequence->cameras.size(), Poses2D{});
    for (Poses2D& view : frame.views) view.Clear(num_joints);
    const auto it = by_id.find(frame.id);
    if (it == by_id.end()) {
      ++report.frames_without;
      continue;
    }
    ++report.frames_with_detections;
    const FrameDetections& found = *it->second;
    for (size_t v = 0; v < found.views.size(); ++v) {
      const auto cam = camera_index.find(found.cameras[v]);
      if (cam == camera_index.end()) {
        throw InputError(source + ": frame '" + frame.id + "': camera '" + found.cameras[v] +
                         "' is not a camera of sequence '" + sequence->name + "'");
      }
      if (found.views[v].num_persons() > 0 && found.views[v].num_joints != num_joints) {
        throw InputError(source + ": frame '" + frame.id + "', camera '" + found.cameras[v] + "': " +
                         std::to_string(found.views[v].num_joints) + " joints, expected " + std::to_string(num_joints));
      }
      frame.views[cam->second] = found.views[v];
    }
  }
  report.unused_frames = static_cast<int>(detections.frames.size()) - report.frames_with_detections;
  if (report.frames_with_detections == 0 && !sequence->frames.empty()) {
    throw InputError(source + ": none of its " + std::to_string(detections.frames.size()) +
                     " frame ids matches a frame of sequence '" + sequence->name + "' (e.g. '" +
                     sequence->frames.front().id + "')");
  }
  return report;
}

JointNames SimulatedDetectionJoints(const SimulationOptions& options, const JointNames& gt_joints) {
  if (!options.joints.empty()) return options.joints;
  const bool whole_body = FindJoint(gt_joints, "hand_root_left") >= 0;
  return whole_body ? CocoWholeBodyJoints() : CocoBodyJoints();
}

synthetic::DetectorOptions SimulatedDetectorModel(const SimulationOptions& options) {
  return synthetic::DetectorProfile(options.perfect ? "perfect" : options.detector);
}

void SimulateDetections(const SimulationOptions& options, Sequence* sequence) {
  const JointNames joints = SimulatedDetectionJoints(options, sequence->gt_joints);
  const synthetic::DetectorSimulator detector(SimulatedDetectorModel(options), joints, options.seed);
  sequence->detection_joints = joints;
  for (size_t f = 0; f < sequence->frames.size(); ++f) {
    SequenceFrame& frame = sequence->frames[f];
    detector.Detect(sequence->cameras, frame.gt, sequence->gt_joints, f, &frame.views, nullptr, &frame.labels_2d);
  }
}

}  // namespace rpt
