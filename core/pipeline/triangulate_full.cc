// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_full.h"

#include "core/pipeline/pair_triangulation.h"

namespace rpt {

int steps::TriangulateFull(const PreparedViews& views, std::span<const ViewGeometry> geometry, const Proposals& core,
                           std::span<const int> members, std::span<const int> core_joints,
                           std::span<const int> all_joints, std::span<const ResolvedLimb> limbs,
                           TriangulationMethod method, const ScoreOptions& score, const NoiseScale& noise,
                           ScoreScratch* scratch, Proposals* proposals, FrameStats* stats) {
  const int num_joints = static_cast<int>(all_joints.size());
  proposals->Clear(num_joints);
  const int num_core = core.num_joints;
  for (int m : members) {
    const PosePair& pair = core.pairs[m];
    const int k = proposals->size();
    proposals->Add(pair);
    const size_t base = static_cast<size_t>(k) * num_joints;
    Eigen::Vector3d* xyz = proposals->xyz.data() + base;
    double* gap = proposals->gap.data() + base;
    double* joint_score = proposals->score.data() + base;
    double* geometric = proposals->geometric.data() + base;
    // Core joints: same pair, same rays -> same result; reuse it.
    for (int c = 0; c < num_core; ++c) {
      const size_t from = static_cast<size_t>(m) * num_core + c;
      if (core.gap[from] < 0) continue;  // not triangulated
      const int j = core_joints[c];
      xyz[j] = core.xyz[from];
      gap[j] = core.gap[from];
      geometric[j] = core.geometric[from];
      joint_score[j] = 1.0;
    }
    const ViewGeometry& ga = geometry[views.view_of[pair.a]];
    const ViewGeometry& gb = geometry[views.view_of[pair.b]];
    const Keypoint* ka = views.Pose(pair.a);
    const Keypoint* kb = views.Pose(pair.b);
    for (int j = 0; j < num_joints; ++j) {
      if (joint_score[j] > 0 || geometric[j] >= 0) continue;  // core joint done above
      if (TriangulateJoint(ga, gb, ka[j], kb[j], method, &xyz[j], &gap[j])) joint_score[j] = 1.0;
    }
  }
  stats->pruned_limbs += ScoreJoints(views, geometry, all_joints, limbs, score, noise, scratch, proposals);
  return proposals->size();
}

}  // namespace rpt
