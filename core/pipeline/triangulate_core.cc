// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_core.h"

#include "core/pipeline/pair_triangulation.h"

namespace rpt {

int steps::TriangulateCore(const TriangulateOptions& options, const TriangulateCoreInput& in, Proposals* proposals) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const std::span<const int> joints = in.joints;
  const TriangulationMethod method = options.method;
  const int num_joints = static_cast<int>(joints.size());
  proposals->Clear(num_joints);
  for (const PosePair& pair : in.pairs) {
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
    if (valid < options.min_core_joints) proposals->Truncate(k);
  }
  return proposals->size();
}

}  // namespace rpt
