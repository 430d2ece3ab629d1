// SPDX-License-Identifier: MIT
// Synthetic scenes: a camera rig around a room with procedurally walking people, as per-frame
// ground-truth 3D poses (world frame: metres, z up, floor z = 0).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"
#include "datasets/synthetic/camera_rig.h"

namespace rpt::synthetic {

struct SceneOptions {
  RigOptions rig;                                   // camera rig (its look_at_m is used as given)
  int num_people = 4;                               // count of people, track ids 0..num_people-1
  bool whole_body = false;                          // true: 133 COCO-WholeBody joints, false: 17 COCO joints
  int num_frames = 300;                             // frames generated
  double fps = 25.0;                                // frames per second (sets the time step)
  Eigen::Vector3d room_center_m{0.0, 0.0, 1.5};     // m, centre of the room box (floor at center.z - size.z / 2)
  Eigen::Vector3d room_size_m{8.0, 8.0, 3.0};       // m, room box extent; people stay >= 0.65 m from the walls
  double min_separation_m = 0.8;                    // m, minimum horizontal distance between hip centres
  uint64_t seed = 1;                                // seeds the rig, the people and their paths

  // "" when valid, else "scene.key: problem" or the rig's "rig.key: problem" (core/options_check.h).
  std::string Check() const;
};

struct Scene {
  std::vector<Camera> cameras;           // rig, in camera order
  JointNames joint_names;                // CocoBodyJoints() or CocoWholeBodyJoints()
  Eigen::Vector3d room_center_m = Eigen::Vector3d::Zero();  // m
  Eigen::Vector3d room_size_m = Eigen::Vector3d::Zero();    // m
  double fps = 25.0;                     // frames per second
  std::vector<Poses3D> gt;               // one per frame; track_ids = person ids 0..N-1, all scores 1
};

// People walk between random waypoints inside the room at 0.6-1.5 m/s, steer around each other,
// wait when blocked and occasionally stand still. Hip centres never come closer than
// min_separation_m, every joint stays inside the room box. Deterministic in the options.
// Throws ConfigError with the problem of options.Check() (e.g. a room too small to walk in), or
// when the people do not fit.
Scene GenerateScene(const SceneOptions& options);

// The scene of GenerateScene frame by frame, with the same numbers: the walk is simulated one
// frame ahead of the gait, so memory does not depend on num_frames. The constructor throws what
// GenerateScene throws.
class SceneStream {
 public:
  explicit SceneStream(const SceneOptions& options);
  ~SceneStream();
  SceneStream(SceneStream&&) noexcept;
  SceneStream& operator=(SceneStream&&) noexcept;

  // Cameras, joint names, room and fps of the scene; gt is empty.
  const Scene& shell() const { return shell_; }
  int num_frames() const { return num_frames_; }
  // The next frame's ground truth (frames 0 .. num_frames - 1 in order); false after the last.
  bool Next(Poses3D* gt);

 private:
  struct State;
  Scene shell_;
  int num_frames_ = 0;
  int next_frame_ = 0;
  std::unique_ptr<State> state_;
};

struct CrossingOptions {
  RigOptions rig;                                   // camera rig
  int num_people = 2;                               // people on parallel lanes, alternating walking direction
  bool whole_body = false;                          // true: 133 COCO-WholeBody joints, false: 17 COCO joints
  int num_frames = 125;                             // frames generated
  double fps = 25.0;                                // frames per second
  Eigen::Vector3d room_center_m{0.0, 0.0, 1.5};     // m, centre of the room box
  Eigen::Vector3d room_size_m{8.0, 8.0, 3.0};       // m, room box extent
  double lane_spacing_m = 0.6;                      // m, distance between neighbouring lanes = closest approach
  double speed_mps = 1.1;                           // m/s, mean walking speed (+-10% per person)
  uint64_t seed = 1;                                // seeds the rig, the bodies and the lane direction

  // "" when valid, else "crossing.key: problem" or the rig's "rig.key: problem" (core/options_check.h).
  std::string Check() const;
};

// People walking towards each other on nearly the same line (parallel lanes lane_spacing_m
// apart, direction rotated randomly) and passing each other at the room centre in the middle of
// the sequence; they stop at the walls if the sequence is longer than the room allows.
Scene MakeCrossingScene(const CrossingOptions& options);

}  // namespace rpt::synthetic
