// SPDX-License-Identifier: MIT
#include "core/pipeline/score_proposals.h"

#include "core/fast_math.h"

#include <cmath>

namespace rpt {
namespace {

// Squared reprojection error (px^2) of `point` against keypoint `kp`; large when behind the camera.
RPT_ALWAYS_INLINE double ReprojectionErrorSq(const ViewGeometry& g, const Eigen::Vector3d& point, const Keypoint& kp) {
  const Eigen::Vector3d h = g.P.leftCols<3>() * point + g.P.col(3);
  if (h.z() <= 0) return 1e12;
  const double inv_z = 1.0 / h.z();
  const double du = h.x() * inv_z - kp.u, dv = h.y() * inv_z - kp.v;
  return du * du + dv * dv;
}

}  // namespace

int ScoreProposals(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                   std::span<const ResolvedLimb> limbs, const ScoreOptions& options, Proposals* proposals,
                   bool pair_scores) {
  const int n = proposals->num_joints;
  const bool use_rep = options.mode != ScoreMode::kTriangulationOnly;
  const bool use_tri = options.mode != ScoreMode::kReprojectionOnly;
  const double inv_rep = 1.0 / options.reprojection_scale_rel;
  const double inv_gap = 1.0 / options.ray_gap_scale_m;
  int pruned = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    const PosePair& pair = proposals->pairs[k];
    const ViewGeometry& ga = geometry[views.view_of[pair.a]];
    const ViewGeometry& gb = geometry[views.view_of[pair.b]];
    const Keypoint* ka = views.Pose(pair.a);
    const Keypoint* kb = views.Pose(pair.b);
    const double diag_a = views.bbox_diag[pair.a];
    const double diag_b = views.bbox_diag[pair.b];
    Eigen::Vector3d* xyz = proposals->xyz.data() + static_cast<size_t>(k) * n;
    const double* gap = proposals->gap.data() + static_cast<size_t>(k) * n;
    double* score = proposals->score.data() + static_cast<size_t>(k) * n;
    double* geometric = proposals->geometric.data() + static_cast<size_t>(k) * n;

    const double inv_diag_a = 1.0 / diag_a, inv_diag_b = 1.0 / diag_b;
    for (int i = 0; i < n; ++i) {
      if (score[i] <= 0) continue;
      if (geometric[i] >= 0) {  // computed by an earlier step for the same pair (core joints)
        score[i] = geometric[i];
        continue;
      }
      // s = exp(-(e/scale_rep)^2) * exp(-(gap/scale_gap)^2) computed with one exp. The gap term
      // comes first: when it alone makes the score negligible (< e^-30), skip the projections.
      double exponent = 0;
      if (use_tri) {
        const double r = gap[i] * inv_gap;
        exponent = r * r;
        if (exponent > 30.0) {
          score[i] = geometric[i] = 0.0;
          continue;
        }
      }
      if (use_rep) {
        const double e = 0.5 * (std::sqrt(ReprojectionErrorSq(ga, xyz[i], ka[joints[i]])) * inv_diag_a +
                                std::sqrt(ReprojectionErrorSq(gb, xyz[i], kb[joints[i]])) * inv_diag_b);
        const double r = e * inv_rep;
        exponent += r * r;
      }
      score[i] = geometric[i] = FastExpNeg(exponent);
    }
    if (options.prune_limbs) {
      for (const ResolvedLimb& limb : limbs) {
        if (score[limb.a] <= 0 || score[limb.b] <= 0) continue;
        const double length_sq = (xyz[limb.a] - xyz[limb.b]).squaredNorm();
        if (length_sq < limb.min_length_sq() || length_sq > limb.max_length_sq()) {
          score[limb.b] = 0;
          ++pruned;
        }
      }
    }
    // Pair score over the joints both views saw; joint score gets the 2D confidence.
    if (!pair_scores) {
      if (options.use_confidence) {
        for (int i = 0; i < n; ++i) score[i] *= ka[joints[i]].sqrt_score * kb[joints[i]].sqrt_score;
      }
      continue;
    }
    double weighted = 0, weights = 0;
    for (int i = 0; i < n; ++i) {
      const Keypoint& a = ka[joints[i]];
      const Keypoint& b = kb[joints[i]];
      if (a.score <= 0 || b.score <= 0) continue;
      const double c = a.sqrt_score * b.sqrt_score;
      const double w = options.use_confidence ? c : 1.0;
      weighted += w * score[i];
      weights += w;
      if (options.use_confidence) score[i] *= c;
    }
    proposals->pair_score[k] = weights > 0 ? weighted / weights : 0.0;
  }
  return pruned;
}

}  // namespace rpt
