// SPDX-License-Identifier: MIT
// OpenPose's BODY_25 skeleton: its 25 body parts named in core/joints.h style, and its 26 part
// affinity fields (PAFs, the limbs OpenPose scores between joint candidates) in the order
// 4D-Association stores them (its BODY25 pafDict; parsing the Shelf detection files with this
// table consumes every token exactly).
#pragma once

#include <array>
#include <utility>

#include "core/joints.h"

namespace rpt {

inline constexpr int kBody25Joints = 25;
inline constexpr int kBody25Pafs = 26;

// 0 nose, 1 neck, 2 shoulder_right, 3 elbow_right, 4 wrist_right, 5 shoulder_left, 6 elbow_left,
// 7 wrist_left, 8 hip_middle (OpenPose MidHip), 9 hip_right, 10 knee_right, 11 ankle_right,
// 12 hip_left, 13 knee_left, 14 ankle_left, 15 eye_right, 16 eye_left, 17 ear_right, 18 ear_left,
// 19 foot_big_toe_left, 20 foot_small_toe_left, 21 foot_heel_left, 22 foot_big_toe_right,
// 23 foot_small_toe_right, 24 foot_heel_right.
const JointNames& Body25Joints();

// The joint pairs (a, b) of the 26 PAFs: (1,8) (9,10) (10,11) (8,9) (8,12) (12,13) (13,14) (1,2)
// (2,3) (3,4) (2,17) (1,5) (5,6) (6,7) (5,18) (1,0) (0,15) (0,16) (15,17) (16,18) (14,19) (19,20)
// (14,21) (11,22) (22,23) (11,24). 24 of them form a tree over the 25 joints; (2,17) and (5,18)
// (shoulder to ear) are redundant links.
const std::array<std::pair<int, int>, kBody25Pafs>& Body25PafPairs();

}  // namespace rpt
