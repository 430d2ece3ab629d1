// SPDX-License-Identifier: MIT
#include "core/pipeline/prefilter_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rpt {

namespace {

// Keeps at most max_pairs_per_person of the pairs matched to each previous person: those with the
// viewing-ray angle at the person's last centre closest to 90 degrees (largest sin).
int ApplyPairBudget(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> core_joints,
                    const PreviousPersons& previous,
                    const PrefilterOptions& options, PrefilterScratch* scratch, std::vector<PosePair>* pairs) {
  const int num_previous = previous.size();
  const int num_core = previous.num_core;
  const std::vector<int>& match = scratch->match;
  const size_t budget = static_cast<size_t>(options.max_pairs_per_person);
  scratch->centers.assign(num_previous, Eigen::Vector3d::Zero());
  for (int q = 0; q < num_previous; ++q) {
    int n = 0;
    for (int c = 0; c < num_core; ++c) {
      const size_t idx = static_cast<size_t>(q) * num_core + c;
      if (previous.score[idx] <= 0) continue;
      scratch->centers[q] += previous.xyz[idx];
      ++n;
    }
    if (n > 0) scratch->centers[q] /= n;
  }
  scratch->keep.assign(pairs->size(), 1);
  scratch->covered.resize(views.num_poses());
  for (int q = 0; q < num_previous; ++q) {
    scratch->budget.clear();
    for (size_t k = 0; k < pairs->size(); ++k) {
      const PosePair& pair = (*pairs)[k];
      if (match[pair.a] != q) continue;  // both sides match q (mixed pairs were dropped)
      const Eigen::Vector3d ra = (geometry[views.view_of[pair.a]].center - scratch->centers[q]).normalized();
      const Eigen::Vector3d rb = (geometry[views.view_of[pair.b]].center - scratch->centers[q]).normalized();
      // Quality: triangulation angle (sin) times the 2D evidence both poses share (mean over the
      // core joints of sqrt(conf_a * conf_b); truncated or uncertain poses rank low).
      const Keypoint* ka = views.Pose(pair.a);
      const Keypoint* kb = views.Pose(pair.b);
      double evidence = 0;
      for (int c : core_joints) evidence += std::sqrt(ka[c].score * kb[c].score);
      const double quality = ra.cross(rb).norm() * evidence / static_cast<double>(core_joints.size());
      scratch->budget.emplace_back(-quality, static_cast<int>(k));  // best first
    }
    if (scratch->budget.size() <= budget) continue;
    // Best pairs first. Every pose of the person keeps its two best pairs (so the person's group
    // claims all its poses, see group.exclusive_poses), then the budget fills by quality.
    std::sort(scratch->budget.begin(), scratch->budget.end());
    for (const auto& [score, k] : scratch->budget) {
      scratch->covered[(*pairs)[k].a] = scratch->covered[(*pairs)[k].b] = 0;
      scratch->keep[k] = 0;
    }
    // Two pairs per pose: if the score filter later drops one, the pose is still claimed.
    constexpr char kPairsPerPose = 2;
    size_t used = 0;
    for (const auto& [score, k] : scratch->budget) {
      const PosePair& pair = (*pairs)[k];
      if (scratch->covered[pair.a] >= kPairsPerPose && scratch->covered[pair.b] >= kPairsPerPose) continue;
      ++scratch->covered[pair.a];
      ++scratch->covered[pair.b];
      scratch->keep[k] = 1;
      ++used;
    }
    for (const auto& [score, k] : scratch->budget) {
      if (used >= budget) break;
      if (!scratch->keep[k]) {
        scratch->keep[k] = 1;
        ++used;
      }
    }
  }
  int kept = 0;
  for (size_t k = 0; k < pairs->size(); ++k) {
    if (scratch->keep[k]) (*pairs)[kept++] = (*pairs)[k];
  }
  pairs->resize(kept);
  return kept;
}

}  // namespace

int PrefilterPairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                   std::span<const int> core_joints, const PreviousPersons& previous, double timestamp_s,
                   const PrefilterOptions& options, PrefilterScratch* scratch, std::vector<PosePair>* pairs) {
  std::vector<int>* match = &scratch->match;
  const int num_previous = previous.size();
  if (!options.enabled || num_previous == 0) return static_cast<int>(pairs->size());

  const int num_core = static_cast<int>(core_joints.size());
  constexpr double kPersonSizeM = 1.8;
  const double elapsed_s = std::max(0.0, timestamp_s - previous.timestamp_s);
  const double radius_rel = options.max_distance_rel + options.person_speed_m_s * elapsed_s / kPersonSizeM;
  match->assign(views.num_poses(), kPoseFree);
  scratch->distance.assign(views.num_poses(), 0.0);
  // Project every previous person into every view once.
  const int num_views = static_cast<int>(views.view_begin.size()) - 1;
  const size_t per_view = static_cast<size_t>(num_previous) * num_core;
  scratch->projected.resize(per_view * num_views);
  for (int v = 0; v < num_views; ++v) {
    const ViewGeometry& geo = geometry[v];
    for (size_t idx = 0; idx < per_view; ++idx) {
      Eigen::Vector2d& uv = scratch->projected[v * per_view + idx];
      const Eigen::Vector3d h = geo.P.leftCols<3>() * previous.xyz[idx] + geo.P.col(3);
      if (previous.score[idx] <= 0 || h.z() <= 0) {
        uv.setConstant(std::numeric_limits<double>::quiet_NaN());
      } else {
        uv = h.head<2>() / h.z();
      }
    }
  }
  for (int g = 0; g < views.num_poses(); ++g) {
    const Keypoint* kps = views.Pose(g);
    const Eigen::Vector2d* projected = scratch->projected.data() + views.view_of[g] * per_view;
    const double radius = radius_rel * views.bbox_diag[g];
    double best = std::numeric_limits<double>::infinity(), second = best;
    int best_q = -1;
    for (int q = 0; q < num_previous; ++q) {
      double sum = 0;
      int n = 0;
      for (int c = 0; c < num_core; ++c) {
        const Keypoint& kp = kps[core_joints[c]];
        const Eigen::Vector2d& uv = projected[static_cast<size_t>(q) * num_core + c];
        if (kp.score <= 0 || std::isnan(uv.x())) continue;
        const double du = uv.x() - kp.u, dv = uv.y() - kp.v;
        sum += std::sqrt(du * du + dv * dv);
        ++n;
      }
      if (n < 3) continue;
      const double mean = sum / n;
      if (mean < best) {
        second = best;
        best = mean;
        best_q = q;
      } else if (mean < second) {
        second = mean;
      }
    }
    if (best < radius && second >= options.ambiguity_ratio * best) {
      (*match)[g] = best_q;
      scratch->distance[g] = best;
    } else if (best < 2 * radius) {
      (*match)[g] = kPoseAmbiguous;
    }
  }
  // One match per person and view: of several poses of a view matching q, only the closest keeps it.
  for (int v = 0; v < num_views; ++v) {
    for (int g = views.view_begin[v]; g < views.view_begin[v + 1]; ++g) {
      if ((*match)[g] < 0) continue;
      for (int h = g + 1; h < views.view_begin[v + 1]; ++h) {
        if ((*match)[h] != (*match)[g]) continue;
        const int loser = scratch->distance[h] < scratch->distance[g] ? g : h;
        (*match)[loser] = kPoseAmbiguous;
        if (loser == g) break;
      }
    }
  }

  int kept = 0;
  for (const PosePair& pair : *pairs) {
    const int a = (*match)[pair.a], b = (*match)[pair.b];
    const bool drop = (a >= 0 && b >= 0 && a != b) || (a >= 0 && b == kPoseFree) || (a == kPoseFree && b >= 0);
    if (!drop) (*pairs)[kept++] = pair;
  }
  pairs->resize(kept);
  if (options.max_pairs_per_person > 0) kept = ApplyPairBudget(views, geometry, core_joints, previous, options, scratch, pairs);
  return kept;
}

}  // namespace rpt
