// SPDX-License-Identifier: MIT
#include "datasets/readers/openpose_body25.h"

namespace rpt {

const JointNames& Body25Joints() {
  static const JointNames names = {
      "nose",           "neck",           "shoulder_right",     "elbow_right",         "wrist_right",
      "shoulder_left",  "elbow_left",     "wrist_left",         "hip_middle",          "hip_right",
      "knee_right",     "ankle_right",    "hip_left",           "knee_left",           "ankle_left",
      "eye_right",      "eye_left",       "ear_right",          "ear_left",            "foot_big_toe_left",
      "foot_small_toe_left", "foot_heel_left", "foot_big_toe_right", "foot_small_toe_right", "foot_heel_right"};
  return names;
}

const std::array<std::pair<int, int>, kBody25Pafs>& Body25PafPairs() {
  static const std::array<std::pair<int, int>, kBody25Pafs> pairs = {{{1, 8},   {9, 10},  {10, 11}, {8, 9},   {8, 12},
                                                                       {12, 13}, {13, 14}, {1, 2},   {2, 3},   {3, 4},
                                                                       {2, 17},  {1, 5},   {5, 6},   {6, 7},   {5, 18},
                                                                       {1, 0},   {0, 15},  {0, 16},  {15, 17}, {16, 18},
                                                                       {14, 19}, {19, 20}, {14, 21}, {11, 22}, {22, 23},
                                                                       {11, 24}}};
  return pairs;
}

}  // namespace rpt
