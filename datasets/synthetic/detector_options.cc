// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_options.h"

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::synthetic {

DetectorOptions DetectorOptions::Perfect() {
  DetectorOptions options;
  options.noise_relative = 0.0;
  options.noise_absolute_px = 0.0;
  options.outlier_probability = 0.0;
  options.outlier_relative = 0.0;
  options.joint_dropout = 0.0;
  options.person_miss = 0.0;
  options.false_positives_per_view = 0.0;
  options.false_positive_score_scale = 1.0;
  options.left_right_swap = 0.0;
  options.min_visible_joints = 1;
  options.score_base = 1.0;
  options.score_error_slope = 0.0;
  options.score_jitter = 0.0;
  options.score_min = 1.0;
  options.shuffle_persons = false;
  return options;
}

DetectorOptions DetectorOptions::Clean() { return DetectorOptions(); }

// Fitted to real OpenPose detections of the 4D-Association Shelf bundle (a room with a shelf,
// 5 cameras, people seen from all sides): rpt detector-stats --dataset shelf-4da versus
// --simulate on the same ground truth and cameras. Shelf has no 2D visibility labels, so how
// hidden joints behave (confidence, error, which are dropped) comes from the MVOR fit (Hard());
// the amount of occlusion, the misses, confidences, noise and skeleton offsets from Shelf.
// docs/detector_model.md has the tables.
DetectorOptions DetectorOptions::Realistic() {
  DetectorOptions options;
  options.joint_dropout = 0.03;
  options.person_miss = 0.01;
  options.false_positives_per_view = 0.2;
  options.false_positive_score_scale = 0.9;
  options.left_right_swap = 0.01;
  options.min_visible_joints = 3;
  options.score_min = 0.05;
  FittedErrorOptions& f = options.fitted;
  f.enabled = true;
  f.score_max = 0.93;
  f.visible_score_mean = 0.88;
  f.visible_score_concentration = 16.0;
  f.error_m = 0.0065;
  f.error_growth = 4.0;
  f.error_dof = 5.0;
  f.person_spread = 0.35;
  f.person_shift_m = 0.012;
  f.stray_probability = 0.02;
  f.stray_error_m = 0.25;
  f.occluded_drop = 0.3;
  f.occluded_score_mean = 0.55;
  f.occluded_score_concentration = 2.5;
  f.occluded_error_m = 0.05;
  f.occluded_error_dof = 6.0;
  f.occluded_snap = 0.1;
  f.person_miss_hidden = 0.4;
  f.false_positive_joint_keep = 0.75;
  f.pair_swap = 0.01;
  f.swap_score_factor = 0.6;
  // Shoulders and hips are inferred when hidden, wrists mostly dropped; hips are less certain.
  f.joints = {{"shoulder_left", 1.0, 0.04, 1.0},  {"shoulder_right", 1.0, 0.04, 1.0},
              {"elbow_left", 1.0, 0.45, 1.0},     {"elbow_right", 1.0, 0.45, 1.0},
              {"wrist_left", 1.0, 0.55, 1.0},     {"wrist_right", 1.0, 0.55, 1.0},
              {"hip_left", 1.0, 0.1, 0.8},        {"hip_right", 1.0, 0.1, 0.8}};
  OcclusionOptions& o = options.occlusion;
  o.enabled = true;
  o.furniture_probability = 0.1;
  o.furniture_top_min_m = -0.45;
  o.furniture_top_max_m = 0.1;
  o.clutter = {{"shoulder_left", 0.1}, {"shoulder_right", 0.1}, {"elbow_left", 0.11},
               {"elbow_right", 0.11},  {"wrist_left", 0.18},    {"wrist_right", 0.18}};
  // The detector's hips and shoulders sit higher than Shelf's labels.
  options.joint_offsets = {{"hip_left", -0.063, 0.0, 0.0},
                           {"hip_right", -0.063, 0.0, 0.0},
                           {"shoulder_left", -0.03, 0.0, 0.0},
                           {"shoulder_right", -0.03, 0.0, 0.0}};
  options.calibration_px = 3.0;
  return options;
}

// Fitted to the OpenPose detections shipped with MVOR (an operating room: 3 cameras, staff
// behind a table, in gowns, holding instruments): rpt detector-stats --dataset mvor versus
// --simulate --detector hard on MVOR's own ground truth and cameras. Much more occlusion
// (furniture in front of 40 % of the people, clutter on the arms), misses and noise than
// realistic, lower confidences, and MVOR's hip labels sit far above the detector's.
DetectorOptions DetectorOptions::Hard() {
  DetectorOptions options;
  options.joint_dropout = 0.015;
  options.person_miss = 0.09;
  options.false_positives_per_view = 0.1;
  options.false_positive_score_scale = 0.68;
  options.left_right_swap = 0.01;
  options.min_visible_joints = 3;
  options.score_min = 0.05;
  FittedErrorOptions& f = options.fitted;
  f.enabled = true;
  f.score_max = 0.92;
  f.visible_score_mean = 0.82;
  f.visible_score_concentration = 7.0;
  f.error_m = 0.0065;
  f.error_growth = 4.0;
  f.error_dof = 10.0;
  f.person_spread = 0.35;
  f.person_shift_m = 0.008;
  f.occluded_drop = 0.3;
  f.occluded_score_mean = 0.52;
  f.occluded_score_concentration = 2.5;
  f.occluded_error_m = 0.075;
  f.occluded_error_dof = 6.0;
  f.occluded_snap = 0.1;
  f.person_miss_hidden = 1.4;
  f.false_positive_joint_keep = 0.55;
  f.pair_swap = 0.02;
  f.swap_score_factor = 0.6;
  f.joints = {{"shoulder_left", 1.0, 0.04, 1.0},  {"shoulder_right", 1.0, 0.04, 1.0},
              {"elbow_left", 1.0, 0.3, 1.0},      {"elbow_right", 1.0, 0.3, 1.0},
              {"wrist_left", 1.0, 0.55, 1.0},     {"wrist_right", 1.0, 0.55, 1.0},
              {"hip_left", 1.0, 0.1, 0.7},        {"hip_right", 1.0, 0.1, 0.7}};
  OcclusionOptions& o = options.occlusion;
  o.enabled = true;
  o.furniture_probability = 0.4;
  o.furniture_top_min_m = -0.45;
  o.furniture_top_max_m = 0.1;
  o.clutter = {{"shoulder_left", 0.23}, {"shoulder_right", 0.23}, {"elbow_left", 0.24},
               {"elbow_right", 0.24},   {"wrist_left", 0.4},      {"wrist_right", 0.4}};
  // The detector's hips sit lower and closer together than MVOR's.
  options.joint_offsets = {{"hip_left", 0.11, -0.045, 0.0}, {"hip_right", 0.11, -0.045, 0.0}};
  options.calibration_px = 2.0;
  return options;
}

const std::vector<std::string>& DetectorProfileNames() {
  static const std::vector<std::string> names = {"perfect", "clean", "realistic", "hard"};
  return names;
}

DetectorOptions DetectorProfile(const std::string& name) {
  if (name == "perfect" || name == "none") return DetectorOptions::Perfect();
  if (name == "clean") return DetectorOptions::Clean();
  if (name == "realistic") return DetectorOptions::Realistic();
  if (name == "hard") return DetectorOptions::Hard();
  throw ConfigError("unknown detector profile " + QuoteName(name) + " (one of " + Join(DetectorProfileNames(), ", ") +
                    "; 'none' = perfect)");
}

}  // namespace rpt::synthetic

