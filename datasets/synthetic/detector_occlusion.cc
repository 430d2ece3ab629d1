// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_occlusion.h"

#include <algorithm>
#include <cmath>

#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
namespace {

constexpr uint64_t kFurnitureStream = 0xF0F0F0F0A5A5A5A5ULL;
constexpr uint64_t kClutterStream = 0xC1C1C1C1E7E7E7E7ULL;
constexpr double kMinDepth = 0.05;  // m, joints closer to the camera plane are not projected

// One person in the camera: camera-frame points, projections, which are usable, image scale.
struct PersonInView {
  Eigen::Matrix3Xd p_cam;
  Eigen::Matrix2Xd uv;
  std::vector<char> valid;
  double pixels_per_metre = 0;
};

PersonInView Place(const Camera& camera, const Eigen::Matrix3Xd& points, const std::vector<char>& present) {
  const int num_joints = static_cast<int>(points.cols());
  PersonInView out;
  out.p_cam = (camera.R * points).colwise() + camera.t;
  out.uv.setZero(2, num_joints);
  out.valid.assign(num_joints, 0);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int n = 0;
  for (int k = 0; k < num_joints; ++k) {
    if (!present[k] || !(out.p_cam(2, k) > kMinDepth)) continue;
    Eigen::Vector2d uv;
    if (!camera.Project(points.col(k), &uv) || !uv.allFinite()) continue;
    out.uv.col(k) = uv;
    out.valid[k] = 1;
    centroid += out.p_cam.col(k);
    ++n;
  }
  if (n > 0) out.pixels_per_metre = PixelsPerMetre(camera, centroid / n);
  return out;
}

// Distance of `q` to the segment a-b and the segment parameter of the closest point.
double SegmentDistance(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double* t) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  *t = length2 > 0.0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + *t * ab - q).norm();
}

}  // namespace

void ComputeOcclusion(const OcclusionOptions& options, const std::vector<Bone>& bones, const BodyJoints& body,
                      const std::vector<double>& clutter, const Camera& camera, const std::vector<Eigen::Matrix3Xd>& points,
                      const std::vector<std::vector<char>>& present, const std::vector<int>& track_ids, uint64_t seed,
                      uint64_t frame_index, uint64_t camera_index, ViewOcclusion* out) {
  const size_t num_persons = points.size();
  out->hidden.assign(num_persons, {});
  out->occluder.assign(num_persons, {});
  for (size_t p = 0; p < num_persons; ++p) {
    out->hidden[p].assign(points[p].cols(), 0);
    out->occluder[p].assign(points[p].cols(), -1);
  }
  if (!options.enabled) return;
  std::vector<PersonInView> persons;
  persons.reserve(num_persons);
  for (size_t p = 0; p < num_persons; ++p) persons.push_back(Place(camera, points[p], present[p]));

  for (size_t p = 0; p < num_persons; ++p) {
    const PersonInView& person = persons[p];
    const int num_joints = static_cast<int>(person.valid.size());
    for (int k = 0; k < num_joints; ++k) {
      if (!person.valid[k]) continue;
      const Eigen::Vector2d uv = person.uv.col(k);
      const double depth = person.p_cam(2, k);
      bool hidden = false;
      for (size_t q = 0; q < num_persons && !hidden; ++q) {
        const PersonInView& other = persons[q];
        const bool self = q == p;
        if (self && !options.self_occlusion) continue;
        for (const Bone& bone : bones) {
          if (self && (!bone.torso || bone.a == k || bone.b == k)) continue;
          if (!other.valid[bone.a] || !other.valid[bone.b]) continue;
          double t = 0;
          const double distance = SegmentDistance(uv, other.uv.col(bone.a), other.uv.col(bone.b), &t);
          if (!(distance < bone.radius_m * other.pixels_per_metre)) continue;
          const double bone_depth = (1.0 - t) * other.p_cam(2, bone.a) + t * other.p_cam(2, bone.b);
          if (depth > bone_depth + options.depth_margin_m) {
            hidden = true;
            out->occluder[p][k] = self ? -1 : static_cast<int>(q);
            break;
          }
        }
      }
      out->hidden[p][k] = hidden;
    }
  }

  if (std::any_of(clutter.begin(), clutter.end(), [](double p) { return p > 0.0; })) {
    for (size_t p = 0; p < num_persons; ++p) {
      const uint64_t track = static_cast<uint64_t>(track_ids[p] >= 0 ? track_ids[p] : static_cast<int>(p));
      Rng rng(DeriveSeed(DeriveSeed(seed, kClutterStream, frame_index), camera_index, track));
      for (size_t k = 0; k < persons[p].valid.size() && k < clutter.size(); ++k) {
        if (clutter[k] > 0.0 && rng.Bernoulli(clutter[k]) && persons[p].valid[k] && !out->hidden[p][k]) {
          out->hidden[p][k] = 1;
          out->occluder[p][k] = -1;
        }
      }
    }
  }

  if (!(options.furniture_probability > 0.0) || body.hip_left < 0 || body.hip_right < 0) return;
  const uint64_t block_frames = static_cast<uint64_t>(std::max(1, options.furniture_block_frames));
  for (size_t p = 0; p < num_persons; ++p) {
    if (!present[p][body.hip_left] || !present[p][body.hip_right]) continue;
    const uint64_t track = static_cast<uint64_t>(track_ids[p] >= 0 ? track_ids[p] : static_cast<int>(p));
    // Blocks are staggered per person so that not everybody changes at the same frame.
    const uint64_t stagger = MixBits(DeriveSeed(seed, kFurnitureStream, track)) % block_frames;
    const uint64_t block = (frame_index + stagger) / block_frames;
    Rng rng(DeriveSeed(DeriveSeed(seed, kFurnitureStream, camera_index), track, block));
    if (!rng.Bernoulli(options.furniture_probability)) continue;
    const double hip_z = 0.5 * (points[p](2, body.hip_left) + points[p](2, body.hip_right));
    const double top = hip_z + rng.Uniform(options.furniture_top_min_m, options.furniture_top_max_m);
    for (size_t k = 0; k < persons[p].valid.size(); ++k) {
      if (persons[p].valid[k] && points[p](2, k) < top && !out->hidden[p][k]) {
        out->hidden[p][k] = 1;
        out->occluder[p][k] = -1;
      }
    }
  }
}

}  // namespace rpt::synthetic
