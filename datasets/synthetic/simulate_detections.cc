// SPDX-License-Identifier: MIT
#include "datasets/synthetic/simulate_detections.h"

#include "datasets/synthetic/detector_simulator.h"

namespace rpt {

JointNames SimulatedDetectionJoints(const SimulationOptions& options, const JointNames& gt_joints) {
  if (!options.joints.empty()) return options.joints;
  const bool whole_body = FindJoint(gt_joints, "hand_root_left") >= 0;
  return whole_body ? CocoWholeBodyJoints() : CocoBodyJoints();
}

synthetic::DetectorOptions SimulatedDetectorModel(const SimulationOptions& options) {
  return synthetic::DetectorProfile(options.perfect ? "perfect" : options.detector);
}

uint64_t SimulatedFrameIndex(std::string_view frame_id, size_t position) {
  size_t digits = 0;
  while (digits < frame_id.size() && digits < 18 && frame_id[frame_id.size() - 1 - digits] >= '0' &&
         frame_id[frame_id.size() - 1 - digits] <= '9') {
    ++digits;
  }
  if (digits == 0) return position;
  uint64_t number = 0;
  for (const char c : frame_id.substr(frame_id.size() - digits)) number = number * 10 + static_cast<uint64_t>(c - '0');
  return number;
}

void SimulateDetections(const SimulationOptions& options, Sequence* sequence) {
  const JointNames joints = SimulatedDetectionJoints(options, sequence->gt_joints);
  const synthetic::DetectorSimulator detector(SimulatedDetectorModel(options), joints, options.seed);
  sequence->detection_joints = joints;
  for (size_t f = 0; f < sequence->frames.size(); ++f) {
    SequenceFrame& frame = sequence->frames[f];
    detector.Detect(sequence->cameras, frame.gt, sequence->gt_joints, SimulatedFrameIndex(frame.id, f), &frame.views,
                    nullptr, &frame.labels_2d);
  }
}

}  // namespace rpt
