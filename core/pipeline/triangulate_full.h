// SPDX-License-Identifier: MIT
// Step 10: the pairs of the kept groups again, now with all joints, scored with the frame's
// kernels of steps 6-7 (joint scores only, with all limbs; proposal_scoring.h). The core joints
// of these pairs were triangulated and scored in steps 4-7 from the same rays; they are copied,
// not recomputed (identical results).
//
// With triangulate.robust_views, each group's joints seen in 3 or more of its poses get a consensus
// over views: the rays of those poses, the point that minimises the squared distances to them, and
// repeatedly the view whose removal leaves the others in best agreement (least sum of squared ray
// distances). That view is dropped for the joint when its ray passes farther than robust_min_m from
// the others' point and farther than robust_ratio x the median distance of the others' rays; then
// the next, while 3 or more views remain. The proposals whose pair uses a dropped view get joint
// score 0 for that joint, so the merge (step 11) averages only the pairs of agreeing views: the
// joint is re-triangulated from them. A joint is left as it is when no proposal of agreeing views
// has it. Nothing changes where the views agree (bit for bit).
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
  const ScoreKernel& kernel;               // the frame's kernels (step 6-7)
};

// proposals->pairs[i] = core.pairs[groups.members[i]], triangulated with triangulate.method.
// Adds the joints invalidated by limb pruning to stats->pruned_limbs. Returns the number of
// proposals.
int TriangulateFull(const TriangulateOptions& options, const TriangulateFullInput& in, TriangulateFullScratch* scratch,
                    Proposals* proposals, FrameStats* stats);

}  // namespace steps
}  // namespace rpt
