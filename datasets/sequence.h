// SPDX-License-Identifier: MIT
// The dataset-independent representation every reader produces: cameras, the capture volume,
// and frames with ground-truth 3D persons and 2D detections, all in metres and the world frame.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"
#include "datasets/input_warnings.h"

namespace rpt {

struct Room {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // <= 0 on an axis: unbounded
};

struct SequenceFrame {
  std::string id;                // unique label id (e.g. "shelf_000300")
  double timestamp_s = 0;        // for speed clipping and tracking
  Poses3D gt;                    // ground truth; joint score = visibility (> 0.1 visible)
  std::vector<Poses2D> views;    // detections per camera (may be empty when not loaded)
};

struct Sequence {
  std::string name;                 // e.g. "shelf", "panoptic/160906_band1"
  std::vector<Camera> cameras;
  JointNames gt_joints;             // joint names of SequenceFrame::gt
  JointNames detection_joints;      // joint names of SequenceFrame::views
  JointNames evaluated_joints;      // the dataset's evaluated joints; empty = the paper's 13
  Room room;
  double fps = 0;
  std::vector<SequenceFrame> frames;
  InputWarnings warnings;           // corrections the reader applied (one line per file and kind)
};

// Checks shapes and values (camera validity, joint counts, finite coordinates, scores in [0, 1],
// unique frame ids). Throws InputError naming `source`, the frame id and the view on failure.
// Strict on purpose: readers correct real-world imprecision first (rotations re-orthonormalised,
// scores clamped; datasets/input_warnings.h), so a reader's Sequence always passes.
void ValidateSequence(const Sequence& sequence, const std::string& source);

}  // namespace rpt
