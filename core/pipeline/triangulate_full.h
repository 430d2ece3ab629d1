// SPDX-License-Identifier: MIT
// Step 10: the pairs of the kept groups again, now with all joints, scored with the frame's
// kernels of steps 6-7 (joint scores only, with all limbs; proposal_scoring.h). The core joints
// of these pairs were triangulated and scored in steps 4-7 from the same rays; they are copied,
// not recomputed (identical results).
#pragma once

#include <span>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"

namespace rpt {
namespace steps {

struct TriangulateFullInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  const Proposals& core;                   // the scored core-joint proposals (steps 4-8)
  const Groups& groups;                    // the kept groups of `core` (step 9)
  std::span<const int> core_joints;        // core slot -> output joint
  std::span<const int> all_joints;         // 0 .. num_output_joints - 1
  std::span<const ResolvedLimb> limbs;     // limbs between output joints
  const ScoreKernel& kernel;               // the frame's kernels (step 6-7)
};

// proposals->pairs[i] = core.pairs[groups.members[i]], triangulated with triangulate.method.
// Adds the joints invalidated by limb pruning to stats->pruned_limbs. Returns the number of
// proposals.
int TriangulateFull(const TriangulateOptions& options, const TriangulateFullInput& in, Proposals* proposals,
                    FrameStats* stats);

}  // namespace steps
}  // namespace rpt
