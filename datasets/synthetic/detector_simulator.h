// SPDX-License-Identifier: MIT
// Simulated 2D pose detector: projects ground-truth 3D poses into each camera and corrupts them
// like a real detector (noise, outliers, dropout, misses, false positives, left/right swaps,
// truncation at the image border; with the fitted model also occluders, confidence-dependent
// heavy-tailed errors, skeleton-definition offsets and calibration error; detector_options.h,
// docs/detector_model.md). Works on any ground truth: joints are matched by name.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/detector_geometry.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::synthetic {

// Where a detected person came from.
struct DetectionSource {
  int gt_person = -1;    // index into the Poses3D persons, -1 for a false positive
  bool swapped = false;  // left/right joints exchanged (all of them)
  int pairs_swapped = 0;  // left/right pairs exchanged one by one (fitted model's pair_swap)
};

class DetectorSimulator {
 public:
  DetectorSimulator(DetectorOptions options, JointNames output_joints, uint64_t seed);

  // Detects the persons of `gt` (joint names `gt_joints`; joints with score <= 0.1 are absent) in
  // every camera. views->at(c) gets camera c's detections with num_joints = output_joints.size();
  // pixels are in the distorted image (Camera::Project). An output joint absent from the GT is
  // missing. Joints behind the camera, outside the image or beyond the lens model's monotonic
  // range are not visible. Randomness depends only on (seed, frame_index, camera index), so
  // frames can be simulated in any order or in parallel with identical results. Thread-safe.
  // `sources`, when given, receives per view and detection where it came from.
  // `labels`, when given, receives per view the GT persons as the simulator saw them: the box of
  // their projected joints (clipped to the image) and per GT joint kLabelVisible, kLabelOccluded
  // (hidden by an occluder: reported displaced or dropped) or kLabelAbsent (outside the image,
  // behind the camera or absent from the GT or the output joints). Persons with no joint in the
  // image are left out.
  void Detect(std::span<const Camera> cameras, const Poses3D& gt, const JointNames& gt_joints, uint64_t frame_index,
              std::vector<Poses2D>* views, std::vector<std::vector<DetectionSource>>* sources = nullptr,
              std::vector<std::vector<PersonLabel2D>>* labels = nullptr) const;

  const DetectorOptions& options() const { return options_; }
  const JointNames& output_joints() const { return output_joints_; }
  // For each output joint, the index of its left/right counterpart (itself when it has none).
  const std::vector<int>& mirror_indices() const { return mirror_; }

 private:
  DetectorOptions options_;
  JointNames output_joints_;
  uint64_t seed_;
  std::vector<int> mirror_;             // left/right partner per output joint
  std::vector<int> from_whole_body_;    // per output joint: index in CocoWholeBodyJoints() or -1
  std::vector<double> joint_factor_;    // per output joint: fitted error factor
  std::vector<double> hidden_drop_;     // per output joint: fitted drop chance when hidden
  std::vector<double> score_factor_;    // per output joint: fitted factor on the confidence
  std::vector<ResolvedOffset> offsets_;  // skeleton-definition offsets of output joints
  std::vector<Bone> bones_;             // silhouettes for the occlusion
  std::vector<double> clutter_;         // per output joint: chance of being hidden by clutter
};


}  // namespace rpt::synthetic
