// SPDX-License-Identifier: MIT
#include "core/pipeline/merge_groups.h"

#include <algorithm>

namespace rpt {

int MergeGroups(const MergeOptions& options, const Proposals& proposals, const Groups& groups,
                MergeScratch* scratch, Poses3D* persons) {
  const int n = proposals.num_joints;
  auto& candidates = scratch->candidates;
  for (int g = 0; g < groups.size(); ++g) {
    auto person = persons->AddPerson();
    for (int j = 0; j < n; ++j) {
      candidates.clear();
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int m = groups.begin[g]; m < groups.begin[g + 1]; ++m) {
        const size_t idx = static_cast<size_t>(m) * n + j;
        if (proposals.score[idx] < options.min_joint_score || proposals.score[idx] <= 0) continue;
        candidates.emplace_back(0.0, m);
        mean += proposals.xyz[idx];
      }
      if (candidates.empty()) {
        person.col(j).setZero();
        continue;
      }
      mean /= static_cast<double>(candidates.size());
      for (auto& [distance, m] : candidates) {
        distance = (proposals.xyz[static_cast<size_t>(m) * n + j] - mean).norm();
      }
      if (options.max_distance_m > 0) {
        // Best-scoring candidate, kept if the filter below would drop everything.
        std::pair<double, int> best = candidates.front();
        double best_score = -1;
        for (const auto& c : candidates) {
          const double score = proposals.score[static_cast<size_t>(c.second) * n + j];
          if (score > best_score) {
            best_score = score;
            best = c;
          }
        }
        candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                        [&](const auto& c) { return c.first > options.max_distance_m; }),
                         candidates.end());
        if (candidates.empty() && options.keep_best_when_all_far) candidates.push_back(best);
      }
      if (options.top_k > 0 && static_cast<int>(candidates.size()) > options.top_k) {
        std::partial_sort(candidates.begin(), candidates.begin() + options.top_k, candidates.end());
        candidates.resize(options.top_k);
      }
      if (candidates.empty()) {
        person.col(j).setZero();
        continue;
      }
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double weights = 0, scores = 0;
      for (const auto& [distance, m] : candidates) {
        const size_t idx = static_cast<size_t>(m) * n + j;
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
