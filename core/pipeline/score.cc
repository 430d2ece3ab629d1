// SPDX-License-Identifier: MIT
#include "core/pipeline/score.h"

namespace rpt {

int steps::Score(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> core_joints,
                 std::span<const ResolvedLimb> core_limbs, const ScoreOptions& options, NoiseScale* noise,
                 ScoreScratch* scratch, Proposals* proposals, FrameStats* stats) {
  stats->pruned_limbs += ScoreProposals(views, geometry, core_joints, core_limbs, options, noise, scratch, proposals);
  stats->noise_m = options.scale == ScoreScale::kAdaptive ? noise->Estimate() : 0.0;
  return proposals->size();
}

}  // namespace rpt
