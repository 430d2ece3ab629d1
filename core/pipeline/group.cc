// SPDX-License-Identifier: MIT
#include "core/pipeline/group.h"

#include <algorithm>
#include <limits>

namespace rpt {

namespace {

// Mean distance between group means a and b over joints valid in both, b's joints taken from
// the slots `map` (identity or the left/right mirror). +inf with fewer than 2 common joints.
double GroupDistance(const GroupScratch& s, int n, int a, int b, std::span<const int> map) {
  double sum = 0;
  int common = 0;
  for (int i = 0; i < n; ++i) {
    const size_t ai = static_cast<size_t>(a) * n + i, bi = static_cast<size_t>(b) * n + map[i];
    if (s.mean_count[ai] == 0 || s.mean_count[bi] == 0) continue;
    sum += (s.mean[ai] - s.mean[bi]).norm();
    ++common;
  }
  return common >= 2 ? sum / common : std::numeric_limits<double>::infinity();
}

}  // namespace

int ResolveMinGroupSize(const GroupOptions& options, int num_cameras) {
  if (options.min_group_size > 0) return options.min_group_size;
  return num_cameras >= 10 ? 2 : 1;  // automatic, see GroupOptions
}

int steps::Group(const GroupOptions& options, const GroupInput& in, GroupScratch* scratch, Proposals* proposals,
                 Groups* groups, FrameStats* counters) {
  const int num_poses = in.num_poses;
  const std::span<const int> mirror = in.mirror;
  counters->small_groups = counters->conflicting_proposals = counters->mirrored_groups = 0;
  int* const conflicting = &counters->conflicting_proposals;
  int* const small_groups = &counters->small_groups;
  const int num = proposals->size();
  const int n = proposals->num_joints;
  GroupScratch& s = *scratch;
  // Visiting order: by decreasing pair score, ties by index (sorted as (-score, index) keys).
  s.keyed.resize(num);
  for (int k = 0; k < num; ++k) s.keyed[k] = {-proposals->pair_score[k], k};
  std::sort(s.keyed.begin(), s.keyed.end());
  s.order.resize(num);
  for (int k = 0; k < num; ++k) s.order[k] = s.keyed[k].second;
  s.sum.clear();
  s.running_mean.clear();
  s.count.clear();
  s.size.clear();

  s.center_sum.clear();
  s.center_count.clear();
  s.center.clear();
  for (int k : s.order) {
    const Eigen::Vector3d* xyz = proposals->xyz.data() + static_cast<size_t>(k) * n;
    const double* score = proposals->score.data() + static_cast<size_t>(k) * n;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    int valid = 0;
    for (int i = 0; i < n; ++i) {
      if (score[i] <= 0) continue;
      center += xyz[i];
      ++valid;
    }
    if (valid > 0) center /= valid;
    int best_group = -1;
    double best_distance = options.max_distance_m;
    const int num_groups = static_cast<int>(s.size.size());
    const double bound_sq = 9.0 * options.max_distance_m * options.max_distance_m;
    for (int g = 0; g < num_groups; ++g) {
      // Cheap bound first: the mean joint distance is at least the distance of the centres (when
      // both cover the same joints); 3x leaves room for different joint subsets.
      if ((s.center[g] - center).squaredNorm() > bound_sq) continue;
      // Scalar: a short row of core joints, summed in joint order (a SIMD kernel that has to keep
      // that order was slower, results/bench.md).
      int common = 0;
      double sum = 0;
      const size_t g0 = static_cast<size_t>(g) * n;
      for (int i = 0; i < n; ++i) {
        if (score[i] <= 0 || s.count[g0 + i] == 0) continue;
        sum += (xyz[i] - s.running_mean[g0 + i]).norm();
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
      s.running_mean.resize(s.running_mean.size() + n, Eigen::Vector3d::Zero());  // the mirror check copies it
      s.count.resize(s.count.size() + n, 0);
      s.size.push_back(0);
      s.center_sum.push_back(Eigen::Vector3d::Zero());
      s.center_count.push_back(0);
      // No member centre yet: NaN, which the bound never skips.
      s.center.push_back(Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
    }
    for (int i = 0; i < n; ++i) {
      if (score[i] <= 0) continue;
      const size_t gi = static_cast<size_t>(best_group) * n + i;
      s.sum[gi] += xyz[i];
      ++s.count[gi];
      s.running_mean[gi] = s.sum[gi] / s.count[gi];
    }
    if (valid > 0) {
      s.center_sum[best_group] += center;
      ++s.center_count[best_group];
      s.center[best_group] = s.center_sum[best_group] / s.center_count[best_group];
    }
    ++s.size[best_group];
    proposals->group[k] = best_group;
  }

  const int num_groups = static_cast<int>(s.size.size());
  s.lost_members.assign(num_groups, 0);
  if (options.exclusive_poses) {
    s.strength.assign(num_groups, 0.0);
    for (int k = 0; k < num; ++k) s.strength[proposals->group[k]] += proposals->pair_score[k];
    // Each pose goes to the strongest group using it (ties: the older group).
    s.owner.assign(num_poses, -1);
    auto claim = [&](int pose, int g) {
      int& owner = s.owner[pose];
      if (owner < 0 || s.strength[g] > s.strength[owner] || (s.strength[g] == s.strength[owner] && g < owner)) {
        owner = g;
      }
    };
    for (int k = 0; k < num; ++k) {
      claim(proposals->pairs[k].a, proposals->group[k]);
      claim(proposals->pairs[k].b, proposals->group[k]);
    }
    for (int k = 0; k < num; ++k) {
      int& g = proposals->group[k];
      if (s.owner[proposals->pairs[k].a] == g && s.owner[proposals->pairs[k].b] == g) continue;
      --s.size[g];
      s.lost_members[g] = 1;
      g = -1;
      ++*conflicting;
    }
  }

  if (options.drop_mirrored && num_groups > 1) {
    // Group means over the surviving members, and strengths. A group that lost no member to
    // exclusive_poses has its mean already (the running mean of the assignment); the others are
    // summed again over their survivors, in the same (visiting) order.
    s.mean.assign(s.running_mean.begin(), s.running_mean.end());
    s.mean_count.assign(s.count.begin(), s.count.end());
    s.strength.assign(num_groups, 0.0);
    bool any_lost = false;
    for (int g = 0; g < num_groups; ++g) {
      if (!s.lost_members[g]) continue;
      any_lost = true;
      for (int i = 0; i < n; ++i) {
        s.mean[static_cast<size_t>(g) * n + i].setZero();
        s.mean_count[static_cast<size_t>(g) * n + i] = 0;
      }
    }
    for (int k = 0; k < num; ++k) {
      if (proposals->group[k] >= 0) s.strength[proposals->group[k]] += proposals->pair_score[k];
    }
    if (any_lost) {
      for (int k : s.order) {
        const int g = proposals->group[k];
        if (g < 0 || !s.lost_members[g]) continue;
        for (int i = 0; i < n; ++i) {
          const size_t idx = static_cast<size_t>(k) * n + i;
          if (proposals->score[idx] <= 0) continue;
          s.mean[static_cast<size_t>(g) * n + i] += proposals->xyz[idx];
          ++s.mean_count[static_cast<size_t>(g) * n + i];
        }
      }
      for (int g = 0; g < num_groups; ++g) {
        if (!s.lost_members[g]) continue;
        for (int i = 0; i < n; ++i) {
          const size_t gi = static_cast<size_t>(g) * n + i;
          if (s.mean_count[gi] > 0) s.mean[gi] /= s.mean_count[gi];
        }
      }
    }
    for (int a = 0; a < num_groups; ++a) {
      for (int b = a + 1; b < num_groups; ++b) {
        if (s.size[a] <= 0 || s.size[b] <= 0) continue;
        if (GroupDistance(s, n, a, b, mirror) >= options.max_distance_m) continue;
        const int weaker = s.strength[b] > s.strength[a] ? a : b;
        s.size[weaker] = -s.size[weaker];  // mark dropped (members are cleared below)
        ++counters->mirrored_groups;
      }
    }
    for (int k = 0; k < num; ++k) {
      int& g = proposals->group[k];
      if (g >= 0 && s.size[g] < 0) g = -1;
    }
    for (int g = 0; g < num_groups; ++g) s.size[g] = std::max(s.size[g], 0);
  }

  // Drop small (or emptied) groups, renumber the rest in creation order, list members contiguously.
  s.renumber.assign(num_groups, -1);
  int kept = 0;
  *small_groups = 0;
  for (int g = 0; g < num_groups; ++g) {
    if (s.size[g] > 0 && s.size[g] >= options.min_group_size) {
      s.renumber[g] = kept++;
    } else if (s.size[g] > 0) {
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
