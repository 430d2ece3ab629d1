// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/joints.h"
#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
namespace {

constexpr uint64_t kCalibrationStream = 0xCA11B7A7E0000001ULL;

}  // namespace

double PixelsPerMetre(const Camera& camera, const Eigen::Vector3d& p_cam) {
  const double pinhole = 0.5 * (camera.K(0, 0) + camera.K(1, 1)) / std::max(p_cam.z(), 1e-3);
  const Eigen::Vector3d half(0.25, 0.0, 0.0);
  Eigen::Vector2d a, b;
  const Eigen::Matrix3d Rt = camera.R.transpose();
  if (!camera.Project(Rt * (p_cam - half - camera.t), &a) || !camera.Project(Rt * (p_cam + half - camera.t), &b) ||
      !a.allFinite() || !b.allFinite()) {
    return pinhole;
  }
  const double local = (b - a).norm() / 0.5;
  return local > 0.0 ? local : pinhole;
}

Camera PerturbedCamera(const Camera& camera, uint64_t seed, uint64_t camera_index, double calibration_px) {
  if (!(calibration_px > 0.0)) return camera;
  Rng rng(DeriveSeed(seed, kCalibrationStream, camera_index));
  const double focal = 0.5 * (camera.K(0, 0) + camera.K(1, 1));
  const double half_diagonal = 0.5 * std::hypot(camera.width, camera.height);
  const double ax = rng.Normal() * calibration_px / focal;
  const double ay = rng.Normal() * calibration_px / focal;
  const double az = rng.Normal() * calibration_px / half_diagonal;
  const Eigen::Matrix3d delta = (Eigen::AngleAxisd(az, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(ay, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(ax, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
  Camera out = camera;
  out.R = delta * camera.R;
  out.t = delta * camera.t;  // same centre
  return out;
}

BodyJoints::BodyJoints(const JointNames& joints)
    : shoulder_left(FindJoint(joints, "shoulder_left")),
      shoulder_right(FindJoint(joints, "shoulder_right")),
      hip_left(FindJoint(joints, "hip_left")),
      hip_right(FindJoint(joints, "hip_right")) {}

std::vector<ResolvedOffset> ResolveOffsets(const std::vector<JointOffset>& offsets, const JointNames& joints) {
  std::vector<ResolvedOffset> out;
  for (const JointOffset& offset : offsets) {
    const int k = FindJoint(joints, offset.joint);
    if (k < 0) continue;
    out.push_back(ResolvedOffset{k, JointSide(offset.joint), offset.down_m, offset.out_m, offset.forward_m});
  }
  return out;
}

void ApplyJointOffsets(const std::vector<ResolvedOffset>& offsets, const BodyJoints& body,
                       const std::vector<char>& present, Eigen::Matrix3Xd* points) {
  if (offsets.empty() || !body.Complete()) return;
  for (int k : {body.shoulder_left, body.shoulder_right, body.hip_left, body.hip_right}) {
    if (!present[k]) return;
  }
  const Eigen::Matrix3Xd& p = *points;
  const Eigen::Vector3d shoulders = 0.5 * (p.col(body.shoulder_left) + p.col(body.shoulder_right));
  const Eigen::Vector3d hips = 0.5 * (p.col(body.hip_left) + p.col(body.hip_right));
  Eigen::Vector3d down = hips - shoulders;
  if (down.norm() < 1e-6) return;
  down.normalize();
  Eigen::Vector3d lateral = p.col(body.shoulder_left) - p.col(body.shoulder_right) + p.col(body.hip_left) -
                            p.col(body.hip_right);
  lateral -= lateral.dot(down) * down;
  if (lateral.norm() < 1e-6) return;
  lateral.normalize();
  const Eigen::Vector3d forward = down.cross(lateral);
  Eigen::Matrix3Xd moved = p;
  for (const ResolvedOffset& offset : offsets) {
    if (!present[offset.joint]) continue;
    const double out_sign = offset.side < 0 ? -1.0 : 1.0;
    moved.col(offset.joint) += offset.down_m * down + out_sign * offset.out_m * lateral + offset.forward_m * forward;
  }
  *points = moved;
}

std::vector<Bone> BodyBones(const JointNames& joints, const OcclusionOptions& options) {
  std::vector<Bone> bones;
  auto add = [&](const char* a, const char* b, double radius, bool torso) {
    const int i = FindJoint(joints, a), j = FindJoint(joints, b);
    if (i >= 0 && j >= 0) bones.push_back(Bone{i, j, radius, torso});
  };
  for (const char* side : {"left", "right"}) {
    const std::string s = side;
    add(("shoulder_" + s).c_str(), ("elbow_" + s).c_str(), options.limb_radius_m, false);
    add(("elbow_" + s).c_str(), ("wrist_" + s).c_str(), options.limb_radius_m, false);
    add(("hip_" + s).c_str(), ("knee_" + s).c_str(), options.limb_radius_m, false);
    add(("knee_" + s).c_str(), ("ankle_" + s).c_str(), options.limb_radius_m, false);
  }
  add("shoulder_left", "shoulder_right", options.torso_radius_m, true);
  add("hip_left", "hip_right", options.torso_radius_m, true);
  add("shoulder_left", "hip_left", options.torso_radius_m, true);
  add("shoulder_right", "hip_right", options.torso_radius_m, true);
  add("shoulder_left", "hip_right", options.torso_radius_m, true);
  add("shoulder_right", "hip_left", options.torso_radius_m, true);
  add("nose", "nose", options.head_radius_m, false);
  return bones;
}

}  // namespace rpt::synthetic
