// SPDX-License-Identifier: MIT
// Steps 6-7: reproject each proposal into its pair's two views and score every joint.
//
// Per joint i of a proposal from poses a, b:
//   reprojection error e_i = mean over both views of |project(X_i) - uv_i| / bbox_diag (rel)
//   ray gap g_i            = distance between the two viewing rays (m)
//   s_rep = exp(-(e_i / reprojection_scale_rel)^2),  s_tri = exp(-(g_i / ray_gap_scale_m)^2)
//   s_i   = s_rep * s_tri (combined) | s_rep (reprojection only) | s_tri (triangulation only)
//   c_i   = sqrt(conf_a * conf_b) (2D confidence)         joint score = s_i * c_i (or s_i)
// Implausible limbs (length outside the limb's range) invalidate their distal joint (score 0).
// Pair score = sum_i w_i s_i / sum_i w_i over the joints seen in both views, with w_i = c_i
// (use_confidence) or 1; pruned or untriangulatable joints count with s_i = 0.
#pragma once

#include <span>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// `joints` maps the proposal's joint slots to prepared-pose joint indices; `limbs` are indexed
// by slot. `pair_scores` = false skips the pair score (step 10: only step 8 uses pair scores).
// Returns the number of joints invalidated by limb pruning.
int ScoreProposals(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                   std::span<const ResolvedLimb> limbs, const ScoreOptions& options, Proposals* proposals,
                   bool pair_scores = true);

}  // namespace rpt
