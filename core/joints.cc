// SPDX-License-Identifier: MIT
#include "core/joints.h"

#include <algorithm>
#include <array>
#include <string>

namespace rpt {
namespace {

JointNames MakeWholeBody() {
  JointNames names = CocoBodyJoints();
  for (const char* side : {"left", "right"}) {
    for (const char* part : {"foot_big_toe", "foot_small_toe", "foot_heel"}) {
      names.push_back(std::string(part) + "_" + side);
    }
  }
  for (int i = 0; i < 68; ++i) {
    names.push_back((i < 10 ? "face_0" : "face_") + std::to_string(i));
  }
  for (const char* side : {"left", "right"}) {
    names.push_back(std::string("hand_root_") + side);
    for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
      for (int k = 1; k <= 4; ++k) {
        names.push_back(std::string("hand_") + finger + "_" + std::to_string(k) + "_" + side);
      }
    }
  }
  return names;
}

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}
bool StartsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

const JointNames& CocoBodyJoints() {
  static const JointNames names = {
      "nose",        "eye_left",       "eye_right",   "ear_left",     "ear_right",     "shoulder_left",
      "shoulder_right", "elbow_left",  "elbow_right", "wrist_left",   "wrist_right",   "hip_left",
      "hip_right",   "knee_left",      "knee_right",  "ankle_left",   "ankle_right"};
  return names;
}

const JointNames& CocoWholeBodyJoints() {
  static const JointNames names = MakeWholeBody();
  return names;
}

const JointNames& DerivedJointNames() {
  static const JointNames names = {"hip_middle", "shoulder_middle", "head"};
  return names;
}

const std::vector<JointNames>& DerivedJointSources(std::string_view name) {
  static const std::vector<JointNames> hip = {{"hip_left", "hip_right"}};
  static const std::vector<JointNames> shoulder = {{"shoulder_left", "shoulder_right"}};
  static const std::vector<JointNames> head = {{"ear_left", "ear_right"}, {"eye_left", "eye_right"}, {"nose"}};
  static const std::vector<JointNames> none;
  if (name == "hip_middle") return hip;
  if (name == "shoulder_middle") return shoulder;
  if (name == "head") return head;
  return none;
}

JointNames AddDerivedJoints(const JointNames& names) {
  JointNames out = names;
  for (const std::string& derived : DerivedJointNames()) {
    if (FindJoint(out, derived) >= 0) continue;
    bool has_source = false;
    for (const JointNames& alternative : DerivedJointSources(derived)) {
      has_source |= std::all_of(alternative.begin(), alternative.end(),
                                [&](const std::string& j) { return FindJoint(names, j) >= 0; });
    }
    if (has_source) out.push_back(derived);
  }
  return out;
}

const JointNames& DefaultCoreJoints() {
  static const JointNames names = {"shoulder_left", "shoulder_right", "hip_left",   "hip_right",
                                   "elbow_left",    "elbow_right",    "wrist_left", "wrist_right",
                                   "knee_left",     "knee_right",     "ankle_left", "ankle_right"};
  return names;
}

const JointNames& EvaluationJoints13() {
  static const JointNames names = {"nose",       "shoulder_left", "shoulder_right", "elbow_left", "elbow_right",
                                   "wrist_left", "wrist_right",   "hip_left",       "hip_right",  "knee_left",
                                   "knee_right", "ankle_left",    "ankle_right"};
  return names;
}

int JointSide(std::string_view name) {
  size_t start = 0;
  while (start <= name.size()) {
    const size_t end = std::min(name.find('_', start), name.size());
    const std::string_view token = name.substr(start, end - start);
    if (token == "left") return 1;
    if (token == "right") return -1;
    start = end + 1;
  }
  return 0;
}

std::string MirrorJointName(std::string_view name) {
  std::string out;
  size_t start = 0;
  while (start <= name.size()) {
    const size_t end = std::min(name.find('_', start), name.size());
    const std::string_view token = name.substr(start, end - start);
    out += token == "left" ? "right" : token == "right" ? "left" : std::string(token);
    if (end < name.size()) out += '_';
    start = end + 1;
  }
  return out;
}

std::vector<int> MirrorIndices(const JointNames& names) {
  std::vector<int> mirror(names.size());
  for (size_t j = 0; j < names.size(); ++j) {
    const int m = FindJoint(names, MirrorJointName(names[j]));
    mirror[j] = m >= 0 ? m : static_cast<int>(j);
  }
  return mirror;
}

std::vector<int> NeighbourIndices(const JointNames& names) {
  std::vector<int> neighbour(names.size());
  for (size_t j = 0; j < names.size(); ++j) neighbour[j] = FindJoint(names, NeighbourJoint(names[j]));
  return neighbour;
}

int FindJoint(const JointNames& names, std::string_view name) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string NeighbourJoint(std::string_view name) {
  // Side suffix of a joint name ("_left" / "_right"), if any.
  const std::string side = EndsWith(name, "_left") ? "_left" : EndsWith(name, "_right") ? "_right" : "";
  const std::string other_side = side == "_left" ? "_right" : "_left";
  const std::string_view base = name.substr(0, name.size() - side.size());

  if (base == "elbow") return "shoulder" + side;
  if (base == "wrist") return "elbow" + side;
  if (base == "knee") return "hip" + side;
  if (base == "ankle") return "knee" + side;
  if (base == "shoulder" || base == "hip") return std::string(base) + other_side;
  if (base == "eye") return "nose";
  if (base == "ear") return "eye" + side;
  if (name == "nose") return "head";
  if (name == "head") return "nose";
  if (name == "hip_middle") return "hip_left";
  if (name == "shoulder_middle") return "shoulder_left";
  if (StartsWith(name, "foot_")) return "ankle" + side;
  if (StartsWith(name, "face_")) return "nose";
  if (base == "hand_root") return "wrist" + side;
  if (StartsWith(name, "hand_")) {
    // hand_<finger>_<k>_<side>: k == 1 attaches to the hand root, otherwise to k - 1.
    const size_t digit = base.find_last_of('_');
    if (digit == std::string_view::npos || digit + 1 >= base.size()) return "";
    const int k = base[digit + 1] - '0';
    if (k <= 1) return "hand_root" + side;
    return std::string(base.substr(0, digit + 1)) + std::to_string(k - 1) + side;
  }
  return "";
}

const std::vector<LimbSpec>& BodyLimbs() {
  // Generous ranges: they catch mismatched pairs and gross outliers, not natural variation.
  static const std::vector<LimbSpec> limbs = {
      {"shoulder_left", "elbow_left", 0.10, 0.60},  {"shoulder_right", "elbow_right", 0.10, 0.60},
      {"elbow_left", "wrist_left", 0.08, 0.55},     {"elbow_right", "wrist_right", 0.08, 0.55},
      {"hip_left", "knee_left", 0.18, 0.75},        {"hip_right", "knee_right", 0.18, 0.75},
      {"knee_left", "ankle_left", 0.18, 0.75},      {"knee_right", "ankle_right", 0.18, 0.75},
      {"shoulder_left", "shoulder_right", 0.12, 0.70}, {"hip_left", "hip_right", 0.06, 0.55},
      {"shoulder_left", "hip_left", 0.20, 0.95},    {"shoulder_right", "hip_right", 0.20, 0.95},
  };
  return limbs;
}


std::vector<LimbSpec> LimbsFor(const JointNames& names) {
  std::vector<LimbSpec> limbs;
  for (const LimbSpec& limb : BodyLimbs()) {
    if (FindJoint(names, limb.a) >= 0 && FindJoint(names, limb.b) >= 0) limbs.push_back(limb);
  }
  for (const std::string& name : names) {
    double max_length = 0;
    if (StartsWith(name, "foot_")) max_length = 0.35;
    if (StartsWith(name, "face_")) max_length = 0.3;
    if (StartsWith(name, "hand_")) max_length = 0.15;
    if (max_length == 0) continue;
    const std::string neighbour = NeighbourJoint(name);
    if (neighbour.empty() || FindJoint(names, neighbour) < 0) continue;
    limbs.push_back(LimbSpec{neighbour, name, 0.0, max_length});
  }
  return limbs;
}

}  // namespace rpt
