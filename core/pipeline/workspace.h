// SPDX-License-Identifier: MIT
// The Triangulator's state: configuration resolved to indices, per-frame buffers (reused, so a
// warm Triangulator does not allocate) and the state carried between frames.
#pragma once

#include <limits>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/pipeline/check_bone_lengths.h"
#include "core/pipeline/group_proposals.h"
#include "core/pipeline/lift_single_views.h"
#include "core/pipeline/merge_groups.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/options.h"
#include "core/pipeline/score_proposals.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/prefilter_pairs.h"
#include "core/pipeline/smooth_tracks.h"
#include "core/pipeline/track_persons.h"
#include "core/pipeline/undistort_poses.h"
#include "core/pipeline/verify_persons.h"

namespace rpt {

struct Workspace {
  // Configuration.
  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;
  JointNames input_joints;
  JointNames output_joints;
  TriangulatorOptions options;
  std::vector<DerivedJointRule> derived;
  std::vector<int> core_joints;        // output-joint indices of the core joints
  std::vector<int> core_mirror;        // per core slot: slot of its left/right counterpart
  std::vector<int> all_joints;         // 0 .. num_output_joints-1
  std::vector<ResolvedLimb> core_limbs;  // indexed by core slot
  std::vector<ResolvedLimb> all_limbs;   // indexed by output joint
  std::vector<int> neighbour;          // per output joint, -1 = none
  std::vector<TypicalLimb> typical_limbs;  // single_view: limbs with typical lengths

  // Per-frame buffers.
  PreparedViews prepared;
  std::vector<PosePair> pairs;
  PrefilterScratch prefilter;
  Proposals core;
  ScoreScratch score_scratch;
  GroupScratch group_scratch;
  Groups groups;
  Proposals full;
  MergeScratch merge_scratch;
  VerifyScratch verify_scratch;
  SingleViewScratch single_view_scratch;
  Poses3D lifted;  // single_view: this frame's persons placed from one view

  // Carried between frames.
  PreviousPersons previous;
  Tracker tracker;
  BoneLengthChecker bone_lengths;  // per-track running limb lengths
  TrackSmoother smoother;          // per-track joint filters
  NoiseScale noise;  // adaptive scoring: the detections' noise level
  double last_timestamp_s = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace rpt
