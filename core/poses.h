// SPDX-License-Identifier: MIT
// Flat pose containers: all persons of one view (2D) or one frame (3D).
//
// Invariants: a joint with score 0 is missing and its coordinates are meaningless. Buffers only
// grow: Clear() keeps capacity so a warm pipeline does not allocate.
#pragma once

#include <Eigen/Core>
#include <cassert>
#include <vector>

namespace rpt {

// 2D poses of all persons detected in one view. Per joint: u_px, v_px (distorted image pixels),
// score in [0, 1].
struct Poses2D {
  int num_joints = 0;
  std::vector<double> data;  // num_persons * num_joints * 3

  int num_persons() const { return num_joints > 0 ? static_cast<int>(data.size()) / (3 * num_joints) : 0; }
  void Clear(int joints) {
    num_joints = joints;
    data.clear();
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

// 3D poses of all persons of one frame. Per joint: x, y, z (metres, world frame), score.
struct Poses3D {
  int num_joints = 0;
  std::vector<double> data;    // num_persons * num_joints * 4
  std::vector<int> track_ids;  // one per person; -1 when not tracked

  int num_persons() const { return static_cast<int>(track_ids.size()); }
  void Clear(int joints) {
    num_joints = joints;
    data.clear();
    track_ids.clear();
  }
  Eigen::Map<Eigen::Matrix4Xd> AddPerson(int track_id = -1) {
    data.resize(data.size() + 4 * static_cast<size_t>(num_joints), 0.0);
    track_ids.push_back(track_id);
    return Person(num_persons() - 1);
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
