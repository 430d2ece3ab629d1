// SPDX-License-Identifier: MIT
// A straightforward implementation of the same algorithm, used as the in-run speed baseline of
// `rpt bench`: every pose pair of every view pair is triangulated with an SVD (dynamic-size
// Eigen) on every joint, there is no pre-filter and no core-joint stage, and every frame builds
// its containers afresh. It scores, filters, groups and merges like the real pipeline so its
// accuracy is comparable.
#pragma once

#include <span>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"

namespace rpt::bench {

class BaselineTriangulator {
 public:
  BaselineTriangulator(std::vector<Camera> cameras, JointNames joints);
  // Persons in metres, joints in the input order.
  Poses3D Process(std::span<const Poses2D> views) const;

 private:
  std::vector<Camera> cameras_;
  JointNames joints_;
};

}  // namespace rpt::bench
