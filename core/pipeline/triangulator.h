// SPDX-License-Identifier: MIT
// RapidPoseTriangulation: multi-view multi-person 3D pose triangulation from 2D poses
// (Bermuth, Poeppel, Reif, CVPR 2026, section 3.1, steps 1-14), plus the optional temporal steps
// 15-16 (bone_lengths, smooth).
//
// The steps, their names and their files are listed in core/pipeline/steps.h.
//
// Usage:
//   Triangulator tri(cameras, joint_names, options);   // throws ConfigError on bad options
//   for each frame: tri.Process(views, timestamp_s, &poses, &stats);
//
// Inputs per frame: one Poses2D per camera (same order as `cameras`), joints in the order of
// `joint_names`, pixels in the original (distorted) image. Output: 3D persons in metres in the
// world frame, joints in the order of output_joints() (input joints + derived joints).
// Process() does not allocate once its buffers have grown to the frame sizes seen.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/pipeline/frame_stats.h"
#include "core/pipeline/frame_trace.h"
#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

// Internal (core/pipeline/): the resolved model, fixed at construction (model.h), the per-frame
// buffers (frame_buffers.h) and the state carried between frames (temporal_state.h).
struct TriangulatorModel;
struct FrameBuffers;
struct TemporalState;

// Not thread-safe: calls on one object must not overlap. Use one Triangulator per thread; they
// share nothing.
class Triangulator {
 public:
  Triangulator(std::vector<Camera> cameras, JointNames input_joints, TriangulatorOptions options);
  ~Triangulator();
  Triangulator(Triangulator&&) noexcept;
  Triangulator& operator=(Triangulator&&) noexcept;

  // Triangulates one multi-view frame. `views.size()` must equal the number of cameras and each
  // non-empty view must have input_joints().size() joints (else InputError). A view marked
  // Poses2D::unavailable (the camera delivered nothing this frame) must be empty: verification and
  // the single-view step do not count it as a camera that saw nobody. `timestamp_s` is the
  // frame's time in seconds, NaN when unknown: a frame more than options().track.max_gap_s after
  // the last one, or with an unknown time, starts afresh (no pre-filter, tracks end, nothing
  // coasts). The detection noise estimate of the adaptive score carries over regardless.
  // With a `trace`, what the association steps did with the poses is recorded into it
  // (frame_trace.h); the recording's time is no step's time but counts in stats->total_us.
  void Process(std::span<const Poses2D> views, double timestamp_s, Poses3D* persons, FrameStats* stats,
               FrameTrace* trace = nullptr);

  // Forgets the previous frame (pre-filter poses, tracks) and the noise estimate, e.g. between
  // sequences.
  void Reset();

  const JointNames& input_joints() const;
  const JointNames& output_joints() const;
  const std::vector<Camera>& cameras() const;
  // The options as given (automatic values such as group.min_group_size = 0 stay as they are).
  const TriangulatorOptions& options() const;

 private:
  std::unique_ptr<const TriangulatorModel> model_;
  std::unique_ptr<FrameBuffers> frame_;
  std::unique_ptr<TemporalState> temporal_;
};

}  // namespace rpt
