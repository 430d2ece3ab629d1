// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_full.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/pipeline/pair_triangulation.h"
#include "core/pipeline/simd_kernels.h"

namespace rpt {
namespace {

using View = TriangulateFullScratch::View;

// Distance of `x` from the (unit) viewing ray of `view`.
double RayDistance(const View& view, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - view.center;
  return (d - view.ray * view.ray.dot(d)).norm();
}

// The point with the least sum of squared distances to the rays of the views neither dropped nor
// `skip`, and the inverse of that least-squares system (its covariance per unit of ray noise);
// false when those rays are (nearly) parallel.
bool FitRays(const std::vector<View>& views, int skip, Eigen::Vector3d* x, Eigen::Matrix3d* inverse) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int i = 0; i < static_cast<int>(views.size()); ++i) {
    if (i == skip || views[i].dropped) continue;
    const Eigen::Matrix3d p = Eigen::Matrix3d::Identity() - views[i].ray * views[i].ray.transpose();
    a += p;
    b += p * views[i].center;
  }
  if (!(a.determinant() > 1e-12)) return false;
  *inverse = a.inverse();
  *x = *inverse * b;
  return true;
}

// Drops the views of joint j that disagree with the others (triangulate_full.h); true when any was.
// A view's disagreement is the distance of its ray from the others' point, divided by
// sqrt(1 + the others' point's variance along that offset per unit of ray noise): two rays that meet
// at a narrow angle fix their point poorly in depth, and a third view is not blamed for that.
bool DropDisagreeingViews(const TriangulateOptions& options, std::vector<View>& views, std::vector<double>& distances) {
  int active = static_cast<int>(views.size());
  bool any = false;
  while (active >= 3) {
    int worst = -1;
    double worst_z = -1, worst_distance = 0;
    Eigen::Vector3d worst_x = Eigen::Vector3d::Zero();
    for (int v = 0; v < static_cast<int>(views.size()); ++v) {
      if (views[v].dropped) continue;
      Eigen::Vector3d x;
      Eigen::Matrix3d inverse;
      if (!FitRays(views, v, &x, &inverse)) continue;
      const Eigen::Vector3d d = x - views[v].center;
      const Eigen::Vector3d offset = d - views[v].ray * views[v].ray.dot(d);
      const double distance = offset.norm();
      const double z =
          distance > 0 ? distance / std::sqrt(1.0 + offset.dot(inverse * offset) / (distance * distance)) : 0.0;
      if (z > worst_z) {
        worst_z = z;
        worst = v;
        worst_x = x;
        worst_distance = distance;
      }
    }
    if (worst < 0) break;
    distances.clear();
    for (int i = 0; i < static_cast<int>(views.size()); ++i)
      if (i != worst && !views[i].dropped) distances.push_back(RayDistance(views[i], worst_x));
    const auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
    std::nth_element(distances.begin(), middle, distances.end());
    if (!(worst_z > options.robust_min_m && worst_distance > options.robust_ratio * *middle)) break;
    views[worst].dropped = true;
    --active;
    any = true;
  }
  return any;
}

bool IsDropped(const std::vector<View>& views, int pose) {
  for (const View& v : views)
    if (v.pose == pose) return v.dropped;
  return false;
}

// triangulate.robust_views over the proposals of group g (proposals [begin, end)).
void DropDisagreeingViewsOfGroup(const TriangulateOptions& options, const steps::TriangulateFullInput& in, int begin, int end,
                                 TriangulateFullScratch* scratch, Proposals* proposals) {
  const int n = proposals->num_joints;
  auto& poses = scratch->poses;
  poses.clear();
  for (int k = begin; k < end; ++k) {
    for (const int pose : {proposals->pairs[k].a, proposals->pairs[k].b})
      if (std::find(poses.begin(), poses.end(), pose) == poses.end()) poses.push_back(pose);
  }
  if (poses.size() < 3) return;
  auto& views = scratch->views;
  for (int j = 0; j < n; ++j) {
    views.clear();
    for (const int pose : poses) {
      const Keypoint& kp = in.views.Pose(pose)[j];
      if (kp.score <= 0) continue;
      views.push_back(View{.pose = pose, .center = in.geometry[in.views.view_of[pose]].center,
                           .ray = kp.ray.normalized(), .dropped = false});
    }
    if (views.size() < 3 || !DropDisagreeingViews(options, views, scratch->distances)) continue;
    // Only when a proposal of agreeing views has the joint: else leave it as it is.
    bool agreeing = false;
    for (int k = begin; k < end && !agreeing; ++k) {
      const PosePair& pair = proposals->pairs[k];
      agreeing = proposals->score[static_cast<size_t>(k) * n + j] > 0 && !IsDropped(views, pair.a) &&
                 !IsDropped(views, pair.b);
    }
    if (!agreeing) continue;
    for (int k = begin; k < end; ++k) {
      const PosePair& pair = proposals->pairs[k];
      if (IsDropped(views, pair.a) || IsDropped(views, pair.b)) proposals->score[static_cast<size_t>(k) * n + j] = 0;
    }
  }
}

}  // namespace

int steps::TriangulateFull(const TriangulateOptions& options, const TriangulateFullInput& in,
                           TriangulateFullScratch* scratch, Proposals* proposals, FrameStats* stats) {
  const PreparedViews& views = in.views;
  const Proposals& core = in.core;
  const int num_joints = static_cast<int>(in.all_joints.size());
  proposals->Clear(num_joints);
  const int num_core = core.num_joints;
  // The SIMD kernels read the columns of all joints (when the proposals' joints are exactly them;
  // the DLT method takes the scalar path).
  bool all_columns = simd::Enabled() && views.all_columns.stride == num_joints && options.method != TriangulationMethod::kDlt;
  for (int j = 0; j < num_joints && all_columns; ++j) all_columns = in.all_joints[j] == j;
  for (int m : in.groups.members) {
    const PosePair& pair = core.pairs[m];
    const int k = proposals->size();
    proposals->Add(pair);
    const size_t base = static_cast<size_t>(k) * num_joints;
    Eigen::Vector3d* xyz = proposals->xyz.data() + base;
    double* gap = proposals->gap.data() + base;
    double* joint_score = proposals->score.data() + base;
    double* geometric = proposals->geometric.data() + base;
    // Core joints: same pair, same rays -> same result; reuse it.
    for (int c = 0; c < num_core && !all_columns; ++c) {
      const size_t from = static_cast<size_t>(m) * num_core + c;
      if (core.gap[from] < 0) continue;  // not triangulated
      const int j = in.core_joints[c];
      xyz[j] = core.xyz[from];
      gap[j] = core.gap[from];
      geometric[j] = core.geometric[from];
      joint_score[j] = 1.0;
    }
    const ViewGeometry& ga = in.geometry[views.view_of[pair.a]];
    const ViewGeometry& gb = in.geometry[views.view_of[pair.b]];
    const Keypoint* ka = views.Pose(pair.a);
    const Keypoint* kb = views.Pose(pair.b);
    if (all_columns) {
      // All joints at once (the core joints again: the kernel gives the core step's numbers), then
      // the core joints' results over them.
      simd::TriangulatePair(ga.center.data(), simd::ColumnsOf(views.all_columns, pair.a), gb.center.data(),
                            simd::ColumnsOf(views.all_columns, pair.b), num_joints, xyz->data(), gap, joint_score);
      for (int c = 0; c < num_core; ++c) {
        const size_t from = static_cast<size_t>(m) * num_core + c;
        const int j = in.core_joints[c];
        if (core.gap[from] < 0) {  // not triangulated
          xyz[j].setZero();
          gap[j] = -1;
          joint_score[j] = 0;
          continue;
        }
        xyz[j] = core.xyz[from];
        gap[j] = core.gap[from];
        geometric[j] = core.geometric[from];
        joint_score[j] = 1.0;
      }
      continue;
    }
    for (int j = 0; j < num_joints; ++j) {
      if (joint_score[j] > 0 || geometric[j] >= 0) continue;  // core joint done above
      if (TriangulateJoint(ga, gb, ka[j], kb[j], options.method, &xyz[j], &gap[j])) joint_score[j] = 1.0;
    }
  }
  // Joint scores with the frame's kernels; the joint score gets the 2D confidence.
  int pruned = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    const ProposalViews pv = ViewsOf(views, in.geometry, *proposals, k);
    pruned += ScoreJointsOfProposal(in.kernel, views, pv, in.all_joints, in.limbs, in.limb_columns, nullptr,
                                    all_columns ? &views.all_columns : nullptr, proposals, k);
    if (!in.kernel.use_confidence) continue;
    double* score = proposals->score.data() + pv.base;
    if (all_columns) {  // the same products, from the contiguous columns
      const PosePair& pair = proposals->pairs[k];
      const size_t stride = static_cast<size_t>(views.all_columns.stride);
      const double* sa = views.all_columns.sqrt_score.data() + static_cast<size_t>(pair.a) * stride;
      const double* sb = views.all_columns.sqrt_score.data() + static_cast<size_t>(pair.b) * stride;
      for (int i = 0; i < num_joints; ++i) score[i] *= sa[i] * sb[i];
      continue;
    }
    for (int i = 0; i < num_joints; ++i)
      score[i] *= pv.ka[in.all_joints[i]].sqrt_score * pv.kb[in.all_joints[i]].sqrt_score;
  }
  stats->pruned_limbs += pruned;
  if (options.robust_views) {
    for (int g = 0; g < in.groups.size(); ++g)
      DropDisagreeingViewsOfGroup(options, in, in.groups.begin[g], in.groups.begin[g + 1], scratch, proposals);
  }
  return proposals->size();
}

}  // namespace rpt
