// SPDX-License-Identifier: MIT
#include "engine/upright_check.h"

#include <cmath>

#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::engine {

UprightCheck::UprightCheck(const JointNames& output_joints) {
  for (const char* name : {"nose", "eye_left", "eye_right", "ear_left", "ear_right"}) {
    if (const int j = FindJoint(output_joints, name); j >= 0) head_.push_back(j);
  }
  const int left = FindJoint(output_joints, "ankle_left"), right = FindJoint(output_joints, "ankle_right");
  if (left >= 0 && right >= 0) ankles_ = {left, right};
  for (const char* name : {"nose", "shoulder_left", "shoulder_right", "hip_left", "hip_right"}) {
    facing_.push_back(FindJoint(output_joints, name));
    if (facing_.back() < 0) {
      facing_.clear();
      break;
    }
  }
  for (int j = 0; j < static_cast<int>(output_joints.size()); ++j) {
    const std::string& name = output_joints[static_cast<size_t>(j)];
    if (!name.starts_with("hand_")) continue;
    if (name.ends_with("_left")) hand_[0].push_back(j);
    if (name.ends_with("_right")) hand_[1].push_back(j);
  }
  const int wrist_left = FindJoint(output_joints, "wrist_left"), wrist_right = FindJoint(output_joints, "wrist_right");
  if (wrist_left >= 0 && wrist_right >= 0 && !hand_[0].empty() && !hand_[1].empty()) {
    wrists_ = {wrist_left, wrist_right};
  }
}

void UprightCheck::Add(const Poses3D& persons) {
  const auto observed = [&](int p, int j) {
    return persons.Person(p)(3, j) > 0 && persons.Provenance(p, j) == JointProvenance::kTriangulated;
  };
  for (int p = 0; p < persons.num_persons() && !facing_.empty(); ++p) {
    bool all = true;
    for (const int j : facing_) all = all && observed(p, j);
    if (!all) continue;
    const auto at = [&](int k) { return persons.Person(p).col(facing_[static_cast<size_t>(k)]).head<3>(); };
    const Eigen::Vector3d shoulders = 0.5 * (at(1) + at(2)), hips = 0.5 * (at(3) + at(4));
    const Eigen::Vector3d forward = (shoulders - hips).cross(at(2) - at(1));
    ++count_.facing_judged;
    count_.mirrored += (at(0) - shoulders).dot(forward) < 0 ? 1 : 0;
  }
  for (int p = 0; p < persons.num_persons() && !wrists_.empty(); ++p) {
    if (!observed(p, wrists_[0]) || !observed(p, wrists_[1])) continue;
    const auto at = [&](int j) { return persons.Person(p).col(j).head<3>(); };
    if ((at(wrists_[0]) - at(wrists_[1])).norm() < 0.2) continue;  // hands together: either wrist fits
    for (int side = 0; side < 2; ++side) {
      double own = 0, other = 0;
      int joints = 0;
      for (const int j : hand_[side]) {
        if (!observed(p, j)) continue;
        own += (at(j) - at(wrists_[side])).norm();
        other += (at(j) - at(wrists_[1 - side])).norm();
        ++joints;
      }
      if (joints < kMinJudgedHandJoints) continue;
      ++count_.hands_judged;
      count_.hands_swapped += other < own ? 1 : 0;
    }
  }
  if (head_.empty() || ankles_.empty()) return;
  for (int p = 0; p < persons.num_persons(); ++p) {
    if (!observed(p, ankles_[0]) || !observed(p, ankles_[1])) continue;
    Eigen::Vector3d head = Eigen::Vector3d::Zero();
    int heads = 0;
    for (const int j : head_) {
      if (!observed(p, j)) continue;
      head += persons.Person(p).col(j).head<3>();
      ++heads;
    }
    if (heads == 0) continue;
    const Eigen::Vector3d axis = head / heads - 0.5 * (persons.Person(p).col(ankles_[0]).head<3>() +
                                                       persons.Person(p).col(ankles_[1]).head<3>());
    ++count_.judged;
    count_.upside_down += axis.z() < 0 ? 1 : 0;
    count_.lying += std::abs(axis.z()) < 0.5 * axis.norm() ? 1 : 0;  // within 30 degrees of the horizontal
  }
}

namespace {

// "<sequence>: N of the M persons with a head and both ankles triangulated (P %) <what>".
std::string JudgedPersonsLine(const std::string& sequence, long n, long judged, const std::string& what) {
  return PrintableText(sequence + ": " + std::to_string(n) + " of the " + std::to_string(judged) +
                       " persons with a head and both ankles triangulated (" +
                       PercentText(static_cast<double>(n) / static_cast<double>(judged)) + ") " + what);
}

}  // namespace

std::string UprightWarning(const std::string& sequence, const UprightCount& count) {
  if (count.judged < kMinUprightJudged) return "";
  if (static_cast<double>(count.upside_down) <= kMaxUpsideDownShare * static_cast<double>(count.judged)) {
    if (static_cast<double>(count.lying) <= kMaxLyingShare * static_cast<double>(count.judged)) return "";
    return JudgedPersonsLine(sequence, count.lying, count.judged,
                             "lie on their sides (ankles to head within 30 degrees of the horizontal; rpt's world "
                             "has z up): does the calibration's world have another axis up (y up or down, as many "
                             "tools' worlds have)? Unless the people do lie (a bed, a floor exercise)");
  }
  return JudgedPersonsLine(sequence, count.upside_down, count.judged,
                           "stand on their heads (head below the ankles; rpt's world has z up): do the detections' "
                           "pixel rows count from the image's top (v down, as OpenCV), and does the calibration's "
                           "world z point up?");
}

std::string SwappedHandsWarning(const std::string& sequence, const UprightCount& count) {
  if (count.hands_judged < kMinUprightJudged ||
      static_cast<double>(count.hands_swapped) <= kMaxSwappedHandShare * static_cast<double>(count.hands_judged)) {
    return "";
  }
  return PrintableText(sequence + ": " + std::to_string(count.hands_swapped) + " of the " +
                       std::to_string(count.hands_judged) + " hands with " + std::to_string(kMinJudgedHandJoints) +
                       " or more joints triangulated (" +
                       PercentText(static_cast<double>(count.hands_swapped) / count.hands_judged) +
                       ") lie at the other wrist: are the detections' left and right hands exchanged (the order of "
                       "their hand joints: hand_root_left and hand_*_left come first)?");
}

std::string MirroredWarning(const std::string& sequence, const UprightCount& count) {
  // Persons on their heads (a v flip is a mirror too) are said by UprightWarning alone.
  if (!UprightWarning(sequence, count).empty() || count.facing_judged < kMinUprightJudged ||
      static_cast<double>(count.mirrored) <= kMaxMirroredShare * static_cast<double>(count.facing_judged)) {
    return "";
  }
  return PrintableText(sequence + ": " + std::to_string(count.mirrored) + " of the " +
                       std::to_string(count.facing_judged) + " persons with nose, shoulders and hips triangulated (" +
                       PercentText(static_cast<double>(count.mirrored) / count.facing_judged) +
                       ") have the nose behind the shoulders, as mirror images have (real detections: under 2 %): "
                       "are the detections of mirrored images in every camera (a webcam's selfie view, a flipped "
                       "video), or left and right exchanged in the joint names? Detections that do not fit the "
                       "cameras at all (another pixel scale, another calibration: `rpt cameras show`, `rpt render` "
                       "show them) give such persons too");
}

}  // namespace rpt::engine
