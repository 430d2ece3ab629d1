// SPDX-License-Identifier: MIT
// Step 12: drop clearly invalid persons and repair joints.
//
// In order: joints of implausible limbs are marked missing (replace_wrong_joints); persons with
// fewer than min_valid_joints joints, a bounding-box diagonal outside [min_extent_m,
// max_extent_m], or a centre outside the room (core/room.h) plus room_margin_m (drop_outside_room) are
// dropped; missing joints take the position of their neighbour joint (fill_missing_joints) with
// score filled_joint_score. Joints placed from one view (provenance kLifted: refine's
// one_view_joints) do not count in the person checks, and of an implausible limb with one such
// end that end is marked missing (else the distal joint).
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/poses.h"
#include "core/room.h"

namespace rpt {

// Fills the missing joints (score <= 0) of one person from their neighbour joints
// (`neighbour[j]`, -1 = none), repeatedly so fills propagate along chains; filled joints get
// `filled_score` and, when `provenance` is not empty (the person's entries), JointProvenance::kFilled.
// Returns the number of joints filled.
int FillMissingJoints(std::span<const int> neighbour, double filled_score, Eigen::Map<Eigen::Matrix4Xd> person,
                      std::span<uint8_t> provenance);

// track.hold_missing_joints for one person whose track's last output is `last` (num_joints x 4,
// column-major): every filled joint (provenance kFilled), and every joint placed from one view
// (kLifted) whose neighbour was not, goes to its neighbour's position plus the offset between the
// two in `last` when both are present there; else a filled joint goes onto its neighbour as
// placed and a lifted one stays. From the torso outwards (a joint once its neighbour is placed).
// `settled` is scratch. Returns the joints placed at an offset.
int HoldFilledJoints(std::span<const int> neighbour, const double* last, Eigen::Map<Eigen::Matrix4Xd> person,
                     std::span<const uint8_t> provenance, std::vector<char>* settled);

namespace steps {

struct PostprocessInput {
  std::span<const int> neighbour;       // per joint of the persons: the joint filling it, -1 = none
  std::span<const ResolvedLimb> limbs;  // limbs between the persons' joints
  const Room& room;                     // the scene's room (the Triangulator's model)
};

// Drops and repairs `persons` in place; adds to stats->replaced_joints and stats->filled_joints.
// Returns the number of persons kept.
int Postprocess(const PostprocessOptions& options, const PostprocessInput& in, Poses3D* persons, FrameStats* stats);

}  // namespace steps

}  // namespace rpt
