// SPDX-License-Identifier: MIT
// Geometry shared by the parts of the simulated detector: image scale of a person, cameras as a
// miscalibrated detector sees them, body frames and skeleton-definition offsets, bones.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::synthetic {

// Pixels per metre at the camera-frame point `p_cam` (z > 0): the distance between the
// projections of p_cam -+ 0.25 m along the camera's x axis, divided by 0.5 m; the pinhole value
// mean(fx, fy) / z when a projection fails.
double PixelsPerMetre(const Camera& camera, const Eigen::Vector3d& p_cam);

// `camera` rotated about its own centre by small angles drawn from (seed, camera index) only:
// about its x and y axes with sigma calibration_px / mean(fx, fy), about its optical axis with
// sigma calibration_px / (half the image diagonal), i.e. image shifts of about calibration_px per
// axis. calibration_px <= 0 returns the camera unchanged.
Camera PerturbedCamera(const Camera& camera, uint64_t seed, uint64_t camera_index, double calibration_px);

// Indices of the joints that span a body frame, -1 when absent.
struct BodyJoints {
  int shoulder_left = -1, shoulder_right = -1, hip_left = -1, hip_right = -1;
  explicit BodyJoints(const JointNames& joints);
  bool Complete() const { return shoulder_left >= 0 && shoulder_right >= 0 && hip_left >= 0 && hip_right >= 0; }
};

// A JointOffset resolved against the output joints.
struct ResolvedOffset {
  int joint = -1;
  int side = 0;  // JointSide of its name
  double down_m = 0, out_m = 0, forward_m = 0;
};
std::vector<ResolvedOffset> ResolveOffsets(const std::vector<JointOffset>& offsets, const JointNames& joints);

// Moves the present joints of one person (3 x joints, world) by the offsets in its body frame:
// down = shoulder centre -> hip centre, lateral = towards the person's left (perpendicular to
// down), forward = down x lateral. Nothing happens when a shoulder or hip is absent.
void ApplyJointOffsets(const std::vector<ResolvedOffset>& offsets, const BodyJoints& body,
                       const std::vector<char>& present, Eigen::Matrix3Xd* points);

// A segment between two joints with a radius in metres; a == b for a disc around one joint.
struct Bone {
  int a = -1, b = -1;
  double radius_m = 0;
  bool torso = false;
};
// The body's bones among `joints` (limbs, torso edges and diagonals, head around the nose).
std::vector<Bone> BodyBones(const JointNames& joints, const OcclusionOptions& options);

}  // namespace rpt::synthetic
