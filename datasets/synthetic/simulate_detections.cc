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
