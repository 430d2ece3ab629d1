// SPDX-License-Identifier: MIT
// Step 4: triangulate each pose pair into a 3D proposal over the core joints (step 3 chose them,
// choose_core_joints.h). The step is written for any joint subset; the Triangulator passes the
// core joints.
//
// A joint is triangulated when both views see it (pair_triangulation.h); the ray gap (distance
// between the two viewing rays at their closest approach) is recorded for scoring. A pair with
// fewer than triangulate.min_core_joints triangulated joints yields no proposal.
#pragma once

#include <span>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {
namespace steps {

struct TriangulateCoreInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  std::span<const PosePair> pairs;         // the pairs left by the pre-filter
  std::span<const int> joints;             // prepared-pose joints to triangulate: the core joints
};

// Triangulates the pairs over `joints` into `proposals` (cleared first; proposals->num_joints =
// joints.size()) with triangulate.method. Initial joint score is 1 for triangulated joints, 0
// otherwise. Returns the number of proposals.
int TriangulateCore(const TriangulateOptions& options, const TriangulateCoreInput& in, Proposals* proposals);

}  // namespace steps
}  // namespace rpt
