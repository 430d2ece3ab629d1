// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_pairs.h"

#include "core/triangulation.h"

namespace rpt {

namespace {

// Triangulates joint `joint` of poses a, b; false when it cannot be triangulated.
RPT_ALWAYS_INLINE bool TriangulateJoint(const ViewGeometry& ga, const ViewGeometry& gb, const Keypoint& a, const Keypoint& b,
                             TriangulationMethod method, Eigen::Vector3d* point, double* gap) {
  if (a.score <= 0 || b.score <= 0) return false;
  if (!TriangulateMidpoint(ga.center, a.ray, gb.center, b.ray, point, gap)) return false;
  return method != TriangulationMethod::kDlt ||
         TriangulateDlt(ga.Rt, Eigen::Vector2d(a.x, a.y), gb.Rt, Eigen::Vector2d(b.x, b.y), point);
}

}  // namespace

int TriangulatePairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                     std::span<const PosePair> pairs, std::span<const int> joints, TriangulationMethod method,
                     int min_joints, Proposals* proposals) {
  const int num_joints = static_cast<int>(joints.size());
  proposals->Clear(num_joints);
  for (const PosePair& pair : pairs) {
    const ViewGeometry& ga = geometry[views.view_of[pair.a]];
    const ViewGeometry& gb = geometry[views.view_of[pair.b]];
    const Keypoint* ka = views.Pose(pair.a);
    const Keypoint* kb = views.Pose(pair.b);
    const int k = proposals->size();
    proposals->Add(pair);
    Eigen::Vector3d* xyz = proposals->xyz.data() + static_cast<size_t>(k) * num_joints;
    double* gap = proposals->gap.data() + static_cast<size_t>(k) * num_joints;
    double* score = proposals->score.data() + static_cast<size_t>(k) * num_joints;
    int valid = 0;
    for (int i = 0; i < num_joints; ++i) {
      if (!TriangulateJoint(ga, gb, ka[joints[i]], kb[joints[i]], method, &xyz[i], &gap[i])) continue;
      score[i] = 1.0;
      ++valid;
    }
    if (valid < min_joints) proposals->Truncate(k);
  }
  return proposals->size();
}

int TriangulateMembers(const PreparedViews& views, std::span<const ViewGeometry> geometry, const Proposals& core,
                       std::span<const int> members, std::span<const int> core_joints, int num_joints,
                       TriangulationMethod method, Proposals* proposals) {
  proposals->Clear(num_joints);
  const int num_core = core.num_joints;
  for (int m : members) {
    const PosePair& pair = core.pairs[m];
    const int k = proposals->size();
    proposals->Add(pair);
    const size_t base = static_cast<size_t>(k) * num_joints;
    Eigen::Vector3d* xyz = proposals->xyz.data() + base;
    double* gap = proposals->gap.data() + base;
    double* score = proposals->score.data() + base;
    double* geometric = proposals->geometric.data() + base;
    // Core joints: same pair, same rays -> same result; reuse it.
    for (int c = 0; c < num_core; ++c) {
      const size_t from = static_cast<size_t>(m) * num_core + c;
      if (core.gap[from] < 0) continue;  // not triangulated
      const int j = core_joints[c];
      xyz[j] = core.xyz[from];
      gap[j] = core.gap[from];
      geometric[j] = core.geometric[from];
      score[j] = 1.0;
    }
    const ViewGeometry& ga = geometry[views.view_of[pair.a]];
    const ViewGeometry& gb = geometry[views.view_of[pair.b]];
    const Keypoint* ka = views.Pose(pair.a);
    const Keypoint* kb = views.Pose(pair.b);
    for (int j = 0; j < num_joints; ++j) {
      if (score[j] > 0 || geometric[j] >= 0) continue;  // core joint done above
      if (TriangulateJoint(ga, gb, ka[j], kb[j], method, &xyz[j], &gap[j])) score[j] = 1.0;
    }
  }
  return proposals->size();
}

}  // namespace rpt
