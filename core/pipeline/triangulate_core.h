// SPDX-License-Identifier: MIT
// Step 4: triangulate each pose pair into a 3D proposal over the core joints (step 3 chose them,
// choose_core_joints.h). The step is written for any joint subset; the Triangulator passes the
// core joints.
//
// A joint is triangulated when both views see it (pair_triangulation.h); the ray gap (distance
// between the two viewing rays at their closest approach) is recorded for scoring. A pair with
// fewer than `min_joints` (triangulate.min_core_joints) triangulated joints yields no proposal.
#pragma once

#include <span>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {
namespace steps {

// Triangulates `pairs` over `joints` (indices into the prepared poses) into `proposals`
// (cleared first; proposals->num_joints = joints.size()). Initial joint score is 1 for
// triangulated joints, 0 otherwise. Returns the number of proposals.
int TriangulateCore(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const PosePair> pairs,
                    std::span<const int> joints, TriangulationMethod method, int min_joints, Proposals* proposals);

}  // namespace steps
}  // namespace rpt
