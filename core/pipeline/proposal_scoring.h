// SPDX-License-Identifier: MIT
// The scoring kernels of steps 6-7 (score.h), shared with step 10 (triangulate_full.h), and the
// kernel scale that verification (11b) and the single-view step (12b) judge agreement by.
//
// Per joint i of a proposal from poses a, b, with ray gap g_i (distance between the two viewing
// rays, m) and reprojection errors e_a, e_b (px) in the two views:
//
//   adaptive scale (default): r_i = mean over both views of e * depth / focal length (the
//     reprojection error in metres at the joint), S = scale_factor * the estimated noise level
//     (noise_scale.h), s_rep = exp(-(r_i / S)^2), s_tri = exp(-(g_i / 2S)^2);
//   fixed scale (the first release): r_i = mean over both views of e / bbox_diag (rel),
//     s_rep = exp(-(r_i / reprojection_scale_rel)^2), s_tri = exp(-(g_i / ray_gap_scale_m)^2);
//
//   s_i = s_rep * s_tri (combined) | s_rep (reprojection only) | s_tri (triangulation only)
//   c_i = sqrt(conf_a * conf_b) (2D confidence)         joint score = s_i * c_i (or s_i)
// Implausible limbs (length outside the limb's range) invalidate their distal joint (score 0).
// The pair score (step 6-7 only) is in score.h.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "core/fast_math.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/simd_kernels.h"

namespace rpt {

// The kernels of one frame: set by the score step once the frame's noise votes are in (the
// adaptive scale follows the estimate), then read by triangulate_full, verify and single_view.
struct ScoreKernel {
  bool use_reprojection = true;  // score.mode
  bool use_ray_gap = true;
  bool adaptive = true;        // score.scale: residuals in metres at the joint, else relative to the box
  bool use_confidence = true;  // score.use_confidence
  bool prune_limbs = true;     // score.prune_limbs
  double inv_residual = 0;     // 1 / the residual's scale (1 / S, or 1 / reprojection_scale_rel)
  double inv_ray_gap = 0;      // 1 / the ray gap's scale (1 / 2S, or 1 / ray_gap_scale_m)
  double scale_m = 0;          // S in metres (KernelScaleM): verify and single_view compare residuals with it
};

// The kernel scale in metres: scale_factor x `noise_m` (adaptive), or, for the fixed scale, the
// ray-gap scale halved (the reprojection error at the person is about half the ray gap).
double KernelScaleM(const ScoreOptions& options, double noise_m);

// The kernels of `options` at the detection noise level `noise_m` (used by the adaptive scale).
ScoreKernel MakeScoreKernel(const ScoreOptions& options, double noise_m);

// Reprojection error of `point` against keypoint `kp` and the point's depth in the view (z). With
// `times_depth` the error times the depth (px m), computed without a division as the length of
// (h_x - u h_z, h_y - v h_z) for the homogeneous projection h; else the error in pixels. Returns 0
// when the point is behind the camera (depth <= 0; the caller tests the depth).
RPT_ALWAYS_INLINE double ReprojectionError(const ViewGeometry& g, const Eigen::Vector3d& point, const Keypoint& kp,
                                           bool times_depth, double* depth) {
  const Eigen::Vector3d h = g.P.leftCols<3>() * point + g.P.col(3);
  *depth = h.z();
  if (h.z() <= 0) return 0;
  double du, dv;
  if (times_depth) {
    du = h.x() - kp.u * h.z();
    dv = h.y() - kp.v * h.z();
  } else {
    const double inv_z = 1.0 / h.z();
    du = h.x() * inv_z - kp.u;
    dv = h.y() * inv_z - kp.v;
  }
  return std::sqrt(du * du + dv * dv);
}

// Residual of joint i of a proposal: the mean reprojection error over both views, in metres at
// the joint (adaptive: the error times the depth, times `scale` = 1 / focal length) or relative to
// the pose's box (fixed: `scale` = 1 / box diagonal); implausibly large when the point is behind a
// camera.
RPT_ALWAYS_INLINE double JointResidual(const ViewGeometry& ga, const ViewGeometry& gb, const Eigen::Vector3d& point,
                                       const Keypoint& ka, const Keypoint& kb, double scale_a, double scale_b,
                                       bool adaptive) {
  double za = 1, zb = 1;
  const double ea = ReprojectionError(ga, point, ka, adaptive, &za);
  const double eb = ReprojectionError(gb, point, kb, adaptive, &zb);
  if (za <= 0 || zb <= 0) return 1e6;
  return 0.5 * (ea * scale_a + eb * scale_b);
}

// Limb pruning: in limb order (proximal before distal), a limb whose two joints are scored
// (score > 0) and whose length lies outside its range invalidates its distal joint (score 0).
// Returns the joints invalidated. Done 64 limbs at a time: first, without branches, which limbs
// are implausible and have both joints scored at the start; then, in limb order, only those, each
// tested again as an earlier limb may have invalidated its proximal joint. The same result as the
// plain loop: pruning only lowers scores to 0, and a length never depends on a score. With
// `limb_columns` (the same limbs as columns; may be null) the first pass is the SIMD kernel, for
// kMinLimbsForKernel limbs or more at a time (below that, the call and its gathers cost more than
// the scalar loop: 16 body limbs ran 0.5-0.9 us slower per frame in each of score and
// triangulate_full, the 132 whole-body limbs 3 us faster, with AVX-512; below AVX-512 the kernel
// loads the joints one limb at a time, as gathers there cost more than they save).
inline constexpr size_t kMinLimbsForKernel = 32;
RPT_ALWAYS_INLINE int PruneImplausibleLimbs(std::span<const ResolvedLimb> limbs, const LimbColumns* limb_columns,
                                            const Eigen::Vector3d* xyz, double* score) {
  int pruned = 0;
  const size_t num_limbs = limbs.size();
  for (size_t begin = 0; begin < num_limbs; begin += 64) {
    const size_t end = std::min(num_limbs, begin + 64);
    uint64_t implausible = 0;
    const bool kernel = limb_columns != nullptr && end - begin >= kMinLimbsForKernel;
    if (kernel)
      implausible = simd::ImplausibleLimbs(*limb_columns, begin, end, reinterpret_cast<const double*>(xyz), score);
    for (size_t l = begin; l < end && !kernel; ++l) {
      const ResolvedLimb& limb = limbs[l];
      const double length_sq = (xyz[limb.a] - xyz[limb.b]).squaredNorm();
      const bool outside = (length_sq < limb.min_length_sq()) | (length_sq > limb.max_length_sq());
      const bool scored = (score[limb.a] > 0) & (score[limb.b] > 0);  // (an unscored joint's xyz is not set)
      implausible |= static_cast<uint64_t>(outside & scored) << (l - begin);
    }
    while (implausible != 0) {
      const ResolvedLimb& limb = limbs[begin + static_cast<size_t>(std::countr_zero(implausible))];
      implausible &= implausible - 1;
      if (score[limb.a] <= 0 || score[limb.b] <= 0) continue;
      score[limb.b] = 0;
      ++pruned;
    }
  }
  return pruned;
}

// What scoring reads of proposal k: the geometry of its two views, its two 2D poses, and the
// index of its first joint in the per-joint arrays.
struct ProposalViews {
  const ViewGeometry& ga;
  const ViewGeometry& gb;
  const Keypoint* ka;
  const Keypoint* kb;
  size_t base;
};

RPT_ALWAYS_INLINE ProposalViews ViewsOf(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                                        const Proposals& proposals, int k) {
  const PosePair& pair = proposals.pairs[k];
  return {geometry[views.view_of[pair.a]], geometry[views.view_of[pair.b]], views.Pose(pair.a), views.Pose(pair.b),
          static_cast<size_t>(k) * proposals.num_joints};
}

// The geometric joint scores s_i of proposal k (`pv` = ViewsOf(k)), then limb pruning, before
// the 2D confidence: score[i] = geometric[i] = s_i for every triangulated joint, except joints
// already scored by an earlier step for the same pair (geometric >= 0), which keep that score.
// `joints` maps the proposal's joint slots to prepared-pose joints, `limbs` are indexed by slot;
// `residual` (may be null: computed here) holds the joints' residuals. `columns` (may be null:
// scalar code) are the keypoint columns of exactly the joints `joints` (the SIMD kernel reads
// them); with them, `limb_columns` (may be null) lets limb pruning use its kernel too. Returns
// the joints invalidated by limb pruning.
RPT_ALWAYS_INLINE int ScoreJointsOfProposal(const ScoreKernel& kernel, const PreparedViews& views,
                                            const ProposalViews& pv, std::span<const int> joints,
                                            std::span<const ResolvedLimb> limbs, const LimbColumns* limb_columns,
                                            const double* residual,
                                            const KeypointColumns* columns, Proposals* proposals, int k) {
  const int n = proposals->num_joints;
  const PosePair& pair = proposals->pairs[k];
  const Eigen::Vector3d* xyz = proposals->xyz.data() + pv.base;
  const double* gap = proposals->gap.data() + pv.base;
  double* score = proposals->score.data() + pv.base;
  double* geometric = proposals->geometric.data() + pv.base;
  const double scale_a = kernel.adaptive ? 1.0 / pv.ga.focal : 1.0 / views.bbox_diag[pair.a];
  const double scale_b = kernel.adaptive ? 1.0 / pv.gb.focal : 1.0 / views.bbox_diag[pair.b];
  if (columns != nullptr) {
    static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
    simd::ScoreJoints({.use_reprojection = kernel.use_reprojection,
                       .use_ray_gap = kernel.use_ray_gap,
                       .inv_residual = kernel.inv_residual,
                       .inv_ray_gap = kernel.inv_ray_gap},
                      {.Pa = pv.ga.P.data(), .Pb = pv.gb.P.data(), .scale_a = scale_a, .scale_b = scale_b,
                       .adaptive = kernel.adaptive},
                      simd::ColumnsOf(*columns, pair.a), simd::ColumnsOf(*columns, pair.b), n,
                      reinterpret_cast<const double*>(xyz), gap, residual, score, geometric);
  }
  for (int i = 0; i < n && columns == nullptr; ++i) {
    if (score[i] <= 0) continue;
    if (geometric[i] >= 0) {  // computed by an earlier step for the same pair (core joints)
      score[i] = geometric[i];
      continue;
    }
    double exponent = 0;
    if (kernel.use_ray_gap) {
      const double r = gap[i] * kernel.inv_ray_gap;
      exponent = r * r;
      if (exponent > 30.0) {  // negligible (< e^-30) whatever the reprojection error
        score[i] = geometric[i] = 0.0;
        continue;
      }
    }
    if (kernel.use_reprojection) {
      const double e = residual != nullptr ? residual[i]
                                           : JointResidual(pv.ga, pv.gb, xyz[i], pv.ka[joints[i]], pv.kb[joints[i]],
                                                           scale_a, scale_b, kernel.adaptive);
      const double r = e * kernel.inv_residual;
      exponent += r * r;
    }
    score[i] = geometric[i] = FastExpNeg(exponent);
  }
  return kernel.prune_limbs ? PruneImplausibleLimbs(limbs, columns != nullptr ? limb_columns : nullptr, xyz, score) : 0;
}

}  // namespace rpt
