// SPDX-License-Identifier: MIT
// Percentage of Correct Parts (PCP), two modes (docs/metrics.md "PCP"):
//  * generic 13-joint PCP (skelda evals.pcp with replace_head_with_nose): 10 parts on COCO-named
//    joints, the head part ending at the nose;
//  * legacy Shelf / Campus PCP (VoxelPose lib/dataset/{shelf,campus}.py evaluate): Shelf14 layout,
//    COCO-17 predictions converted with the head synthesis, per-actor PCP averaged over actors 0-2.
//
// A part (a, b) is correct iff (|P_a - G_a| + |P_b - G_b|) / 2 <= alpha * |G_a - G_b| (non-strict,
// alpha = 0.5). All coordinates in mm.
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/joints.h"
#include "metrics/eval_options.h"
#include "metrics/person_error.h"

namespace rpt::metrics {

// The correctness test of one part (mm). False when any input is NaN.
bool IsPartCorrect(const Eigen::Vector3d& pred_a,
                   const Eigen::Vector3d& pred_b,
                   const Eigen::Vector3d& gt_a,
                   const Eigen::Vector3d& gt_b,
                   double alpha);

// ---------------------------------------------------------------------------------------------
// Generic PCP

// A part endpoint is the mean of two joints (the same name twice for a plain joint).
struct PcpEndpoint {
  std::string joint_1;
  std::string joint_2;
};
struct PcpPartSpec {
  std::string name;
  PcpEndpoint a;
  PcpEndpoint b;
};

// The 10 generic parts, in this order: upper_arm_left/right (shoulder-elbow), lower_arm_left/right
// (elbow-wrist), upper_leg_left/right (hip-knee), lower_leg_left/right (knee-ankle), torso
// (mid-hip -> mid-shoulder), head (mid-shoulder -> nose).
const std::vector<PcpPartSpec>& GenericPcpParts();

// The generic parts resolved against a joint list (the evaluated joints): endpoint joint indices,
// and per part whether all its joints exist in the list.
struct GenericPcpLayout {
  struct Part {
    std::array<int, 2> a{-1, -1};
    std::array<int, 2> b{-1, -1};
    bool defined = false;  // false when a joint of the part is not in the list: never evaluated
  };
  std::vector<Part> parts;  // GenericPcpParts() order
};
GenericPcpLayout MakeGenericPcpLayout(const JointNames& joint_names);

// Outcome of one part for one GT person.
enum class PartOutcome : signed char {
  kNotEvaluated = -1,  // part undefined in the layout, or a GT endpoint joint invalid
  kWrong = 0,          // including: predicted endpoint joint missing, or no prediction at all
  kCorrect = 1,
};

// Outcome of every part for GT person `gt` against `pred` (nullptr = no prediction: every evaluable
// part is wrong). Both persons use the layout's joint order (EvalPerson of the evaluated joints).
std::vector<PartOutcome> EvaluateGenericPcp(const GenericPcpLayout& layout,
                                            const EvalPerson& gt,
                                            const EvalPerson* pred,
                                            double alpha);

// ---------------------------------------------------------------------------------------------
// Legacy Shelf / Campus PCP

using Shelf14 = Eigen::Matrix<double, 3, 14>;  // one column per Shelf14 joint, mm; NaN = missing
using Coco17 = Eigen::Matrix<double, 3, 17>;   // CocoBodyJoints() order, mm; NaN = missing

// Shelf14 joint names (actorsGT.mat order): 0 ankle_right, 1 knee_right, 2 hip_right, 3 hip_left,
// 4 knee_left, 5 ankle_left, 6 wrist_right, 7 elbow_right, 8 shoulder_right, 9 shoulder_left,
// 10 elbow_left, 11 wrist_left, 12 head_bottom, 13 head_top.
const JointNames& Shelf14Joints();

// COCO-17 -> Shelf14 (VoxelPose coco2shelf3D / coco2campus3D). Joints 0..11 copy COCO indices
// 16, 14, 12, 11, 13, 15, 10, 8, 6, 5, 7, 9. With mid_sho = (c5 + c6) / 2, head_center = (c3 + c4) / 2,
// hb = (mid_sho + head_center) / 2 and ht = hb + 2 (head_center - hb):
//  * kCampus: head_bottom = hb, head_top = ht;
//  * kShelf:  top = mid_sho + (c0 - mid_sho) .* (0.75, 0.75, 1.5) (z up), bottom = (mid_sho + c0) / 2,
//             then head_top = 0.75 top + 0.25 ht, head_bottom = 0.75 bottom + 0.25 hb.
// Missing (NaN) COCO joints propagate to every Shelf14 joint computed from them.
// Precondition: layout != kNone.
Shelf14 CocoToShelf14(const Coco17& coco_mm, LegacyPcpLayout layout);

// The 10 legacy parts (VoxelPose order): 0 R lower leg (0-1), 1 R upper leg (1-2), 2 L upper leg (3-4),
// 3 L lower leg (4-5), 4 R lower arm (6-7), 5 R upper arm (7-8), 6 L upper arm (9-10),
// 7 L lower arm (10-11), 8 head (12-13), 9 torso (mid-hip of 2,3 -> 12).
inline constexpr int kNumLegacyParts = 10;
// Reported groups, VoxelPose order: Head {8}, Torso {9}, Upper arms {5, 6}, Lower arms {4, 7},
// Upper legs {1, 2}, Lower legs {0, 3}.
inline constexpr int kNumLegacyGroups = 6;
const std::array<std::string, kNumLegacyGroups>& LegacyPcpGroupNames();

// One GT actor in one frame.
struct LegacyActor {
  int actor_id = 0;  // actorsGT.mat actor index (0-based)
  Shelf14 joints_mm;
};

struct LegacyPcpResult {
  struct Actor {
    int actor_id = 0;
    int num_frames = 0;                              // actor-frames with GT (after skipping)
    double pcp = 0.0;                                // percent, all 10 parts
    std::array<double, kNumLegacyGroups> group_pcp;  // percent, LegacyPcpGroupNames() order
    bool averaged = false;                           // one of the actors average_pcp is over
  };
  std::vector<Actor> actors;  // sorted by actor_id; only actors with GT in some evaluated frame
  // Mean of the per-actor values over actor ids 0..legacy_pcp_actors-1 that have GT (percent).
  double average_pcp = 0.0;
  std::array<double, kNumLegacyGroups> average_group_pcp{};
  // Actor-frames whose nearest prediction has mean joint error < 500 mm, percent of all actor-frames.
  double recall_500 = 0.0;
  int num_frames = 0;          // frames added
  int num_skipped_frames = 0;  // frames without predictions that were skipped (skip flag)
};

// Accumulates legacy PCP frame by frame.
class LegacyPcpEvaluator {
 public:
  // Reads the legacy_pcp_* fields of `options`.
  explicit LegacyPcpEvaluator(const EvalOptions& options);

  // One frame: the GT actors present and all predictions, already in Shelf14 layout (mm).
  // Each actor is matched to the prediction with the smallest mean joint error over the 14 joints
  // (argmin, no threshold; a prediction may serve several actors; missing joints count +inf).
  void AddFrame(std::span<const LegacyActor> gt, std::span<const Shelf14> preds);

  // Adds the frames of `other` (same options), as if they had been added here.
  void Merge(const LegacyPcpEvaluator& other);

  LegacyPcpResult Finalize() const;

 private:
  struct ActorCounts {
    int num_frames = 0;
    std::array<int, kNumLegacyParts> correct{};
  };
  EvalOptions options_;
  std::map<int, ActorCounts> actors_;
  int num_frames_ = 0;
  int num_skipped_frames_ = 0;
  int num_actor_frames_ = 0;
  int num_recalled_ = 0;
};

}  // namespace rpt::metrics
