// SPDX-License-Identifier: MIT
// Step 12: drop clearly invalid persons and repair joints.
//
// In order: joints of implausible limbs are marked missing (replace_wrong_joints); persons with
// fewer than min_valid_joints joints, a bounding-box diagonal outside [min_extent_m,
// max_extent_m], or a centre outside the room are dropped; missing joints take the position of
// their neighbour joint (fill_missing_joints) with score filled_joint_score.
#pragma once

#include <span>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/poses.h"

namespace rpt {

// Fills the missing joints (score <= 0) of one person from their neighbour joints
// (`neighbour[j]`, -1 = none), repeatedly so fills propagate along chains; filled joints get
// `filled_score`. Returns the number of joints filled.
int FillMissingJoints(std::span<const int> neighbour, double filled_score, Eigen::Map<Eigen::Matrix4Xd> person);

namespace steps {

// `neighbour[j]` is the joint filling j (-1 = none); `limbs` index the persons' joints.
// Returns the number of persons kept.
int Postprocess(const PostprocessOptions& options, const RoomCheckOptions& room, std::span<const int> neighbour,
                std::span<const ResolvedLimb> limbs, Poses3D* persons, FrameStats* stats);

}  // namespace steps

}  // namespace rpt
