// SPDX-License-Identifier: MIT
// Joint sets by name. Names follow the style nose, shoulder_left, ..., ankle_right.
//
// Body: the 17 COCO joints; with AddDerivedJoints() also hip_middle, shoulder_middle and head
// (the paper's 20). Whole body: the 133 COCO-WholeBody joints (+3 derived = the paper's 136).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rpt {

using JointNames = std::vector<std::string>;

const JointNames& CocoBodyJoints();       // 17
const JointNames& CocoWholeBodyJoints();  // 133 (first 17 = CocoBodyJoints())

// The joints derived from others: hip_middle, shoulder_middle, head.
const JointNames& DerivedJointNames();
// How a derived joint is computed: the mean of the first alternative whose joints are all
// present. hip_middle = mean(hips); shoulder_middle = mean(shoulders); head = mean(ears), else
// mean(eyes), else nose. Empty for a joint that is not derived.
const std::vector<JointNames>& DerivedJointSources(std::string_view name);
// Appends each derived joint whose sources exist in `names` and that is not present yet.
JointNames AddDerivedJoints(const JointNames& names);

// The paper's core joints (step 3): shoulders, hips, elbows, wrists, knees, ankles.
const JointNames& DefaultCoreJoints();

// The 13 joints evaluated in the paper: nose plus the 12 core joints.
const JointNames& EvaluationJoints13();

// The name with its "left" and "right" tokens ('_'-separated) exchanged, e.g. wrist_left ->
// wrist_right, hand_thumb_1_left -> hand_thumb_1_right; unchanged when it has none.
std::string MirrorJointName(std::string_view name);

// +1 for a joint of the left side, -1 for the right side, 0 otherwise (its "left" / "right"
// token, '_'-separated).
int JointSide(std::string_view name);

// For each joint, the index of its left/right counterpart in `names` (itself when none).
std::vector<int> MirrorIndices(const JointNames& names);

// Index of `name` in `names`, or -1.
int FindJoint(const JointNames& names, std::string_view name);

// The neighbouring joint used to fill a missing joint (e.g. wrist_left -> elbow_left,
// face_12 -> nose, hand_index_2_left -> hand_index_1_left). Empty when there is none.
std::string NeighbourJoint(std::string_view name);

// For each joint, the index of its NeighbourJoint in `names` (-1 when none or absent).
std::vector<int> NeighbourIndices(const JointNames& names);

// A limb between two joints with its plausible length range (metres).
struct LimbSpec {
  std::string a;  // proximal joint (closer to the torso)
  std::string b;  // distal joint
  double min_length_m;
  double max_length_m;
};
// Limbs used for pruning; only limbs whose both joints exist in a set are applied.
const std::vector<LimbSpec>& BodyLimbs();
// The body limbs present in `names`, plus for whole-body joints a maximum distance to their
// neighbour joint (feet 0.35 m to the ankle, face 0.3 m to the nose, hand joints 0.15 m).
std::vector<LimbSpec> LimbsFor(const JointNames& names);

}  // namespace rpt
