// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_options.h"

#include <algorithm>

#include "core/errors.h"
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

// Fitted to the OpenPose detections shipped with MVOR (rpt detector-stats --dataset mvor versus
// --simulate on the same ground truth and cameras; docs/detector_model.md has both tables).
DetectorOptions DetectorOptions::Realistic() {
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
  // Shoulders and hips are inferred when hidden, wrists mostly dropped; hips are less certain.
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

// Realistic made clearly worse: noisier joints, more clutter and furniture, more misses, false
// positives and swaps, a worse calibration.
DetectorOptions DetectorOptions::Hard() {
  DetectorOptions options = Realistic();
  options.person_miss = 0.15;
  options.false_positives_per_view = 0.3;
  options.left_right_swap = 0.02;
  options.calibration_px = 4.0;
  FittedErrorOptions& f = options.fitted;
  f.error_m *= 1.5;
  f.person_spread = 0.45;
  f.person_shift_m *= 1.5;
  f.occluded_error_m *= 1.3;
  f.person_miss_hidden = 1.6;
  f.pair_swap = 0.04;
  OcclusionOptions& o = options.occlusion;
  o.furniture_probability = 0.7;
  o.furniture_top_min_m = -0.3;
  o.furniture_top_max_m = 0.25;
  for (JointChance& clutter : o.clutter) clutter.probability = std::min(1.0, 1.5 * clutter.probability);
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
  throw ConfigError("unknown detector profile '" + name + "' (one of " + Join(DetectorProfileNames(), ", ") +
                    "; 'none' = perfect)");
}

}  // namespace rpt::synthetic

