// SPDX-License-Identifier: MIT
// Step 2: filter pairs with the last frame's 3D poses.
//
// The previous persons' core joints are projected into every view; each 2D pose is matched to
// the closest projected person (mean core-joint distance relative to the pose's bounding-box
// diagonal, below max_distance_rel). A pair is kept when both poses match the same person
// (likely that person) or when neither matches (possibly a new person); it is dropped when only
// one side matches, or the two sides match different persons.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Core joints of the previous frame's persons: `num_core` entries per person; score 0 = missing.
struct PreviousPersons {
  int num_core = 0;
  std::vector<Eigen::Vector3d> xyz;
  std::vector<double> score;
  int size() const { return num_core > 0 ? static_cast<int>(score.size()) / num_core : 0; }
  void Clear(int core) {
    num_core = core;
    xyz.clear();
    score.clear();
  }
};

// Matches every pose to a previous person (-1 = none) into `match`, then compacts `pairs`.
// Returns the number of pairs kept. Does nothing (keeps all) when there are no previous persons.
int PrefilterPairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                   std::span<const int> core_joints, const PreviousPersons& previous,
                   const PrefilterOptions& options, std::vector<int>* match, std::vector<PosePair>* pairs);

}  // namespace rpt
