// SPDX-License-Identifier: MIT
#include "core/pipeline/group_proposals.h"

#include <algorithm>

namespace rpt {

int GroupProposals(const GroupOptions& options, Proposals* proposals, Groups* groups, GroupScratch* scratch,
                   int* small_groups) {
  const int num = proposals->size();
  const int n = proposals->num_joints;
  GroupScratch& s = *scratch;
  s.order.resize(num);
  for (int k = 0; k < num; ++k) s.order[k] = k;
  std::sort(s.order.begin(), s.order.end(), [&](int x, int y) {
    const double sx = proposals->pair_score[x], sy = proposals->pair_score[y];
    return sx > sy || (sx == sy && x < y);
  });
  s.sum.clear();
  s.count.clear();
  s.size.clear();

  for (int k : s.order) {
    const Eigen::Vector3d* xyz = proposals->xyz.data() + static_cast<size_t>(k) * n;
    const double* score = proposals->score.data() + static_cast<size_t>(k) * n;
    int best_group = -1;
    double best_distance = options.max_distance_m;
    const int num_groups = static_cast<int>(s.size.size());
    for (int g = 0; g < num_groups; ++g) {
      double sum = 0;
      int common = 0;
      for (int i = 0; i < n; ++i) {
        const size_t gi = static_cast<size_t>(g) * n + i;
        if (score[i] <= 0 || s.count[gi] == 0) continue;
        sum += (xyz[i] - s.sum[gi] / s.count[gi]).norm();
        ++common;
      }
      if (common < 2) continue;
      const double distance = sum / common;
      if (distance < best_distance) {
        best_distance = distance;
        best_group = g;
      }
    }
    if (best_group < 0) {
      best_group = num_groups;
      s.sum.resize(s.sum.size() + n, Eigen::Vector3d::Zero());
      s.count.resize(s.count.size() + n, 0);
      s.size.push_back(0);
    }
    for (int i = 0; i < n; ++i) {
      if (score[i] <= 0) continue;
      const size_t gi = static_cast<size_t>(best_group) * n + i;
      s.sum[gi] += xyz[i];
      ++s.count[gi];
    }
    ++s.size[best_group];
    proposals->group[k] = best_group;
  }

  // Drop small groups, renumber the rest in creation order, list members contiguously.
  const int num_groups = static_cast<int>(s.size.size());
  s.renumber.assign(num_groups, -1);
  int kept = 0;
  *small_groups = 0;
  for (int g = 0; g < num_groups; ++g) {
    if (s.size[g] >= options.min_group_size) {
      s.renumber[g] = kept++;
    } else {
      ++*small_groups;
    }
  }
  groups->begin.assign(kept + 1, 0);
  for (int k = 0; k < num; ++k) {
    int& g = proposals->group[k];
    g = g >= 0 ? s.renumber[g] : -1;
    if (g >= 0) ++groups->begin[g + 1];
  }
  for (int g = 0; g < kept; ++g) groups->begin[g + 1] += groups->begin[g];
  groups->members.resize(groups->begin[kept]);
  s.renumber.assign(kept, 0);  // reuse as fill cursor
  for (int k = 0; k < num; ++k) {
    const int g = proposals->group[k];
    if (g >= 0) groups->members[groups->begin[g] + s.renumber[g]++] = k;
  }
  return kept;
}

}  // namespace rpt
