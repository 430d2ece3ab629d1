// SPDX-License-Identifier: MIT
// Steps 6-7: reproject each core-joint proposal into its pair's two views, score every joint
// (the kernels and their formulas: proposal_scoring.h) and the pair, prune impossible limbs.
//
// With the adaptive scale (score.scale = adaptive) the step first measures every proposal's
// residuals, lets the frame's mutually best pairs vote for the detection noise level
// (noise_scale.h), and only then applies the kernels, so even a scene's first frame is scored at
// its own noise level. The kernels it applies are the frame's ScoreKernel, its output for the
// steps that score or judge later (triangulate_full, verify, single_view).
//
// Pair score = sum_i w_i s_i / sum_i w_i over the joints seen in both views, with w_i = c_i
// (use_confidence) or 1, leaving out the trim_fraction of those joints with the lowest s_i;
// pruned or untriangulatable joints count with s_i = 0.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"

namespace rpt {

// Reused buffers of the score step.
struct ScoreScratch {
  std::vector<double> residual;                  // per proposal and joint (adaptive scale)
  std::vector<double> pair_residual;             // per proposal: median joint residual (adaptive scale)
  std::vector<double> votes;                     // per joint of one proposal
  std::vector<std::pair<double, double>> terms;  // (s_i, w_i) per joint of one proposal
  std::vector<double> best_residual;             // per pose and view: its best partner's pair residual
  std::vector<int> best_partner;                 // per pose and view: its best partner pose, -1 = none
};

namespace steps {

struct ScoreInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;    // per camera
  std::span<const int> core_joints;          // proposal slot -> prepared-pose joint
  std::span<const ResolvedLimb> core_limbs;  // limbs between core joints, indexed by slot
  const LimbColumns* core_limb_columns = nullptr;  // the same as columns (null: scalar pruning)
};

// Scores `proposals` (triangulate_core's, after the room check). With the adaptive scale the
// frame's best pairs vote into `noise` (the estimate carried between frames) first. Sets `kernel`
// to the kernels applied. Adds the joints invalidated by limb pruning to stats->pruned_limbs and
// sets stats->noise_m. Returns the number of proposals (all are kept).
int Score(const ScoreOptions& options, const ScoreInput& in, NoiseScale* noise, ScoreScratch* scratch,
          Proposals* proposals, ScoreKernel* kernel, FrameStats* stats);

}  // namespace steps
}  // namespace rpt
