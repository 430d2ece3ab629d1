// SPDX-License-Identifier: MIT
#include "core/pipeline/refine.h"

#include <algorithm>

namespace rpt {
namespace {

// Rays at less than about half a degree from each other (two rays: det / (trace / 3)^3 = 0.84
// sin^2 of their angle) do not fix a point in depth.
constexpr double kMinConditioning = 1e-4;

// The normal equations of one joint, A x = b with A symmetric (a00 .. a22), and the views used.
enum Sum { kA00, kA01, kA02, kA11, kA12, kA22, kB0, kB1, kB2, kUsed, kSums };

}  // namespace

int steps::Refine(const RefineOptions& options, const RefineInput& in, RefineScratch* scratch, Poses3D* persons) {
  if (!options.enabled) return 0;
  const Proposals& proposals = in.proposals;
  const Groups& groups = in.groups;
  const KeypointColumns& columns = in.views.all_columns;
  const int n = proposals.num_joints;
  // Person i was merged from group i, over the prepared poses' joints (their columns).
  if (groups.size() != persons->num_persons() || n != persons->num_joints || columns.stride != n) return 0;
  const double scale = options.scale_factor * in.kernel.scale_m;
  if (!(scale > 0)) return 0;
  const double inv_scale_sq = 1.0 / (scale * scale);
  const double cutoff_sq = options.cutoff * options.cutoff * scale * scale;
  RefineScratch& s = *scratch;
  s.x.resize(n);
  s.y.resize(n);
  s.z.resize(n);
  s.sums.resize(static_cast<size_t>(kSums) * n);
  double* const sum = s.sums.data();
  int moved = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    const int first = groups.begin[p], last = groups.begin[p + 1];
    // The person's poses; per pose and joint, its confidence where a pair the merge could use has it.
    s.poses.clear();
    for (int k = first; k < last; ++k)
      for (const int pose : {proposals.pairs[k].a, proposals.pairs[k].b})
        if (std::find(s.poses.begin(), s.poses.end(), pose) == s.poses.end()) s.poses.push_back(pose);
    const int num_poses = static_cast<int>(s.poses.size());
    s.weight.assign(static_cast<size_t>(num_poses) * n, 0.0);
    for (int k = first; k < last; ++k) {
      const double* score = proposals.score.data() + static_cast<size_t>(k) * n;
      for (const int pose : {proposals.pairs[k].a, proposals.pairs[k].b}) {
        const int q = static_cast<int>(std::find(s.poses.begin(), s.poses.end(), pose) - s.poses.begin());
        const double* confidence = columns.score.data() + static_cast<size_t>(pose) * n;
        double* weight = s.weight.data() + static_cast<size_t>(q) * n;
        for (int j = 0; j < n; ++j)
          if (score[j] >= in.min_joint_score && score[j] > 0 && confidence[j] > 0) weight[j] = confidence[j];
      }
    }
    auto person = persons->Person(p);
    s.inv_norm_sq.resize(static_cast<size_t>(num_poses) * n);
    s.origin_dot.resize(static_cast<size_t>(num_poses) * n);
    for (int q = 0; q < num_poses; ++q) {
      const size_t at = static_cast<size_t>(s.poses[q]) * n;
      const double *rx = columns.rx.data() + at, *ry = columns.ry.data() + at, *rz = columns.rz.data() + at;
      const Eigen::Vector3d& c = in.geometry[in.views.view_of[s.poses[q]]].center;
      double* weight = s.weight.data() + static_cast<size_t>(q) * n;
      double* inv_norm_sq = s.inv_norm_sq.data() + static_cast<size_t>(q) * n;
      double* origin_dot = s.origin_dot.data() + static_cast<size_t>(q) * n;
      for (int j = 0; j < n; ++j) {
        if (person(3, j) <= 0) weight[j] = 0;  // missing after the merge: stays missing
        const double norm_sq = rx[j] * rx[j] + ry[j] * ry[j] + rz[j] * rz[j];
        inv_norm_sq[j] = weight[j] > 0 && norm_sq > 0 ? 1.0 / norm_sq : 0.0;
        if (inv_norm_sq[j] == 0) weight[j] = 0;
        origin_dot[j] = rx[j] * c.x() + ry[j] * c.y() + rz[j] * c.z();
      }
    }
    for (int j = 0; j < n; ++j) {
      s.x[j] = person(0, j);
      s.y[j] = person(1, j);
      s.z[j] = person(2, j);
    }
    std::vector<uint8_t>& changed = s.changed;
    changed.assign(n, 0);
    for (int it = 0; it < options.iterations; ++it) {
      std::fill(s.sums.begin(), s.sums.end(), 0.0);
      double* __restrict a00 = sum + kA00 * n;
      double* __restrict a01 = sum + kA01 * n;
      double* __restrict a02 = sum + kA02 * n;
      double* __restrict a11 = sum + kA11 * n;
      double* __restrict a12 = sum + kA12 * n;
      double* __restrict a22 = sum + kA22 * n;
      double* __restrict b0 = sum + kB0 * n;
      double* __restrict b1 = sum + kB1 * n;
      double* __restrict b2 = sum + kB2 * n;
      double* __restrict used = sum + kUsed * n;
      const double* __restrict x = s.x.data();
      const double* __restrict y = s.y.data();
      const double* __restrict z = s.z.data();
      for (int q = 0; q < num_poses; ++q) {
        const size_t at = static_cast<size_t>(s.poses[q]) * n;
        const double* __restrict rx = columns.rx.data() + at;
        const double* __restrict ry = columns.ry.data() + at;
        const double* __restrict rz = columns.rz.data() + at;
        const Eigen::Vector3d& c = in.geometry[in.views.view_of[s.poses[q]]].center;
        const double cx = c.x(), cy = c.y(), cz = c.z();
        const double* __restrict weight = s.weight.data() + static_cast<size_t>(q) * n;
        const double* __restrict inv_norm_sq = s.inv_norm_sq.data() + static_cast<size_t>(q) * n;
        const double* __restrict origin_dot = s.origin_dot.data() + static_cast<size_t>(q) * n;
        for (int j = 0; j < n; ++j) {  // branch-free, lanes across joints (weight 0: no view)
          const double tx = x[j] - cx, ty = y[j] - cy, tz = z[j] - cz;
          const double along = rx[j] * tx + ry[j] * ty + rz[j] * tz;
          const double distance_sq = tx * tx + ty * ty + tz * tz - along * along * inv_norm_sq[j];
          const double robust = weight[j] / (1.0 + distance_sq * inv_scale_sq);
          const double inside = static_cast<double>(distance_sq <= cutoff_sq);  // 0 or 1, no branch
          const double w = robust * inside;
          const double u = w * inv_norm_sq[j];  // w times the ray's outer product over |ray|^2
          a00[j] += w - u * rx[j] * rx[j];
          a01[j] -= u * rx[j] * ry[j];
          a02[j] -= u * rx[j] * rz[j];
          a11[j] += w - u * ry[j] * ry[j];
          a12[j] -= u * ry[j] * rz[j];
          a22[j] += w - u * rz[j] * rz[j];
          b0[j] += w * cx - u * rx[j] * origin_dot[j];
          b1[j] += w * cy - u * ry[j] * origin_dot[j];
          b2[j] += w * cz - u * rz[j] * origin_dot[j];
          used[j] += static_cast<double>(w > 0);
        }
      }
      for (int j = 0; j < n; ++j) {
        const double a00 = sum[kA00 * n + j], a01 = sum[kA01 * n + j], a02 = sum[kA02 * n + j];
        const double a11 = sum[kA11 * n + j], a12 = sum[kA12 * n + j], a22 = sum[kA22 * n + j];
        const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
        const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
        const double det = a00 * c00 + a01 * c01 + a02 * c02;
        const double third_trace = (a00 + a11 + a22) / 3.0;
        if (!(sum[kUsed * n + j] >= 2 && det > kMinConditioning * third_trace * third_trace * third_trace)) continue;
        const double b0 = sum[kB0 * n + j], b1 = sum[kB1 * n + j], b2 = sum[kB2 * n + j];
        const double inv_det = 1.0 / det;
        s.x[j] = (c00 * b0 + c01 * b1 + c02 * b2) * inv_det;
        s.y[j] = (c01 * b0 + c11 * b1 + c12 * b2) * inv_det;
        s.z[j] = (c02 * b0 + c12 * b1 + c22 * b2) * inv_det;
        changed[j] = 1;
      }
    }
    for (int j = 0; j < n; ++j) {
      if (!changed[j]) continue;
      person(0, j) = s.x[j];
      person(1, j) = s.y[j];
      person(2, j) = s.z[j];
      ++moved;
    }
  }
  return moved;
}

}  // namespace rpt
