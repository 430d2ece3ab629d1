// SPDX-License-Identifier: MIT
// Step 10: the pairs of the kept groups again, now with all joints, scored with the frame's
// kernels of steps 6-7 (joint scores only, with all limbs; proposal_scoring.h). The core joints
// of these pairs were triangulated and scored in steps 4-7 from the same rays; they are copied,
// not recomputed (identical results).
//
// With triangulate.robust_views, each group's joints seen in 3 or more of its poses get a consensus
// over views. For every view, the others' rays give a point (least squares over the distances to
// the rays); the view's disagreement is its ray's distance from that point, divided by
// sqrt(1 + that point's variance along the offset per unit of ray noise), so that two rays meeting
// at a narrow angle, which fix their point poorly in depth, do not outvote a third view. The view
// that disagrees most is dropped for the joint when its disagreement exceeds robust_min_m and its
// distance robust_ratio x the median distance of the other views' rays; then the next, while 3 or
// more views remain. The proposals whose pair uses a dropped view get joint score 0 for that
// joint, so the merge (step 11) averages only the pairs of agreeing views: the joint is
// re-triangulated from them. A joint is left as it is when no proposal of agreeing views has it.
// Nothing changes where the views agree (bit for bit).
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"

namespace rpt {
struct TriangulateFullScratch {
  struct View {
    int pose = 0;
    Eigen::Vector3d center, ray;  // ray: unit direction
    bool dropped = false;
  };
  std::vector<int> poses;           // the group's distinct poses
  std::vector<View> views;          // the poses that see the current joint
  std::vector<double> distances;    // ray distances of the other views (median)
};

namespace steps {

struct TriangulateFullInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  const Proposals& core;                   // the scored core-joint proposals (steps 4-8)
  const Groups& groups;                    // the kept groups of `core` (step 9)
  std::span<const int> core_joints;        // core slot -> output joint
  std::span<const int> all_joints;         // 0 .. num_output_joints - 1
  std::span<const ResolvedLimb> limbs;     // limbs between output joints
  const LimbColumns* limb_columns = nullptr;  // the same as columns (null: scalar pruning)
  const ScoreKernel& kernel;               // the frame's kernels (step 6-7)
};

// proposals->pairs[i] = core.pairs[groups.members[i]], triangulated with triangulate.method.
// Adds the joints invalidated by limb pruning to stats->pruned_limbs. Returns the number of
// proposals.
int TriangulateFull(const TriangulateOptions& options, const TriangulateFullInput& in, TriangulateFullScratch* scratch,
                    Proposals* proposals, FrameStats* stats);

}  // namespace steps
}  // namespace rpt
