// SPDX-License-Identifier: MIT
// Internal data passed between the pipeline steps (not part of the public API).
//
// All buffers are std::vectors that are cleared and refilled every frame; clear() keeps their
// capacity, so once a Triangulator has seen its largest frame it no longer allocates.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rpt {

// Per camera, precomputed once: the undistorted pinhole model and the pose.
struct ViewGeometry {
  Eigen::Matrix<double, 3, 4> P;  // K [R | t]: world -> undistorted pixels (homogeneous)
  Eigen::Matrix<double, 3, 4> Rt;  // [R | t]: world -> normalised camera coordinates
  Eigen::Matrix3d R_t;             // R transposed: camera -> world directions
  Eigen::Vector3d center;          // camera centre in world (m)
  double fx = 1, fy = 1, cx = 0, cy = 0, skew = 0;
  double focal = 1;                // (fx + fy) / 2: pixels per unit of normalised coordinates
  int width = 0, height = 0;       // image size (px)
};

// One undistorted 2D joint and its viewing ray.
struct Keypoint {
  double u = 0, v = 0;  // undistorted pixels
  double score = 0;     // 0 = missing
  double sqrt_score = 0;  // sqrt(score): pair confidence is sqrt(score_a * score_b) = product
  Eigen::Vector3d ray = Eigen::Vector3d::Zero();  // world direction through the joint (unnormalised)
  double x = 0, y = 0;  // normalised undistorted camera coordinates
};

// The keypoints of every pose as columns (structure of arrays) for the SIMD kernels
// (simd_kernels.h): field f of joint j of pose g at f[g * stride + j].
struct KeypointColumns {
  int stride = 0;  // joints per pose
  std::vector<double> u, v, score, sqrt_score, rx, ry, rz;

  // Sets the columns of `poses` poses of `pose_size` keypoints each (kps): their joints `joints`
  // (n indices into a pose), or the first n when `joints` is null.
  void Assign(const Keypoint* kps, int poses, int pose_size, const int* joints, int n) {
    stride = n;
    Resize(static_cast<size_t>(poses) * n);
    for (int g = 0; g < poses; ++g) {
      const Keypoint* pose = kps + static_cast<size_t>(g) * pose_size;
      const size_t at = static_cast<size_t>(g) * n;
      if (joints != nullptr) {
        for (int i = 0; i < n; ++i) Set(at + i, pose[joints[i]]);
      } else {
        for (int i = 0; i < n; ++i) Set(at + i, pose[i]);
      }
    }
  }
  // Every column to `size` values and kSlack zeros more (a column that grows gets zeros; none
  // allocates below its capacity). The slack lets a kernel read whole vectors past a pose's last joint.
  static constexpr size_t kSlack = 8;
  void Resize(size_t size) {
    for (auto* c : {&u, &v, &score, &sqrt_score, &rx, &ry, &rz}) {
      c->resize(size + kSlack);
      std::fill(c->begin() + static_cast<std::ptrdiff_t>(size), c->end(), 0.0);
    }
  }
  // Value `at` of every column from `kp`.
  void Set(size_t at, const Keypoint& kp) {
    u[at] = kp.u;
    v[at] = kp.v;
    score[at] = kp.score;
    sqrt_score[at] = kp.sqrt_score;
    rx[at] = kp.ray.x();
    ry[at] = kp.ray.y();
    rz[at] = kp.ray.z();
  }
};

// Output of the undistort step: every usable 2D pose of the frame, all views concatenated.
struct PreparedViews {
  int num_joints = 0;              // output joints (input + derived)
  std::vector<int> view_of;        // per pose
  std::vector<int> person_of;      // per pose: index in its view's input
  std::vector<double> bbox_diag;   // per pose: bounding-box diagonal of its valid joints (px)
  std::vector<Keypoint> keypoints; // per pose and joint
  std::vector<int> view_begin;     // num_views + 1 offsets into the pose list
  std::vector<char> unavailable;   // per view: Poses2D::unavailable (no data this frame)
  // The keypoints again as columns: all joints, and the core joints (`core_joints`, the undistort
  // input's) in their slot order.
  KeypointColumns all_columns;
  KeypointColumns core_columns;
  std::vector<int> core_joints;
  std::vector<double> pinhole_scratch;  // the undistort step's SIMD kernel: x and y of one pose

  int num_poses() const { return static_cast<int>(view_of.size()); }
  const Keypoint* Pose(int g) const { return keypoints.data() + static_cast<size_t>(g) * num_joints; }
};

// Step 1 output: two poses from different views (indices into PreparedViews), view(a) < view(b).
struct PosePair {
  int a = 0;
  int b = 0;
};

// 3D proposals, one per pose pair, over a subset of the joints (core joints or all joints).
struct Proposals {
  int num_joints = 0;               // joints per proposal (size of the subset)
  std::vector<PosePair> pairs;      // per proposal
  std::vector<Eigen::Vector3d> xyz; // per proposal and joint (m, world)
  std::vector<double> gap;          // per proposal and joint: ray gap (m); < 0 = not triangulated
  std::vector<double> score;        // per proposal and joint: joint score, 0 = invalid
  std::vector<double> geometric;    // per proposal and joint: reprojection/gap score before limb
                                    // pruning and confidence; < 0 = not computed yet
  std::vector<double> pair_score;   // per proposal
  std::vector<int> group;           // per proposal: group index (after grouping)

  int size() const { return static_cast<int>(pairs.size()); }
  void Clear(int joints) {
    num_joints = joints;
    pairs.clear();
    xyz.clear();
    gap.clear();
    score.clear();
    geometric.clear();
    pair_score.clear();
    group.clear();
  }
  // Appends a proposal for `pair` with all joints invalid.
  void Add(const PosePair& pair) {
    pairs.push_back(pair);
    xyz.resize(xyz.size() + num_joints);  // read only where score > 0: no need to clear
    gap.resize(gap.size() + num_joints, -1.0);
    score.resize(score.size() + num_joints, 0.0);
    geometric.resize(geometric.size() + num_joints, -1.0);
    pair_score.push_back(0.0);
    group.push_back(-1);
  }
  // Moves proposal `from` to slot `to` (to <= from), used when compacting.
  void Move(int from, int to);
  // Keeps the first n proposals.
  void Truncate(int n);
};

// Step 9 output: groups of proposals, members listed contiguously.
struct Groups {
  std::vector<int> begin;    // num_groups + 1 offsets into members
  std::vector<int> members;  // proposal indices

  int size() const { return begin.empty() ? 0 : static_cast<int>(begin.size()) - 1; }
};

// A limb resolved to joint indices within a joint subset.
struct ResolvedLimb {
  int a = 0;  // proximal
  int b = 0;  // distal (invalidated when the limb is implausible)
  double min_length_m = 0;
  double max_length_m = 0;
  // Squared bounds, compared with squared lengths (no square root per limb).
  double min_length_sq() const { return min_length_m * min_length_m; }
  double max_length_sq() const { return max_length_m * max_length_m; }
};

// The same limbs as columns, for the SIMD limb-pruning kernel (simd::ImplausibleLimbs): joint
// indices as 64-bit lanes (gather indices) and the squared bounds computed once.
struct LimbColumns {
  std::vector<int64_t> a, b;
  std::vector<double> min_sq, max_sq;
};

inline LimbColumns ToLimbColumns(std::span<const ResolvedLimb> limbs) {
  LimbColumns out;
  for (const ResolvedLimb& limb : limbs) {
    out.a.push_back(limb.a);
    out.b.push_back(limb.b);
    out.min_sq.push_back(limb.min_length_sq());
    out.max_sq.push_back(limb.max_length_sq());
  }
  return out;
}

}  // namespace rpt
