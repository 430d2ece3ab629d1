// SPDX-License-Identifier: MIT
// Simulated 2D pose detector: projects ground-truth 3D poses into each camera and corrupts them
// like a real detector (noise, outliers, dropout, misses, false positives, left/right swaps,
// truncation at the image border). Works on any ground truth: joints are matched by name.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"

namespace rpt::synthetic {

struct DetectorOptions {
  double noise_relative = 0.008;          // fraction of the person's 2D bbox diagonal: per-axis Gaussian pixel sigma
  double noise_absolute_px = 0.5;         // px, added to the relative sigma
  double outlier_probability = 0.01;      // per joint, chance of a heavy-tailed error instead of the normal one
  double outlier_relative = 0.05;         // fraction of the bbox diagonal: per-axis sigma of outlier errors
  double joint_dropout = 0.03;            // per visible joint, chance it is reported missing (score 0)
  double person_miss = 0.03;              // per person and view, chance it is not detected
  double false_positives_per_view = 0.2;  // Poisson mean of spurious persons per view (each seen in one view only)
  double false_positive_score_scale = 0.7;  // factor on the confidences of false positives
  double left_right_swap = 0.01;          // per detected person, chance its left and right joints are exchanged
  int min_visible_joints = 5;             // a person with fewer in-image joints is not detected
  double score_base = 0.95;               // confidence of an error-free joint
  double score_error_slope = 0.1;         // confidence lost per inlier sigma of pixel error
  double score_jitter = 0.03;             // sigma of Gaussian noise added to confidences
  double score_min = 0.05;                // lower clamp of confidences of reported joints (upper clamp: 1)
  bool shuffle_persons = true;            // randomise the order of persons within a view

  // Exact projections, score 1, nothing dropped, missed, swapped or invented; GT order kept.
  // Truncation still applies (a person needs one in-image joint).
  static DetectorOptions Perfect();
  // The defaults above: what the demos use.
  static DetectorOptions Realistic();
};

// Where a detected person came from.
struct DetectionSource {
  int gt_person = -1;    // index into the Poses3D persons, -1 for a false positive
  bool swapped = false;  // left/right joints exchanged
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
  void Detect(std::span<const Camera> cameras, const Poses3D& gt, const JointNames& gt_joints, uint64_t frame_index,
              std::vector<Poses2D>* views, std::vector<std::vector<DetectionSource>>* sources = nullptr) const;

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
};


}  // namespace rpt::synthetic
