// SPDX-License-Identifier: MIT
// Step 11a (`refine`, an addition): re-triangulate each merged joint from every view of its person
// at once, robustly.
//
// The merge (step 11) averages pair proposals: each is the midpoint of two rays, so a person seen
// in v views gets its joint from up to top_k of the v(v-1)/2 pairs, and each view's noise enters
// through the pairs that happen to be kept. Here each joint of a merged person is fitted to the
// rays of all the person's views that the merge could use for it (the views of the group's pairs
// whose joint score is at least merge.min_joint_score: limb pruning, robust views and the score
// kernels have had their say): the point with the least weighted sum of squared distances to those
// rays, starting from the merged joint and iteratively reweighted (`iterations` times) with
//   w_v = c_v / (1 + (d_v / s)^2),  s = scale_factor x S,
// where c_v is the view's 2D confidence, d_v the distance of its ray from the current point and S
// the frame's score kernel scale (ScoreKernel::scale_m, metres at the joint). A view farther than
// cutoff x s gets no weight (a wrong view that the scores let through). A joint keeps the merged
// position when fewer than 2 views remain or their rays are nearly parallel. The joint's score
// is not changed.
//
// One-view joints (options.one_view_joints, default on): a joint the merge left missing (no
// pair triangulated it) that exactly one of the person's views detected, whose neighbour joint
// (the joint post-processing would fill it from) was triangulated, is placed on that view's ray
// at the point nearest the neighbour (its depth is the neighbour's), with score half its 2D
// confidence and provenance kLifted. Post-processing does not count such joints in its person
// checks and drops them first from implausible limbs (postprocess.h); tracking holds them
// (track.h) where the track's last output has them.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"
#include "core/poses.h"

namespace rpt {

// Scratch buffers reused across frames. Per-joint arrays hold the person's joints side by side,
// padded to simd::kRefineAlign with zeros (the kernels run over whole vectors).
struct RefineScratch {
  std::vector<int> poses;           // the person's 2D poses (its group's pairs)
  std::vector<double> weight;       // per pose and joint: 2D confidence where usable, else 0
  std::vector<double> inv_norm_sq;  // per pose and joint: 1 / |ray|^2 (0 where weight is 0)
  std::vector<double> origin_dot;   // per pose and joint: ray . camera centre
  std::vector<double> x, y, z;      // per joint: the current point
  std::vector<double> person_score; // per joint: the merged joint's score (0: missing)
  std::vector<double> sums;         // per joint: the normal equations (simd::kRefineSums arrays)
  std::vector<double> changed;      // per joint: 1 once a pass moved it
};

namespace steps {

struct RefineInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  const Proposals& proposals;              // triangulate_full's: person i was merged from group i
  const Groups& groups;
  double min_joint_score;                  // merge.min_joint_score: the pairs the merge could use
  const ScoreKernel& kernel;               // the frame's kernels (step 6-7): scale_m
  std::span<const int> neighbour = {};     // per joint: the joint post-processing fills it from, -1 = none
};

// Moves the joints of `persons` (merge's output: person i from group i) to their multi-view fit,
// and with options.one_view_joints places the joints one view saw (below; counted in
// stats->one_view_joints). Returns the number of joints moved.
int Refine(const RefineOptions& options, const RefineInput& in, RefineScratch* scratch, Poses3D* persons,
           FrameStats* stats);

}  // namespace steps

}  // namespace rpt
