// SPDX-License-Identifier: MIT
// Steps 6-7: reproject each core-joint proposal into its pair's two views, score every joint and
// the pair, prune impossible limbs (the kernels and their formulas: proposal_scoring.h).
#pragma once

#include <span>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"

namespace rpt {
namespace steps {

// `core_joints` maps proposal slots to prepared-pose joints, `core_limbs` are indexed by slot.
// With the adaptive scale the frame's best pairs vote into `noise` first. Adds the joints
// invalidated by limb pruning to stats->pruned_limbs and sets stats->noise_m. Returns the number
// of proposals (all are kept).
int Score(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> core_joints,
          std::span<const ResolvedLimb> core_limbs, const ScoreOptions& options, NoiseScale* noise,
          ScoreScratch* scratch, Proposals* proposals, FrameStats* stats);

}  // namespace steps
}  // namespace rpt
