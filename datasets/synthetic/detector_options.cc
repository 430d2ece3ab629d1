// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_options.h"

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

DetectorOptions DetectorOptions::Realistic() { return DetectorOptions(); }

DetectorOptions DetectorOptions::Hard() { return DetectorOptions(); }

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
