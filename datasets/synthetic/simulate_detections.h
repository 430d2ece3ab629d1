// SPDX-License-Identifier: MIT
// Simulated 2D detections of a sequence's ground truth (the synthetic detector model with one of
// its profiles), for `--simulate` and `rpt detector-stats --compare`: a whole sequence at once
// here, frame by frame in SimulatedDetectionsSource (datasets/synthetic/simulated_source.h), with
// the same numbers.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/joints.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt {

// Replaces every frame's views by simulated detections of its GT (synthetic detector model,
// joints mapped by name to `joints`; default: COCO-17, or COCO-WholeBody when the GT has it), and
// its labels_2d by the simulator's view of the GT (which joints it treated as occluded).
struct SimulationOptions {
  uint64_t seed = 1;
  std::string detector = "realistic";  // profile: perfect | clean | realistic | hard (docs/detector_model.md)
  bool perfect = false;   // deprecated: same as detector = "perfect"
  JointNames joints;      // empty = automatic as above
};
void SimulateDetections(const SimulationOptions& options, Sequence* sequence);
// Its parts (also used frame by frame: datasets/synthetic/simulated_source.h): the simulated joints for GT
// with `gt_joints`, and the detector model of the profile.
JointNames SimulatedDetectionJoints(const SimulationOptions& options, const JointNames& gt_joints);
synthetic::DetectorOptions SimulatedDetectorModel(const SimulationOptions& options);
// The frame index the simulator's randomness of a frame depends on: the number its id ends in
// ("shelf_000300" -> 300, "panoptic_160906_band1_000180" -> 180; at most 18 digits), else its
// position in the sequence. So a frame's detections do not depend on which other frames were
// selected (frames=, every=, days=): a subset's run is a subset of the whole run's.
uint64_t SimulatedFrameIndex(std::string_view frame_id, size_t position);

}  // namespace rpt
