// SPDX-License-Identifier: MIT
// Step 3: choose the core joints, the joints steps 4-9 associate poses with (shoulders, hips,
// elbows, wrists, knees, ankles unless triangulate.core_joints says otherwise). The choice depends
// only on the options and the joint list, so it runs once, when the Triangulator builds its model
// (model.h), and has no per-frame timing row.
#pragma once

#include <vector>

#include "core/joints.h"
#include "core/pipeline/options.h"

namespace rpt {
namespace steps {

// Output-joint indices of the core joints, in the order of triangulate.core_joints (or
// DefaultCoreJoints()). Throws ConfigError when a core joint is not among `output_joints` or when
// triangulate.min_core_joints exceeds their number.
std::vector<int> ChooseCoreJoints(const TriangulateOptions& options, const JointNames& output_joints);

}  // namespace steps
}  // namespace rpt
