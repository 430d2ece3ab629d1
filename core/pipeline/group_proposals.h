// SPDX-License-Identifier: MIT
// Step 9: group the remaining 3D proposals in 3D space.
//
// Proposals are visited by decreasing pair score. Each joins the existing group whose running
// mean pose is closest (mean distance over the core joints valid in both, at least 2 joints)
// if that distance is below max_distance_m; otherwise it starts a new group. Groups with fewer
// than min_group_size proposals are dropped. Proposals of a person seen in k views form one
// group of up to k(k-1)/2 proposals; proposals of mismatched pairs land far from any person.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Scratch buffers reused across frames.
struct GroupScratch {
  std::vector<int> order;
  std::vector<Eigen::Vector3d> sum;  // per group and joint
  std::vector<int> count;            // per group and joint
  std::vector<int> size;             // per group
  std::vector<int> renumber;
};

// Sets proposals->group (-1 for proposals in dropped groups) and fills `groups` with the kept
// groups' members. Returns the number of kept groups; *small_groups gets the number dropped.
int GroupProposals(const GroupOptions& options, Proposals* proposals, Groups* groups, GroupScratch* scratch,
                   int* small_groups);

}  // namespace rpt
