// SPDX-License-Identifier: MIT
// 2D detections independent of their file format, keyed by frame id and camera name, and how
// they attach to a Sequence.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt {

struct FrameDetections {
  std::string frame_id;              // matches SequenceFrame::id
  std::vector<std::string> cameras;  // camera names, one per entry of `views`
  std::vector<Poses2D> views;        // pixels of the original (distorted) image; score 0 = missing
};

struct Detections {
  JointNames joints;                   // joint names of every Poses2D
  std::vector<FrameDetections> frames;
  InputWarnings warnings;              // corrections the reader applied (one line per file and kind)
};

struct AttachReport {
  int frames_with_detections = 0;   // sequence frames that received detections
  int frames_without = 0;           // sequence frames absent from the detections (no persons)
  int unused_frames = 0;            // detection frames whose id is not in the sequence
};

// Sets sequence->detection_joints and every frame's views (camera order of the sequence) from
// `detections`. Cameras are matched by name; a camera the detections do not mention gets no
// persons. Throws InputError naming `source` when a detection camera is not in the sequence,
// when no frame id matches at all, or on joint-count mismatches. `detections.warnings` is not
// copied (one Detections may be attached to several sequences): the caller reports it once.
AttachReport AttachDetections(const Detections& detections, const std::string& source, Sequence* sequence);

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
// Its parts (also used frame by frame: datasets/simulated_source.h): the simulated joints for GT
// with `gt_joints`, and the detector model of the profile.
JointNames SimulatedDetectionJoints(const SimulationOptions& options, const JointNames& gt_joints);
synthetic::DetectorOptions SimulatedDetectorModel(const SimulationOptions& options);

}  // namespace rpt
