// SPDX-License-Identifier: MIT
#include "core/pipeline/proposal_scoring.h"

namespace rpt {

double KernelScaleM(const ScoreOptions& options, double noise_m) {
  return options.scale == ScoreScale::kAdaptive ? options.scale_factor * noise_m : 0.5 * options.ray_gap_scale_m;
}

ScoreKernel MakeScoreKernel(const ScoreOptions& options, double noise_m) {
  ScoreKernel kernel;
  kernel.use_reprojection = options.mode != ScoreMode::kTriangulationOnly;
  kernel.use_ray_gap = options.mode != ScoreMode::kReprojectionOnly;
  kernel.adaptive = options.scale == ScoreScale::kAdaptive;
  kernel.use_confidence = options.use_confidence;
  kernel.prune_limbs = options.prune_limbs;
  kernel.scale_m = KernelScaleM(options, noise_m);
  kernel.inv_residual = kernel.adaptive ? 1.0 / kernel.scale_m : 1.0 / options.reprojection_scale_rel;
  kernel.inv_ray_gap = kernel.adaptive ? 0.5 / kernel.scale_m : 1.0 / options.ray_gap_scale_m;
  return kernel;
}

}  // namespace rpt
