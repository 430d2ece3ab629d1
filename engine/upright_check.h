// SPDX-License-Identifier: MIT
// Are the triangulated persons upright? rpt's world has z up (the readers turn every dataset so);
// a calibration whose world z points down, or detections whose pixel rows count from the image's
// bottom (v flipped), give persons standing on their heads, without any other sign: each camera's
// projections still match its detections. A person is judged when its head (nose, eyes or ears)
// and both ankles are triangulated; most judged persons with the head below the ankles is named,
// and else most of them lying (a world whose up is another axis).
//
// And are they mirror images? Detections of mirrored images in every camera (a webcam's selfie
// view, a flipped video) give persons whose left and right are exchanged, or junk from views that
// do not fit; each camera's projections may still match. A person with nose, shoulders and hips
// triangulated faces the way (mid-shoulder - mid-hip) x (shoulder_right - shoulder_left) points
// (z up, right east: north); its nose lies in front of its shoulders. Real detections put under
// 2 % of persons' noses behind (`rpt triangulate`: MVOR 0.7 %, Shelf-4DA 0.0 %, generated scenes
// with the hard detector 1.2 %), mirrored detections in every camera half (461 of 929 on the
// generated scene of docs/robustness.md's recipe); more than a quarter is named.
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"

namespace rpt::engine {

inline constexpr long kMinUprightJudged = 20;   // persons judged before anything is said
inline constexpr double kMaxUpsideDownShare = 0.5;
// A person lies when its axis from the ankles' midpoint to the head is within 30 degrees of the
// horizontal (|z| under half its length); more than kMaxLyingShare of the judged persons lying is
// named: a world whose up is y (either way) or x puts standing people on their sides. Of the
// persons judged on real detections none lay (MVOR 0 of 72, Shelf-4DA 0 of 827; generated scenes
// of 3, 5 and 16 cameras 0 of 964, 1181 and 703); in a y-down world all of them do.
inline constexpr double kMaxLyingShare = 0.5;
inline constexpr double kMaxMirroredShare = 0.25;
// A hand is judged when both wrists, at least 0.2 m apart, and kMinJudgedHandJoints of its joints
// are triangulated; it lies at the other wrist when its joints' mean distance to the other wrist is
// the smaller. More than half of at least kMinUprightJudged judged hands so is named: the
// detections' left and right hands exchanged (a whole-body user's converter swapped the two
// 21-point blocks: hands 0.5 m off, no warning). Generated whole-body scenes, clean, realistic and
// hard detector, 2 and 3 people: none of 432-1200 judged hands per scene; with the blocks
// exchanged, all of them (`rpt.synthetic.scene(joints="wholebody", ...)` through process_sequence).
inline constexpr int kMinJudgedHandJoints = 5;
inline constexpr double kMaxSwappedHandShare = 0.5;

struct UprightCount {
  long judged = 0;         // persons with a triangulated head joint and both ankles
  long upside_down = 0;    // of those: the head's mean z below the ankles' mean z
  long lying = 0;          // of those: the ankles-to-head axis within 30 degrees of the horizontal
  long facing_judged = 0;  // persons with nose, both shoulders and both hips triangulated
  long mirrored = 0;       // of those: the nose behind the shoulders (left and right exchanged)
  long hands_judged = 0;   // hands with both wrists and kMinJudgedHandJoints of their joints triangulated
  long hands_swapped = 0;  // of those: nearer the other wrist
};

class UprightCheck {
 public:
  explicit UprightCheck(const JointNames& output_joints);
  void Add(const Poses3D& persons);
  const UprightCount& count() const { return count_; }

 private:
  std::vector<int> head_;    // output joint indices of the head joints present
  std::vector<int> ankles_;  // ankle_left, ankle_right (empty when either is missing)
  std::vector<int> facing_;  // nose, shoulder_left, shoulder_right, hip_left, hip_right (empty when one is missing)
  std::vector<int> wrists_;  // wrist_left, wrist_right (empty without both or without hand joints)
  std::vector<int> hand_[2];  // the hand joints of each side (hand_root_left, hand_thumb_1_left, ...)
  UprightCount count_;
};

// The warning line of a sequence whose persons are mostly upside down, or else mostly lying;
// empty otherwise.
std::string UprightWarning(const std::string& sequence, const UprightCount& count);
// The warning line of a sequence whose persons are mirror images more than kMaxMirroredShare of
// the time (at least kMinUprightJudged judged) and not upside down (UprightWarning says those);
// empty otherwise.
std::string MirroredWarning(const std::string& sequence, const UprightCount& count);
// The warning line of a sequence whose hands lie at the other wrist more than kMaxSwappedHandShare
// of the time (at least kMinUprightJudged hands judged); empty otherwise.
std::string SwappedHandsWarning(const std::string& sequence, const UprightCount& count);

}  // namespace rpt::engine
