// SPDX-License-Identifier: MIT
// Step 11: merge each group's proposals into one 3D person, joint by joint.
//
// For every joint: take the proposals whose joint score is >= min_joint_score, compute their
// mean, drop those farther than max_distance_m from it, keep the top_k closest, and average them
// (weighted by joint score when score_weighted). The merged joint's score is the mean score of
// the kept proposals; a joint with no candidate is missing (score 0). When the distance filter
// drops every candidate (e.g. two proposals that disagree), the highest-scoring candidate is kept
// (keep_best_when_all_far; the paper leaves the joint missing).
#pragma once

#include <utility>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/poses.h"

namespace rpt {

struct MergeScratch {
  std::vector<std::pair<double, int>> candidates;  // (distance to mean, proposal)
  std::vector<double> distances;                   // the SIMD kernel's (simd::MergeGroup)
};

namespace steps {

struct MergeInput {
  const Proposals& proposals;  // all joints (num_joints == persons->num_joints): triangulate_full's
  const Groups& groups;        // group g's proposals are proposals [groups.begin[g], groups.begin[g+1])
};

// Appends one person per group to `persons` (not cleared). Returns the number of persons added.
int Merge(const MergeOptions& options, const MergeInput& in, MergeScratch* scratch, Poses3D* persons);

}  // namespace steps

}  // namespace rpt
