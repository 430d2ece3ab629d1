// SPDX-License-Identifier: MIT
#include "core/pipeline/score.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/pipeline/median.h"

namespace rpt {
namespace {

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

int steps::Score(const ScoreOptions& options, const ScoreInput& in, NoiseScale* noise, ScoreScratch* scratch,
                 Proposals* proposals, ScoreKernel* kernel, FrameStats* stats) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const std::span<const int> joints = in.core_joints;
  const int n = proposals->num_joints;
  const bool use_rep = options.mode != ScoreMode::kTriangulationOnly;
  const bool use_tri = options.mode != ScoreMode::kReprojectionOnly;
  const bool adaptive = options.scale == ScoreScale::kAdaptive;
  // The SIMD kernels read the core joints' columns of the undistort step (other subsets: scalar).
  const KeypointColumns* columns =
      simd::Enabled() && std::equal(joints.begin(), joints.end(), views.core_joints.begin(), views.core_joints.end())
          ? &views.core_columns
          : nullptr;

  // Pass 1 (adaptive scale): every proposal's residuals, then the votes. Otherwise the single
  // pass below computes the residuals where the kernels need them.
  scratch->pair_residual.resize(proposals->size());
  scratch->votes.resize(n);
  scratch->terms.resize(n);
  if (adaptive) {
    scratch->residual.resize(static_cast<size_t>(proposals->size()) * n);
    // Joints whose ray gap alone makes the score negligible (< e^-30) skip the projections (their
    // residual is implausible: the ray gap is about twice the residual). The bound uses the
    // estimate before this frame's votes; should the votes double it, a skipped joint's score
    // would still be below e^-7.5.
    const double skip_gap = use_tri ? 2.0 * std::sqrt(30.0) * KernelScaleM(options, noise->Estimate())
                                    : std::numeric_limits<double>::infinity();
    for (int k = 0; k < proposals->size(); ++k) {
      const auto [ga, gb, ka, kb, base] = ViewsOf(views, geometry, *proposals, k);
      const Eigen::Vector3d* xyz = proposals->xyz.data() + base;
      const double* gap = proposals->gap.data() + base;
      const double* score = proposals->score.data() + base;
      const double* geometric = proposals->geometric.data() + base;
      double* residual = scratch->residual.data() + base;
      if (columns != nullptr) {
        const PosePair& pair = proposals->pairs[k];
        simd::PairResiduals({.Pa = ga.P.data(), .Pb = gb.P.data(), .scale_a = 1.0 / ga.focal,
                             .scale_b = 1.0 / gb.focal, .adaptive = true},
                            simd::ColumnsOf(*columns, pair.a), simd::ColumnsOf(*columns, pair.b), n,
                            reinterpret_cast<const double*>(xyz), gap, score, geometric, use_rep, skip_gap, residual);
      } else {
        for (int i = 0; i < n; ++i) {
          residual[i] = -1;
          if (score[i] <= 0 || geometric[i] >= 0) continue;  // not triangulated, or scored by an earlier step
          if (!use_rep) {
            residual[i] = 0;
          } else if (gap[i] > skip_gap) {
            residual[i] = 1e6;  // scored 0 below
          } else {
            residual[i] =
                JointResidual(ga, gb, xyz[i], ka[joints[i]], kb[joints[i]], 1.0 / ga.focal, 1.0 / gb.focal, true);
          }
        }
      }
      int votes = 0, plausible_votes = 0;
      for (int i = 0; i < n; ++i) {
        if (residual[i] < 0) continue;  // not triangulated, or scored by an earlier step
        const double v = use_rep ? residual[i] : 0.5 * gap[i];
        scratch->votes[votes++] = v;
        plausible_votes += v <= NoiseScale::kMaxPlausibleResidualM ? 1 : 0;
      }
      // A pair whose median residual is implausible can neither vote nor keep a plausible pair
      // from being mutually best, so it gets infinity without computing the median.
      scratch->pair_residual[k] = votes > 0 && plausible_votes >= votes / 2 ? Median(scratch->votes.data(), votes)
                                                                            : std::numeric_limits<double>::infinity();
    }
    VoteNoise(views, static_cast<int>(geometry.size()), *scratch, *proposals, scratch, noise);
  }

  // Pass 2 (or the only pass): kernels, limb pruning, pair scores.
  *kernel = MakeScoreKernel(options, noise->Estimate());
  int pruned = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    const ProposalViews pv = ViewsOf(views, geometry, *proposals, k);
    const double* residual = adaptive ? scratch->residual.data() + pv.base : nullptr;
    pruned += ScoreJointsOfProposal(*kernel, views, pv, joints, in.core_limbs, in.core_limb_columns, residual, columns,
                                    proposals, k);
    // Pair score over the joints both views saw; joint score gets the 2D confidence.
    double* score = proposals->score.data() + pv.base;
    int seen = 0;
    for (int i = 0; i < n; ++i) {
      const Keypoint& a = pv.ka[joints[i]];
      const Keypoint& b = pv.kb[joints[i]];
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
  stats->pruned_limbs += pruned;
  stats->noise_m = adaptive ? noise->Estimate() : 0.0;
  return proposals->size();
}

}  // namespace rpt
