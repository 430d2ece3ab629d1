// SPDX-License-Identifier: MIT
// Step 10: the pairs of the kept groups again, now with all joints, scored like in steps 6-7
// (joint scores only, with all limbs; proposal_scoring.h). The core joints of these pairs were
// triangulated and scored in steps 4-7 from the same rays; they are copied, not recomputed
// (identical results).
#pragma once

#include <span>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"

namespace rpt {
namespace steps {

// proposals->pairs[i] = core.pairs[members[i]]; core_joints[c] is the output joint of core slot c;
// `limbs` are indexed by output joint. Adds the joints invalidated by limb pruning to
// stats->pruned_limbs. Returns the number of proposals.
int TriangulateFull(const PreparedViews& views, std::span<const ViewGeometry> geometry, const Proposals& core,
                    std::span<const int> members, std::span<const int> core_joints, std::span<const int> all_joints,
                    std::span<const ResolvedLimb> limbs, TriangulationMethod method, const ScoreOptions& score,
                    const NoiseScale& noise, ScoreScratch* scratch, Proposals* proposals, FrameStats* stats);

}  // namespace steps
}  // namespace rpt
