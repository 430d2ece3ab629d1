// SPDX-License-Identifier: MIT
// Steps 3-4 and 10: triangulate each pose pair into a 3D proposal over a subset of the joints
// (step 3 selects the core joints; step 10 re-triangulates the surviving pairs with all joints).
//
// A joint is triangulated when both views see it; the ray gap (distance between the two viewing
// rays at their closest approach) is recorded for scoring. A pair with fewer than `min_joints`
// triangulated joints yields no proposal.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Triangulates `pairs` over `joints` (indices into the prepared poses) into `proposals`
// (cleared first; proposals->num_joints = joints.size()). Initial joint score is 1 for
// triangulated joints, 0 otherwise. Returns the number of proposals.
int TriangulatePairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                     std::span<const PosePair> pairs, std::span<const int> joints, TriangulationMethod method,
                     int min_joints, Proposals* proposals);

// Step 10: the proposals of the grouped pairs with all joints. proposals->pairs[i] =
// core.pairs[members[i]]; the core joints (core_joints[c] = output joint of core slot c) are copied
// from `core` with their geometric scores, the other joints are triangulated.
int TriangulateMembers(const PreparedViews& views, std::span<const ViewGeometry> geometry, const Proposals& core,
                       std::span<const int> members, std::span<const int> core_joints, int num_joints,
                       TriangulationMethod method, Proposals* proposals);

}  // namespace rpt
