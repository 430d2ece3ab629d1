// SPDX-License-Identifier: MIT
// Undistortion (before the paper's step 1): turns the raw 2D poses of all views into undistorted
// keypoints with world rays, adds the derived joints (hip_middle, shoulder_middle, head) and drops
// poses that cannot be triangulated: those with fewer than undistort.min_core_joints valid core
// joints. A pair's proposal needs triangulate.min_core_joints core joints seen in both of its
// views (triangulate_core.h), so with the same value (both default to 3) a pose dropped here could
// not be in any proposal; dropping it here keeps it out of make_pairs and the pre-filter, whose
// counts (and the pre-filter's pair budget) would otherwise include it.
#pragma once

#include <span>
#include <vector>

#include "core/camera.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/poses.h"

namespace rpt {

// A derived joint: output index and alternatives of input-joint indices (first complete wins).
struct DerivedJointRule {
  int output_index = 0;
  std::vector<std::vector<int>> alternatives;
};

namespace steps {

struct UndistortInput {
  std::span<const Poses2D> views;  // this frame's 2D poses, views[v] seen by cameras[v]
  std::span<const Camera> cameras;
  std::span<const ViewGeometry> geometry;     // per camera
  std::span<const DerivedJointRule> derived;  // the derived joints to add
  std::span<const int> core_joints;           // output-joint indices of the core joints (step 3)
  int num_output_joints = 0;                  // input joints + derived joints
};

// Joints with score < min_joint_score, non-finite coordinates or non-finite scores are treated as
// missing. Fills `prepared` (cleared first). Returns the number of usable poses.
int Undistort(const UndistortOptions& options, const UndistortInput& in, PreparedViews* prepared);

}  // namespace steps

}  // namespace rpt
