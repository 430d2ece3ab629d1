// SPDX-License-Identifier: MIT
// Are the triangulated persons upright? rpt's world has z up (the readers turn every dataset so);
// a calibration whose world z points down, or detections whose pixel rows count from the image's
// bottom (v flipped), give persons standing on their heads, without any other sign: each camera's
// projections still match its detections. A person is judged when its head (nose, eyes or ears)
// and both ankles are triangulated; most judged persons with the head below the ankles is named.
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"

namespace rpt::engine {

inline constexpr long kMinUprightJudged = 20;   // persons judged before anything is said
inline constexpr double kMaxUpsideDownShare = 0.5;

struct UprightCount {
  long judged = 0;       // persons with a triangulated head joint and both ankles
  long upside_down = 0;  // of those: the head's mean z below the ankles' mean z
};

class UprightCheck {
 public:
  explicit UprightCheck(const JointNames& output_joints);
  void Add(const Poses3D& persons);
  const UprightCount& count() const { return count_; }

 private:
  std::vector<int> head_;    // output joint indices of the head joints present
  std::vector<int> ankles_;  // ankle_left, ankle_right (empty when either is missing)
  UprightCount count_;
};

// The warning line of a sequence whose persons are mostly upside down; empty otherwise.
std::string UprightWarning(const std::string& sequence, const UprightCount& count);

}  // namespace rpt::engine
