// SPDX-License-Identifier: MIT
#include "core/pipeline/proposal_scoring.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/fast_math.h"

namespace rpt {
namespace {

// Squared reprojection error (px^2) of `point` against keypoint `kp`, and the point's depth in
// the view (z); a huge error when the point is behind the camera.
RPT_ALWAYS_INLINE double ReprojectionErrorSq(const ViewGeometry& g, const Eigen::Vector3d& point, const Keypoint& kp,
                                             double* depth) {
  const Eigen::Vector3d h = g.P.leftCols<3>() * point + g.P.col(3);
  *depth = h.z();
  if (h.z() <= 0) return 1e12;
  const double inv_z = 1.0 / h.z();
  const double du = h.x() * inv_z - kp.u, dv = h.y() * inv_z - kp.v;
  return du * du + dv * dv;
}

// What both passes read of proposal k: the geometry of its two views, its two 2D poses, and
// the index of its first joint in the per-joint arrays.
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

// Residual of joint i of a proposal: the mean reprojection error over both views, in metres at
// the joint (adaptive: `scale` = 1 / focal length) or relative to the pose's box (fixed:
// `scale` = 1 / box diagonal); implausibly large when the point is behind a camera.
RPT_ALWAYS_INLINE double JointResidual(const ViewGeometry& ga, const ViewGeometry& gb, const Eigen::Vector3d& point,
                                       const Keypoint& ka, const Keypoint& kb, double scale_a, double scale_b,
                                       bool adaptive) {
  double za = 1, zb = 1;
  const double ea = std::sqrt(ReprojectionErrorSq(ga, point, ka, &za));
  const double eb = std::sqrt(ReprojectionErrorSq(gb, point, kb, &zb));
  if (za <= 0 || zb <= 0) return 1e6;
  return adaptive ? 0.5 * (ea * za * scale_a + eb * zb * scale_b) : 0.5 * (ea * scale_a + eb * scale_b);
}

// Median of values[0..n) (may reorder them). A pair has a dozen core joints: for so few values
// the ranks are counted without branches (nth_element's mispredicted branches cost several
// times more); larger sets use nth_element.
double Median(double* values, int n) {
  if (n <= 0) return std::numeric_limits<double>::infinity();
  if (n > 32) {
    double* mid = values + n / 2;
    std::nth_element(values, mid, values + n);
    if (n % 2 == 1) return *mid;
    return 0.5 * (*mid + *std::max_element(values, mid));
  }
  // Rank = values below, plus equal values earlier in the list: ranks are 0..n-1, each once.
  double lower = 0, upper = 0;  // the values of rank (n - 1) / 2 and n / 2
  for (int i = 0; i < n; ++i) {
    int rank = 0;
    for (int j = 0; j < n; ++j) rank += (values[j] < values[i]) | ((values[j] == values[i]) & (j < i));
    lower = rank == (n - 1) / 2 ? values[i] : lower;
    upper = rank == n / 2 ? values[i] : upper;
  }
  return 0.5 * (lower + upper);
}

// Moves the `trimmed` lowest-scoring of the (score, weight) terms to the front, lowest first;
// of equal scores the earlier joint goes first, so the trimmed joints are well defined. One
// branch-free minimum search per trimmed term: only a quarter of a pose's joints are trimmed.
void MoveLowestToFront(std::pair<double, double>* terms, int n, int trimmed) {
  for (int t = 0; t < trimmed; ++t) {
    int lowest = t;
    double low = terms[t].first;  // kept in a register: no load in the dependency chain
    for (int i = t + 1; i < n; ++i) {
      const bool less = terms[i].first < low;
      low = less ? terms[i].first : low;
      lowest = less ? i : lowest;
    }
    std::swap(terms[t], terms[lowest]);
  }
}

// Adaptive mode: the mutually best pairs vote for the noise level (see noise_scale.h).
void VoteNoise(const PreparedViews& views, int num_views, const ScoreScratch& s, const Proposals& proposals,
               ScoreScratch* scratch, NoiseScale* noise) {
  const size_t slots = static_cast<size_t>(views.num_poses()) * num_views;
  scratch->best_residual.assign(slots, std::numeric_limits<double>::infinity());
  scratch->best_partner.assign(slots, -1);
  auto offer = [&](int pose, int other, double residual) {
    const size_t slot = static_cast<size_t>(pose) * num_views + views.view_of[other];
    if (residual < scratch->best_residual[slot]) {
      scratch->best_residual[slot] = residual;
      scratch->best_partner[slot] = other;
    }
  };
  for (int k = 0; k < proposals.size(); ++k) {
    offer(proposals.pairs[k].a, proposals.pairs[k].b, s.pair_residual[k]);
    offer(proposals.pairs[k].b, proposals.pairs[k].a, s.pair_residual[k]);
  }
  noise->BeginFrame();
  for (int k = 0; k < proposals.size(); ++k) {
    const int a = proposals.pairs[k].a, b = proposals.pairs[k].b;
    const size_t slot_a = static_cast<size_t>(a) * num_views + views.view_of[b];
    const size_t slot_b = static_cast<size_t>(b) * num_views + views.view_of[a];
    if (scratch->best_partner[slot_a] == b && scratch->best_partner[slot_b] == a) noise->Vote(s.pair_residual[k]);
  }
}

}  // namespace

double KernelScaleM(const ScoreOptions& options, double noise_m) {
  return options.scale == ScoreScale::kAdaptive ? options.scale_factor * noise_m : 0.5 * options.ray_gap_scale_m;
}

namespace {

// `vote_into` (may be null) receives the noise votes when pair scores are computed with the
// adaptive scale; the kernels then use `noise` (null: the prior).
int Score(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
          std::span<const ResolvedLimb> limbs, const ScoreOptions& options, NoiseScale* vote_into,
          const NoiseScale* noise, ScoreScratch* scratch, Proposals* proposals, bool pair_scores) {
  const int n = proposals->num_joints;
  const bool use_rep = options.mode != ScoreMode::kTriangulationOnly;
  const bool use_tri = options.mode != ScoreMode::kReprojectionOnly;
  const bool adaptive = options.scale == ScoreScale::kAdaptive;

  // With the adaptive scale, step 7 first measures every proposal's residuals, lets the frame's
  // mutually best pairs vote for the noise level, and only then applies the kernels (pass 1, then
  // pass 2), so even a scene's first frame is scored at its own noise level. Otherwise one pass
  // computes the residuals where the kernels need them.
  const bool vote = pair_scores && adaptive && vote_into != nullptr;
  scratch->pair_residual.resize(proposals->size());
  scratch->votes.resize(n);
  scratch->terms.resize(n);
  if (vote) {
    scratch->residual.resize(static_cast<size_t>(proposals->size()) * n);
    // Joints whose ray gap alone makes the score negligible (< e^-30) skip the projections (their
    // residual is implausible: the ray gap is about twice the residual). The bound uses the
    // estimate before this frame's votes; should the votes double it, a skipped joint's score
    // would still be below e^-7.5.
    const double skip_gap =
        use_tri ? 2.0 * std::sqrt(30.0) * KernelScaleM(options, noise->Estimate()) : std::numeric_limits<double>::infinity();
    for (int k = 0; k < proposals->size(); ++k) {
      const auto [ga, gb, ka, kb, base] = ViewsOf(views, geometry, *proposals, k);
      const Eigen::Vector3d* xyz = proposals->xyz.data() + base;
      const double* gap = proposals->gap.data() + base;
      const double* score = proposals->score.data() + base;
      const double* geometric = proposals->geometric.data() + base;
      double* residual = scratch->residual.data() + base;
      int votes = 0, plausible_votes = 0;
      for (int i = 0; i < n; ++i) {
        residual[i] = -1;
        if (score[i] <= 0 || geometric[i] >= 0) continue;  // not triangulated, or scored by an earlier step
        if (!use_rep) {
          residual[i] = 0;
        } else if (gap[i] > skip_gap) {
          residual[i] = 1e6;  // scored 0 below
        } else {
          residual[i] = JointResidual(ga, gb, xyz[i], ka[joints[i]], kb[joints[i]], 1.0 / ga.focal, 1.0 / gb.focal, true);
        }
        const double v = use_rep ? residual[i] : 0.5 * gap[i];
        scratch->votes[votes++] = v;
        plausible_votes += v <= NoiseScale::kMaxPlausibleResidualM ? 1 : 0;
      }
      // A pair whose median residual is implausible can neither vote nor keep a plausible pair
      // from being mutually best, so it gets infinity without computing the median.
      scratch->pair_residual[k] = votes > 0 && plausible_votes >= votes / 2 ? Median(scratch->votes.data(), votes)
                                                                            : std::numeric_limits<double>::infinity();
    }
    VoteNoise(views, static_cast<int>(geometry.size()), *scratch, *proposals, scratch, vote_into);
  }

  // Pass 2 (or the only pass): kernels, limb pruning, pair scores.
  const double noise_m = noise != nullptr ? noise->Estimate() : options.noise_prior_m;
  const double inv_rep = adaptive ? 1.0 / KernelScaleM(options, noise_m) : 1.0 / options.reprojection_scale_rel;
  const double inv_gap = adaptive ? 0.5 / KernelScaleM(options, noise_m) : 1.0 / options.ray_gap_scale_m;
  int pruned = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    const PosePair& pair = proposals->pairs[k];
    const auto [ga, gb, ka, kb, base] = ViewsOf(views, geometry, *proposals, k);
    const Eigen::Vector3d* xyz = proposals->xyz.data() + base;
    const double* gap = proposals->gap.data() + base;
    const double* residual = vote ? scratch->residual.data() + base : nullptr;
    double* score = proposals->score.data() + base;
    double* geometric = proposals->geometric.data() + base;
    const double scale_a = adaptive ? 1.0 / ga.focal : 1.0 / views.bbox_diag[pair.a];
    const double scale_b = adaptive ? 1.0 / gb.focal : 1.0 / views.bbox_diag[pair.b];
    for (int i = 0; i < n; ++i) {
      if (score[i] <= 0) continue;
      if (geometric[i] >= 0) {  // computed by an earlier step for the same pair (core joints)
        score[i] = geometric[i];
        continue;
      }
      double exponent = 0;
      if (use_tri) {
        const double r = gap[i] * inv_gap;
        exponent = r * r;
        if (exponent > 30.0) {  // negligible (< e^-30) whatever the reprojection error
          score[i] = geometric[i] = 0.0;
          continue;
        }
      }
      if (use_rep) {
        const double e = vote ? residual[i]
                              : JointResidual(ga, gb, xyz[i], ka[joints[i]], kb[joints[i]], scale_a, scale_b, adaptive);
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
    int seen = 0;
    for (int i = 0; i < n; ++i) {
      const Keypoint& a = ka[joints[i]];
      const Keypoint& b = kb[joints[i]];
      if (a.score <= 0 || b.score <= 0) continue;
      const double c = a.sqrt_score * b.sqrt_score;
      scratch->terms[seen++] = {score[i], options.use_confidence ? c : 1.0};
      if (options.use_confidence) score[i] *= c;
    }
    // The worst trim_fraction of the joints do not count (occluded joints reported at wrong places).
    const int trimmed = static_cast<int>(options.trim_fraction * seen);
    MoveLowestToFront(scratch->terms.data(), seen, trimmed);
    double weighted = 0, weights = 0;
    for (int t = trimmed; t < seen; ++t) {
      weighted += scratch->terms[t].first * scratch->terms[t].second;
      weights += scratch->terms[t].second;
    }
    proposals->pair_score[k] = weights > 0 ? weighted / weights : 0.0;
  }
  return pruned;
}

}  // namespace

int ScoreProposals(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                   std::span<const ResolvedLimb> limbs, const ScoreOptions& options, NoiseScale* noise,
                   ScoreScratch* scratch, Proposals* proposals) {
  return Score(views, geometry, joints, limbs, options, noise, noise, scratch, proposals, /*pair_scores=*/true);
}

int ScoreJoints(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> joints,
                std::span<const ResolvedLimb> limbs, const ScoreOptions& options, const NoiseScale& noise,
                ScoreScratch* scratch, Proposals* proposals) {
  return Score(views, geometry, joints, limbs, options, nullptr, &noise, scratch, proposals, /*pair_scores=*/false);
}

}  // namespace rpt
