// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_error_model.h"

#include <algorithm>
#include <cmath>

namespace rpt::synthetic {
namespace {

double DrawScore(double mean, double concentration, Rng& rng) {
  const double m = std::clamp(mean, 1e-3, 1.0 - 1e-3);
  const double k = std::max(concentration, 1e-3);
  return rng.Beta(m * k, (1.0 - m) * k);
}

}  // namespace

Eigen::Vector2d StudentError(double scale_px, double dof, Rng& rng) {
  const double x = rng.Normal();
  const double y = rng.Normal();
  return Eigen::Vector2d(x, y) * (scale_px * rng.StudentScale(dof));
}

JointDraw DrawVisibleJoint(const FittedErrorOptions& options, double pixels_per_metre, double factor, Rng& rng) {
  JointDraw draw;
  draw.reported = true;
  draw.score = options.score_max * DrawScore(options.visible_score_mean, options.visible_score_concentration, rng);
  const double scale =
      options.error_m * pixels_per_metre * factor * std::exp(options.error_growth * (1.0 - draw.score));
  draw.error_px = StudentError(scale, options.error_dof, rng);
  return draw;
}

JointDraw DrawHiddenJoint(const FittedErrorOptions& options, double drop, double pixels_per_metre, Rng& rng) {
  JointDraw draw;
  if (drop > 0.0 && rng.Bernoulli(drop)) return draw;
  draw.reported = true;
  draw.score = options.score_max * DrawScore(options.occluded_score_mean, options.occluded_score_concentration, rng);
  draw.error_px = StudentError(options.occluded_error_m * pixels_per_metre, options.occluded_error_dof, rng);
  return draw;
}

}  // namespace rpt::synthetic
