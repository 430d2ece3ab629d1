// SPDX-License-Identifier: MIT
// The per-joint draws of the fitted detector model: confidence first, then a heavy-tailed pixel
// error given it (visible joints), or drop / medium confidence / large error (hidden joints).
#pragma once

#include <Eigen/Core>

#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/random.h"

namespace rpt::synthetic {

struct JointDraw {
  bool reported = false;
  double score = 0;                                    // before clamping to [score_min, 1]
  Eigen::Vector2d error_px = Eigen::Vector2d::Zero();  // added to the projection
};

// A 2D Student-t vector with per-axis scale `scale_px` (Gaussian for dof <= 0).
Eigen::Vector2d StudentError(double scale_px, double dof, Rng& rng);

// A visible joint: confidence = score_max * Beta(visible_score_*), error scale error_m * pixels_per_metre *
// factor * exp(error_growth * (1 - confidence)). Always reported (dropout is the caller's).
JointDraw DrawVisibleJoint(const FittedErrorOptions& options, double pixels_per_metre, double factor, Rng& rng);

// A hidden joint: dropped with chance `drop`, else confidence = score_max * Beta(occluded_score_*) and an
// error of scale occluded_error_m * pixels_per_metre.
JointDraw DrawHiddenJoint(const FittedErrorOptions& options, double drop, double pixels_per_metre, Rng& rng);

}  // namespace rpt::synthetic
