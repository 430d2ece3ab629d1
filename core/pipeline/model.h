// SPDX-License-Identifier: MIT
// The Triangulator's resolved model: everything fixed when it is built (cameras, view geometry,
// joints, derived-joint rules, core joints, limbs, neighbours, the scene's room and continuity,
// resolved options). Built once by BuildModel() and read-only afterwards; the steps get the parts
// they read through their input structs. The per-frame buffers are in frame_buffers.h, the state
// carried between frames in temporal_state.h.
//
// A step reads its own options section and its inputs, never another step's section: what
// several steps need that is not any step's choice lives here (the room, the continuity gap, the
// score that marks filled joints).
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/single_view.h"
#include "core/pipeline/undistort.h"
#include "core/room.h"

namespace rpt {

struct TriangulatorModel {
  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;  // per camera
  JointNames input_joints;
  JointNames output_joints;            // input joints + derived joints
  TriangulatorOptions options;         // as the user gave them
  TriangulatorOptions resolved;        // what the steps read: `options` with automatic values
                                       // resolved (group.min_group_size = 0 -> 1 or 2)
  std::vector<DerivedJointRule> derived;
  std::vector<int> core_joints;        // step 3: output-joint indices of the core joints
  std::vector<int> core_mirror;        // per core slot: slot of its left/right counterpart
  std::vector<int> all_joints;         // 0 .. num_output_joints-1
  std::vector<ResolvedLimb> core_limbs;  // indexed by core slot
  std::vector<ResolvedLimb> all_limbs;   // indexed by output joint
  LimbColumns core_limb_columns;         // core_limbs and all_limbs as columns (limb pruning's kernel)
  LimbColumns all_limb_columns;
  std::vector<int> neighbour;          // per output joint, -1 = none
  std::vector<TypicalLimb> typical_limbs;  // single_view: limbs with typical lengths
  GroundJoints ground_joints;              // single_view's ground prior: ankles, hips, shoulders

  // The scene and the frames' continuity.
  Room room;             // room_check.center_m / size_m (the dataset's room unless the user set them)
  double max_gap_s = 0;  // track.max_gap_s: frames further apart, or at an unknown time, are not continuous
  // Joints at or below this score are not observations for the temporal steps (bone_lengths,
  // smooth): missing ones (0) and those post-processing filled (TriangulatorOptions::UnobservedScore).
  double unobserved_score = 0;

  int num_core_joints() const { return static_cast<int>(core_joints.size()); }
  int num_output_joints() const { return static_cast<int>(output_joints.size()); }
};

// The limbs whose two joints are both in `names`, as indices into it.
std::vector<ResolvedLimb> ResolveLimbs(const std::vector<LimbSpec>& limbs, const JointNames& names);

// Validates the inputs (ConfigError on bad options, cameras or joint lists) and resolves them.
TriangulatorModel BuildModel(std::vector<Camera> cameras, JointNames input_joints, TriangulatorOptions options);

}  // namespace rpt
