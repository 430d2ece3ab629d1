// SPDX-License-Identifier: MIT
#include "core/pipeline/prefilter_pairs.h"

#include <cmath>

namespace rpt {

int PrefilterPairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                   std::span<const int> core_joints, const PreviousPersons& previous,
                   const PrefilterOptions& options, std::vector<int>* match, std::vector<PosePair>* pairs) {
  const int num_previous = previous.size();
  if (!options.enabled || num_previous == 0) return static_cast<int>(pairs->size());

  const int num_core = static_cast<int>(core_joints.size());
  match->assign(views.num_poses(), -1);
  for (int g = 0; g < views.num_poses(); ++g) {
    const ViewGeometry& geo = geometry[views.view_of[g]];
    const Keypoint* kps = views.Pose(g);
    const double max_distance = options.max_distance_rel * views.bbox_diag[g];
    double best = max_distance;
    for (int q = 0; q < num_previous; ++q) {
      double sum = 0;
      int n = 0;
      for (int c = 0; c < num_core; ++c) {
        const Keypoint& kp = kps[core_joints[c]];
        const size_t idx = static_cast<size_t>(q) * num_core + c;
        if (kp.score <= 0 || previous.score[idx] <= 0) continue;
        const Eigen::Vector3d h = geo.P * previous.xyz[idx].homogeneous();
        if (h.z() <= 0) continue;
        sum += std::hypot(h.x() / h.z() - kp.u, h.y() / h.z() - kp.v);
        ++n;
      }
      if (n < 3) continue;
      const double mean = sum / n;
      if (mean < best) {
        best = mean;
        (*match)[g] = q;
      }
    }
  }

  int kept = 0;
  for (const PosePair& pair : *pairs) {
    if ((*match)[pair.a] == (*match)[pair.b]) (*pairs)[kept++] = pair;
  }
  pairs->resize(kept);
  return kept;
}

}  // namespace rpt
