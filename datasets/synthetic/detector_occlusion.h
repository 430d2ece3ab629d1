// SPDX-License-Identifier: MIT
// Occluders of the simulated detector: which joints of which person are hidden in one view, by
// other persons (depth-ordered silhouettes), by the person's own torso, or by furniture in front
// of the lower body (docs/detector_model.md).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "datasets/synthetic/detector_geometry.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::synthetic {

struct ViewOcclusion {
  std::vector<std::vector<char>> hidden;   // per person, per joint
  std::vector<std::vector<int>> occluder;  // per person, per joint: the hiding person; -1 furniture or own torso
};

// `points[p]` are person p's world points per joint, `present[p]` which exist; `bones`, `body`
// and `clutter` (per joint: OcclusionOptions::clutter resolved) index the same joints.
// Furniture is drawn from (seed, camera index, track id, block of frames), clutter from (seed,
// frame index, camera index, track id); track_ids[p] < 0 uses p. Only joints in front of the
// camera can be hidden.
void ComputeOcclusion(const OcclusionOptions& options, const std::vector<Bone>& bones, const BodyJoints& body,
                      const std::vector<double>& clutter,
                      const Camera& camera, const std::vector<Eigen::Matrix3Xd>& points,
                      const std::vector<std::vector<char>>& present, const std::vector<int>& track_ids, uint64_t seed,
                      uint64_t frame_index, uint64_t camera_index, ViewOcclusion* out);

}  // namespace rpt::synthetic
