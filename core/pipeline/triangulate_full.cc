// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_full.h"

#include "core/pipeline/pair_triangulation.h"

namespace rpt {

int steps::TriangulateFull(const TriangulateOptions& options, const TriangulateFullInput& in, Proposals* proposals,
                           FrameStats* stats) {
  const PreparedViews& views = in.views;
  const Proposals& core = in.core;
  const int num_joints = static_cast<int>(in.all_joints.size());
  proposals->Clear(num_joints);
  const int num_core = core.num_joints;
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
    for (int c = 0; c < num_core; ++c) {
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
    for (int j = 0; j < num_joints; ++j) {
      if (joint_score[j] > 0 || geometric[j] >= 0) continue;  // core joint done above
      if (TriangulateJoint(ga, gb, ka[j], kb[j], options.method, &xyz[j], &gap[j])) joint_score[j] = 1.0;
    }
  }
  // Joint scores with the frame's kernels; the joint score gets the 2D confidence.
  int pruned = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    const ProposalViews pv = ViewsOf(views, in.geometry, *proposals, k);
    pruned += ScoreJointsOfProposal(in.kernel, views, pv, in.all_joints, in.limbs, nullptr, proposals, k);
    if (!in.kernel.use_confidence) continue;
    double* score = proposals->score.data() + pv.base;
    for (int i = 0; i < num_joints; ++i)
      score[i] *= pv.ka[in.all_joints[i]].sqrt_score * pv.kb[in.all_joints[i]].sqrt_score;
  }
  stats->pruned_limbs += pruned;
  return proposals->size();
}

}  // namespace rpt
