// SPDX-License-Identifier: MIT
// Scoring kernels of steps 6-7 (score) and 10 (triangulate_full): reproject each proposal into its
// pair's two views and score every joint.
//
// Per joint i of a proposal from poses a, b, with ray gap g_i (distance between the two viewing
// rays, m) and reprojection errors e_a, e_b (px) in the two views:
//
//   adaptive scale (default): r_i = mean over both views of e * depth / focal length (the
//     reprojection error in metres at the joint), S = scale_factor * the estimated noise level
//     (noise_scale.h), s_rep = exp(-(r_i / S)^2), s_tri = exp(-(g_i / 2S)^2);
//   fixed scale (the first release): r_i = mean over both views of e / bbox_diag (rel),
//     s_rep = exp(-(r_i / reprojection_scale_rel)^2), s_tri = exp(-(g_i / ray_gap_scale_m)^2);
//
//   s_i = s_rep * s_tri (combined) | s_rep (reprojection only) | s_tri (triangulation only)
//   c_i = sqrt(conf_a * conf_b) (2D confidence)         joint score = s_i * c_i (or s_i)
// Implausible limbs (length outside the limb's range) invalidate their distal joint (score 0).
// Pair score = sum_i w_i s_i / sum_i w_i over the joints seen in both views, with w_i = c_i
// (use_confidence) or 1, leaving out the trim_fraction of those joints with the lowest s_i;
// pruned or untriangulatable joints count with s_i = 0.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "core/pipeline/noise_scale.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Reused buffers of the score step.
struct ScoreScratch {
  std::vector<double> residual;       // per proposal and joint (adaptive scale, step 7)
  std::vector<double> pair_residual;  // per proposal: median joint residual (adaptive scale)
  std::vector<double> votes;          // per joint of one proposal
  std::vector<std::pair<double, double>> terms;  // (s_i, w_i) per joint of one proposal
  std::vector<double> best_residual;  // per pose and view: its best partner's pair residual
  std::vector<int> best_partner;      // per pose and view: its best partner pose, -1 = none
};

// The kernel scale in metres: scale_factor x `noise_m` (adaptive), or, for the fixed scale, the
// ray-gap scale halved (the reprojection error at the person is about half the ray gap).
double KernelScaleM(const ScoreOptions& options, double noise_m);

// Joint scores and pair scores (steps 6-7). `joints` maps the proposal's joint slots to
// prepared-pose joint indices; `limbs` are indexed by slot. With the adaptive scale, the frame's
// mutually best pairs first vote into `noise`, whose estimate then sets the kernels (null: the
// prior noise_prior_m is used). Returns the number of joints invalidated by limb pruning.
int ScoreProposals(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                   std::span<const ResolvedLimb> limbs, const ScoreOptions& options, NoiseScale* noise,
                   ScoreScratch* scratch, Proposals* proposals);

// Joint scores only (step 10: only step 8 uses pair scores), with kernels set by `noise`'s current
// estimate; joints already scored by an earlier step for the same pair keep that score. Returns
// the number of joints invalidated by limb pruning.
int ScoreJoints(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                std::span<const ResolvedLimb> limbs, const ScoreOptions& options, const NoiseScale& noise,
                ScoreScratch* scratch, Proposals* proposals);

}  // namespace rpt
