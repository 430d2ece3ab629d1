// SPDX-License-Identifier: MIT
// Undistortion (before the paper's step 1): turns the raw 2D poses of all views into undistorted
// keypoints with world rays, adds the derived joints (hip_middle, shoulder_middle, head) and drops
// poses that cannot be triangulated.
//
// The last part applies step 4's rule triangulate.min_core_joints early, and it must stay here: a
// pair's proposal needs that many core joints seen in both of its views (triangulate_core.h), so
// a pose that has fewer valid core joints cannot be in any proposal. Dropping it here keeps it out
// of make_pairs and the pre-filter, whose counts (and the pre-filter's pair budget) depend on it.
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

// views[v] are the detections of cameras[v]. Joints with score < min_joint_score, non-finite
// coordinates or non-finite scores are treated as missing. Returns the number of usable poses.
int Undistort(std::span<const Poses2D> views, std::span<const Camera> cameras, std::span<const ViewGeometry> geometry,
              std::span<const DerivedJointRule> derived, std::span<const int> core_joints, int min_core_joints,
              int num_output_joints, const UndistortOptions& options, PreparedViews* prepared);

}  // namespace steps

}  // namespace rpt
