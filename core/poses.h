// SPDX-License-Identifier: MIT
// Flat pose containers: all persons of one view (2D) or one frame (3D).
//
// Invariants: a joint with score 0 is missing and its coordinates are meaningless. Buffers only
// grow: Clear() keeps capacity so a warm pipeline does not allocate.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

namespace rpt {

// 2D poses of all persons detected in one view. Per joint: u_px, v_px (distorted image pixels),
// score in [0, 1].
struct Poses2D {
  int num_joints = 0;
  std::vector<double> data;  // num_persons * num_joints * 3
  // The camera delivered nothing for this frame (dropped, not started yet, not processed): it has
  // no persons and neither supports nor contradicts a person the other views see. A view that is
  // not unavailable and has no persons looked and saw nobody.
  bool unavailable = false;

  int num_persons() const { return num_joints > 0 ? static_cast<int>(data.size()) / (3 * num_joints) : 0; }
  void Clear(int joints) {
    num_joints = joints;
    data.clear();
    unavailable = false;
  }
  // Appends a person with all joints missing and returns its joints (3 x num_joints).
  Eigen::Map<Eigen::Matrix3Xd> AddPerson() {
    data.resize(data.size() + 3 * static_cast<size_t>(num_joints), 0.0);
    return Person(num_persons() - 1);
  }
  Eigen::Map<Eigen::Matrix3Xd> Person(int p) {
    assert(p >= 0 && p < num_persons());
    return Eigen::Map<Eigen::Matrix3Xd>(data.data() + 3 * static_cast<size_t>(p) * num_joints, 3, num_joints);
  }
  Eigen::Map<const Eigen::Matrix3Xd> Person(int p) const {
    assert(p >= 0 && p < num_persons());
    return Eigen::Map<const Eigen::Matrix3Xd>(data.data() + 3 * static_cast<size_t>(p) * num_joints, 3, num_joints);
  }
};

// Where the position of a 3D joint comes from (Poses3D::provenance). Its score says whether it
// is present at all (0 = missing, whatever the provenance).
enum class JointProvenance : uint8_t {
  kTriangulated = 0,  // from the views of this frame (steps 1-12)
  kFilled = 1,        // missing, given its neighbour's position (postprocess.fill_missing_joints, bone_lengths)
  kSmoothed = 2,      // triangulated, then moved by a temporal step (clip_speed, smooth, offline smoothing)
  kLifted = 3,        // placed from one view at a guessed depth (refine.one_view_joints; single_view, step 12b)
  kPredicted = 4,     // a coasting person's: its last pose carried on (track, no detection this frame)
};
inline constexpr int kNumJointProvenances = 5;

// 3D poses of all persons of one frame. Per joint: x, y, z (metres, world frame), score.
struct Poses3D {
  int num_joints = 0;
  std::vector<double> data;    // num_persons * num_joints * 4
  std::vector<int> track_ids;  // one per person; -1 when not tracked
  // One per joint (num_persons * num_joints), a JointProvenance; AddPerson starts a person as
  // triangulated. Poses not made by a Triangulator may leave it shorter: Provenance() then says
  // kTriangulated.
  std::vector<uint8_t> provenance;

  int num_persons() const { return static_cast<int>(track_ids.size()); }
  void Clear(int joints) {
    num_joints = joints;
    data.clear();
    track_ids.clear();
    provenance.clear();
  }
  Eigen::Map<Eigen::Matrix4Xd> AddPerson(int track_id = -1) {
    data.resize(data.size() + 4 * static_cast<size_t>(num_joints), 0.0);
    track_ids.push_back(track_id);
    provenance.resize(provenance.size() + static_cast<size_t>(num_joints),
                      static_cast<uint8_t>(JointProvenance::kTriangulated));
    return Person(num_persons() - 1);
  }
  // Keeps the first `count` persons.
  void Truncate(int count) {
    data.resize(4 * static_cast<size_t>(count) * num_joints);
    track_ids.resize(count);
    provenance.resize(std::min(provenance.size(), static_cast<size_t>(count) * num_joints));
  }
  // Person `from` becomes person `to` (positions, track id, provenance); for compaction, to <= from.
  void MovePerson(int from, int to) {
    Person(to) = Person(from);
    track_ids[to] = track_ids[from];
    const size_t n = static_cast<size_t>(num_joints);
    if (provenance.size() >= (from + 1) * n) {
      std::copy_n(provenance.begin() + from * n, n, provenance.begin() + to * n);
    }
  }
  // The provenance of joint j of person p (kTriangulated when not recorded).
  JointProvenance Provenance(int p, int j) const {
    const size_t k = static_cast<size_t>(p) * num_joints + j;
    return k < provenance.size() ? static_cast<JointProvenance>(provenance[k]) : JointProvenance::kTriangulated;
  }
  // Person p's provenance entries (empty when not recorded), to set them.
  std::span<uint8_t> PersonProvenance(int p) {
    const size_t n = static_cast<size_t>(num_joints);
    if (provenance.size() < (p + 1) * n) return {};
    return {provenance.data() + p * n, n};
  }
  Eigen::Map<Eigen::Matrix4Xd> Person(int p) {
    assert(p >= 0 && p < num_persons());
    return Eigen::Map<Eigen::Matrix4Xd>(data.data() + 4 * static_cast<size_t>(p) * num_joints, 4, num_joints);
  }
  Eigen::Map<const Eigen::Matrix4Xd> Person(int p) const {
    assert(p >= 0 && p < num_persons());
    return Eigen::Map<const Eigen::Matrix4Xd>(data.data() + 4 * static_cast<size_t>(p) * num_joints, 4, num_joints);
  }
};

}  // namespace rpt
