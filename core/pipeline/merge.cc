// SPDX-License-Identifier: MIT
#include "core/pipeline/merge.h"

#include <algorithm>

#include "core/pipeline/simd_kernels.h"

namespace rpt {

int steps::Merge(const MergeOptions& options, const MergeInput& in, MergeScratch* scratch, Poses3D* persons) {
  const Proposals& proposals = in.proposals;
  const Groups& groups = in.groups;
  const int n = proposals.num_joints;
  auto& candidates = scratch->candidates;  // (squared distance to the mean, proposal)
  const double max_distance_sq = options.max_distance_m * options.max_distance_m;
  const double min_score = std::max(options.min_joint_score, 1e-300);  // score 0 = invalid in any case
  // The SIMD kernel merges a group's joints side by side (its selection of the top_k reproduces
  // the k minimum searches below, not nth_element's order).
  const bool use_simd = simd::Enabled() && options.top_k <= 8;
  const simd::MergeParams params{.min_score = min_score,
                                 .max_distance_m = options.max_distance_m,
                                 .max_distance_sq = max_distance_sq,
                                 .top_k = options.top_k,
                                 .score_weighted = options.score_weighted,
                                 .keep_best = options.keep_best_when_all_far};
  for (int g = 0; g < groups.size(); ++g) {
    auto person = persons->AddPerson();
    const int first = groups.begin[g], last = groups.begin[g + 1];
    if (use_simd && last > first) {
      scratch->distances.resize(std::max(scratch->distances.size(), simd::MergeScratchSize(last - first)));
      const size_t at = static_cast<size_t>(first) * n;
      simd::MergeGroup(params, proposals.xyz[at].data(), proposals.score.data() + at, last - first, n,
                       scratch->distances.data(), person.data());
      continue;
    }
    for (int j = 0; j < n; ++j) {
      candidates.clear();
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      int best = -1;  // highest-scoring candidate (fallback)
      double best_score = -1;
      for (int m = first; m < last; ++m) {
        const size_t idx = static_cast<size_t>(m) * n + j;
        const double score = proposals.score[idx];
        if (score < min_score) continue;
        candidates.emplace_back(0.0, m);
        mean += proposals.xyz[idx];
        if (score > best_score) {
          best_score = score;
          best = m;
        }
      }
      if (candidates.empty()) {
        person.col(j).setZero();
        continue;
      }
      mean /= static_cast<double>(candidates.size());
      size_t kept = 0;
      for (auto& c : candidates) {
        c.first = (proposals.xyz[static_cast<size_t>(c.second) * n + j] - mean).squaredNorm();
        if (options.max_distance_m <= 0 || c.first <= max_distance_sq) candidates[kept++] = c;
      }
      candidates.resize(kept);
      if (candidates.empty() && options.keep_best_when_all_far) candidates.emplace_back(0.0, best);
      if (options.top_k > 0 && static_cast<int>(candidates.size()) > options.top_k) {
        // The top_k closest (ties: the earlier proposal). For the usual small k, k searches for the
        // minimum beat nth_element, whose comparisons mispredict.
        if (options.top_k <= 8) {
          for (int t = 0; t < options.top_k; ++t) {
            size_t lowest = t;
            std::pair<double, int> low = candidates[t];  // in registers: no load in the dependency chain
            for (size_t i = t + 1; i < candidates.size(); ++i) {
              const bool less = candidates[i] < low;
              low = less ? candidates[i] : low;
              lowest = less ? i : lowest;
            }
            std::swap(candidates[t], candidates[lowest]);
          }
        } else {
          std::nth_element(candidates.begin(), candidates.begin() + (options.top_k - 1), candidates.end());
        }
        candidates.resize(options.top_k);
      }
      if (candidates.empty()) {
        person.col(j).setZero();
        continue;
      }
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double weights = 0, scores = 0;
      for (const auto& c : candidates) {
        const size_t idx = static_cast<size_t>(c.second) * n + j;
        const double w = options.score_weighted ? proposals.score[idx] : 1.0;
        sum += w * proposals.xyz[idx];
        weights += w;
        scores += proposals.score[idx];
      }
      person.col(j).head<3>() = sum / weights;
      person(3, j) = scores / static_cast<double>(candidates.size());
    }
  }
  return groups.size();
}

}  // namespace rpt
