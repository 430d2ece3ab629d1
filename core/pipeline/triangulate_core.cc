// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulate_core.h"

#include <algorithm>

#include "core/pipeline/pair_triangulation.h"
#include "core/pipeline/simd_kernels.h"

namespace rpt {

int steps::TriangulateCore(const TriangulateOptions& options, const TriangulateCoreInput& in, Proposals* proposals) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const std::span<const int> joints = in.joints;
  const TriangulationMethod method = options.method;
  const int num_joints = static_cast<int>(joints.size());
  proposals->Clear(num_joints);
  // The SIMD kernel reads the core joints' columns of the undistort step; other joint subsets (and
  // the DLT's refinement) take the scalar path.
  const bool columns = simd::Enabled() && std::equal(joints.begin(), joints.end(), views.core_joints.begin(), views.core_joints.end());
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
    if (columns) {
      simd::TriangulatePair(ga.center.data(), simd::ColumnsOf(views.core_columns, pair.a), gb.center.data(),
                            simd::ColumnsOf(views.core_columns, pair.b), num_joints, xyz->data(), gap, score);
      for (int i = 0; i < num_joints; ++i) {
        if (score[i] <= 0) continue;
        if (method == TriangulationMethod::kDlt &&
            !TriangulateDlt(ga.Rt, Eigen::Vector2d(ka[joints[i]].x, ka[joints[i]].y), gb.Rt,
                            Eigen::Vector2d(kb[joints[i]].x, kb[joints[i]].y), &xyz[i])) {
          score[i] = 0;  // the ray gap stays: as TriangulateJoint leaves it
          continue;
        }
        ++valid;
      }
      if (valid < options.min_core_joints) proposals->Truncate(k);
      continue;
    }
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
