// SPDX-License-Identifier: MIT
// Step 9: group the remaining 3D proposals in 3D space.
//
// Proposals are visited by decreasing pair score. Each joins the existing group whose running
// mean pose is closest (mean distance over the core joints valid in both, at least 2 joints)
// if that distance is below max_distance_m; otherwise it starts a new group. Groups with fewer
// than min_group_size proposals are dropped. Proposals of a person seen in k views form one
// group of up to k(k-1)/2 proposals; proposals of mismatched pairs land far from any person.
//
// With exclusive_poses (an addition to the paper), every 2D pose belongs to at most one person:
// a pose used by several groups stays with the strongest group (largest sum of pair scores) and
// the other groups' proposals that use it are removed. This removes the phantom persons that
// two-view ambiguity creates from poses of different people (they reuse poses that well-supported
// persons already explain) and the duplicates of a person whose proposals split into two groups.
#pragma once

#include <Eigen/Core>
#include <span>
#include <utility>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Scratch buffers reused across frames.
struct GroupScratch {
  std::vector<std::pair<double, int>> keyed;  // (-pair score, proposal), sorted
  std::vector<int> order;                      // proposals in visiting order
  std::vector<Eigen::Vector3d> sum;  // per group and joint
  std::vector<Eigen::Vector3d> running_mean;  // per group and joint: sum / count
  std::vector<int> count;            // per group and joint
  std::vector<int> size;             // per group
  std::vector<Eigen::Vector3d> center_sum;  // per group: sum of member centres
  std::vector<int> center_count;
  std::vector<Eigen::Vector3d> center;  // per group: center_sum / center_count
  std::vector<int> renumber;
  std::vector<double> strength;  // per group: sum of pair scores
  std::vector<int> owner;        // per 2D pose: owning group
  std::vector<Eigen::Vector3d> mean;  // per group and joint (members only)
  std::vector<int> mean_count;
  std::vector<char> lost_members;  // per group: exclusive_poses removed some of its proposals
};

// min_group_size with the automatic value (0) resolved for `num_cameras`: 1 below 10 cameras, 2
// from 10 up. The Triangulator resolves it once (model.h) and leaves the user's options as given.
int ResolveMinGroupSize(const GroupOptions& options, int num_cameras);

namespace steps {

struct GroupInput {
  int num_poses;                // bounds the 2D pose indices of the pairs (prepared poses)
  std::span<const int> mirror;  // per proposal joint slot: the slot of its left/right counterpart (itself when none)
};

// Sets proposals->group (-1 for proposals in dropped groups) and fills `groups` with the kept
// groups' members. `options.min_group_size` must be resolved (> 0). Returns the number of kept
// groups. Sets the stats' small_groups (dropped by min_group_size), conflicting_proposals
// (removed by exclusive_poses) and mirrored_groups (dropped as mirrored duplicates).
int Group(const GroupOptions& options, const GroupInput& in, GroupScratch* scratch, Proposals* proposals,
          Groups* groups, FrameStats* stats);

}  // namespace steps

}  // namespace rpt
