// SPDX-License-Identifier: MIT
#include "core/pipeline/undistort.h"

#include <algorithm>
#include <cmath>

#include "core/fast_math.h"
#include "core/pipeline/simd_kernels.h"

namespace rpt {

namespace {

RPT_ALWAYS_INLINE void SetFromNormalized(const ViewGeometry& g, double x, double y, double score, Keypoint* kp) {
  kp->x = x;
  kp->y = y;
  kp->u = g.fx * x + g.skew * y + g.cx;
  kp->v = g.fy * y + g.cy;
  kp->score = score;
  kp->sqrt_score = std::sqrt(score);
  kp->ray = g.R_t * Eigen::Vector3d(x, y, 1.0);
}

// Whether pose p of `view` equals an earlier pose of it in every number (pixels and scores).
bool RepeatsEarlierPose(const Poses2D& view, int p) {
  const size_t n = 3 * static_cast<size_t>(view.num_joints);
  const double* pose = view.data.data() + p * n;
  for (int e = 0; e < p; ++e) {
    if (std::equal(pose, pose + n, view.data.data() + e * n)) return true;
  }
  return false;
}

}  // namespace

int steps::Undistort(const UndistortOptions& options, const UndistortInput& in, PreparedViews* prepared) {
  const std::span<const Poses2D> views = in.views;
  const int num_output_joints = in.num_output_joints;
  PreparedViews& out = *prepared;
  out.num_joints = num_output_joints;
  out.view_of.clear();
  out.person_of.clear();
  out.bbox_diag.clear();
  out.view_begin.clear();
  out.unavailable.clear();
  // The keypoints are written into the slots of the last frame (every field of every joint of a
  // pose is written below), so the slots are initialised only when the frame needs more of them.
  size_t used = 0;
  KeypointColumns& columns = out.all_columns;  // slot for slot with the keypoints

  const int num_views = static_cast<int>(views.size());
  for (int v = 0; v < num_views; ++v) {
    out.view_begin.push_back(out.num_poses());
    const Poses2D& view = views[v];
    out.unavailable.push_back(view.unavailable ? 1 : 0);
    const Camera& camera = in.cameras[v];
    const ViewGeometry& g = in.geometry[v];
    const bool distorted = camera.HasDistortion();
    // A pinhole camera's joints go through the SIMD kernel (the numbers of the loop below), which
    // writes the columns directly; the keypoints are filled from them.
    const bool pinhole_kernel = !distorted && simd::Enabled();
    const simd::PinholeView pinhole{.fx = g.fx, .fy = g.fy, .cx = g.cx, .cy = g.cy, .skew = g.skew,
                                    .R_t = g.R_t.data(), .min_score = options.min_joint_score};
    if (pinhole_kernel) out.pinhole_scratch.resize(2 * static_cast<size_t>(view.num_joints));
    for (int p = 0; p < view.num_persons(); ++p) {
      const auto person = view.Person(p);
      if (options.drop_exact_copies && RepeatsEarlierPose(view, p)) continue;
      const size_t base = used;
      if (out.keypoints.size() < base + num_output_joints) out.keypoints.resize(base + num_output_joints);
      if (columns.u.size() < base + num_output_joints) columns.Resize(base + num_output_joints);
      Keypoint* kps = out.keypoints.data() + base;
      // The box of the joints with a positive score: the kernel's joints from the kernel.
      double box[4] = {1e300, 1e300, -1e300, -1e300};  // min u, min v, max u, max v
      int box_from = 0;                                  // joints [box_from, output) still to add
      if (pinhole_kernel) {
        const int n = view.num_joints;
        double* const xy = out.pinhole_scratch.data();
        const simd::KeypointFields fields{.u = columns.u.data() + base, .v = columns.v.data() + base,
                                          .score = columns.score.data() + base,
                                          .sqrt_score = columns.sqrt_score.data() + base,
                                          .rx = columns.rx.data() + base, .ry = columns.ry.data() + base,
                                          .rz = columns.rz.data() + base, .x = xy, .y = xy + n};
        simd::UndistortPinhole(pinhole, person.data(), n, fields, box);
        box_from = n;
        for (int j = 0; j < n; ++j) {
          Keypoint& kp = kps[j];
          kp.u = fields.u[j];
          kp.v = fields.v[j];
          kp.score = fields.score[j];
          kp.sqrt_score = fields.sqrt_score[j];
          kp.ray = Eigen::Vector3d(fields.rx[j], fields.ry[j], fields.rz[j]);
          kp.x = fields.x[j];
          kp.y = fields.y[j];
        }
      }
      for (int j = 0; j < view.num_joints && !pinhole_kernel; ++j) {
        const double u = person(0, j), v_px = person(1, j), s = person(2, j);
        if (!(s >= options.min_joint_score) || !std::isfinite(u) || !std::isfinite(v_px) || !std::isfinite(s)) {
          kps[j] = Keypoint{};
          continue;
        }
        Eigen::Vector2d xy;
        if (distorted) {
          xy = camera.PixelToNormalized(Eigen::Vector2d(u, v_px));
        } else {
          // Pinhole: invert K directly (cheaper than the generic path).
          const double y = (v_px - g.cy) / g.fy;
          xy = Eigen::Vector2d((u - g.cx - g.skew * y) / g.fx, y);
        }
        SetFromNormalized(g, xy.x(), xy.y(), std::min(s, 1.0), &kps[j]);
      }
      for (int j = view.num_joints; j < num_output_joints; ++j) kps[j] = Keypoint{};
      // Derived joints: mean of the sources in normalised coordinates, score = weakest source.
      for (const DerivedJointRule& rule : in.derived) {
        for (const std::vector<int>& sources : rule.alternatives) {
          double x = 0, y = 0, score = 1.0;
          bool complete = true;
          for (int s : sources) {
            if (kps[s].score <= 0) {
              complete = false;
              break;
            }
            x += kps[s].x;
            y += kps[s].y;
            score = std::min(score, kps[s].score);
          }
          if (!complete) continue;
          const double n = static_cast<double>(sources.size());
          SetFromNormalized(g, x / n, y / n, score, &kps[rule.output_index]);
          break;
        }
      }
      // Usable only with enough core joints; bounding box over all valid joints.
      int core_valid = 0;
      for (int c : in.core_joints) core_valid += kps[c].score > 0 ? 1 : 0;
      if (core_valid < options.min_core_joints) continue;  // its slots go to the next pose
      double min_u = box[0], min_v = box[1], max_u = box[2], max_v = box[3];
      for (int j = box_from; j < num_output_joints; ++j) {
        if (kps[j].score <= 0) continue;
        min_u = std::min(min_u, kps[j].u);
        max_u = std::max(max_u, kps[j].u);
        min_v = std::min(min_v, kps[j].v);
        max_v = std::max(max_v, kps[j].v);
      }
      // The columns of what the kernel did not write: all joints, or the added and derived ones.
      for (int j = pinhole_kernel ? view.num_joints : 0; j < num_output_joints; ++j) columns.Set(base + j, kps[j]);
      used += static_cast<size_t>(num_output_joints);
      out.view_of.push_back(v);
      out.person_of.push_back(p);
      out.bbox_diag.push_back(std::max(1.0, std::hypot(max_u - min_u, max_v - min_v)));
    }
  }
  out.view_begin.push_back(out.num_poses());
  out.keypoints.resize(used);  // smaller or equal: nothing is initialised
  // The same keypoints as columns for the SIMD kernels: all joints (written above), and the core joints.
  columns.stride = num_output_joints;
  columns.Resize(used);
  out.core_joints.assign(in.core_joints.begin(), in.core_joints.end());
  out.core_columns.Assign(out.keypoints.data(), out.num_poses(), num_output_joints, out.core_joints.data(),
                          static_cast<int>(out.core_joints.size()));
  return out.num_poses();
}

}  // namespace rpt
