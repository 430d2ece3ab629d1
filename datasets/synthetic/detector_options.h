// SPDX-License-Identifier: MIT
// Options of the simulated 2D detector and its named profiles (docs/detector_model.md).
#pragma once

#include <string>
#include <vector>

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
  // The hand-tuned model used before the fit to real detectors: the defaults above.
  static DetectorOptions Clean();
  // Fitted to real detections (the default profile).
  static DetectorOptions Realistic();
  // Clearly worse than realistic: heavier occlusion and noise.
  static DetectorOptions Hard();
};

// Profile names: perfect, clean, realistic, hard.
const std::vector<std::string>& DetectorProfileNames();
// The options of a profile by name ("none" is an alias of "perfect"); ConfigError otherwise.
DetectorOptions DetectorProfile(const std::string& name);

}  // namespace rpt::synthetic
