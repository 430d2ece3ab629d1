// SPDX-License-Identifier: MIT
#include "core/pipeline/frame_size.h"

namespace rpt {

std::string FrameSizeProblem(std::span<const Poses2D> views, std::span<const Camera> cameras, int max_persons_per_view,
                             long long max_pairs_per_frame) {
  for (size_t v = 0; v < views.size(); ++v) {
    if (views[v].num_persons() <= max_persons_per_view) continue;
    return "view " + std::to_string(v) + " (camera '" + (v < cameras.size() ? cameras[v].name : std::string()) +
           "') has " + std::to_string(views[v].num_persons()) + " 2D poses, above triangulate.max_persons_per_view (" +
           std::to_string(max_persons_per_view) +
           "); raise it with --set triangulate.max_persons_per_view=N if this is a real scene";
  }
  // Every pose of a view pairs with every pose of each later view: the pair buffers grow with
  // (persons x views)^2.
  long long num_pairs = 0, poses_before = 0;
  for (const Poses2D& view : views) {
    num_pairs += poses_before * view.num_persons();
    poses_before += view.num_persons();
  }
  if (num_pairs <= max_pairs_per_frame) return {};
  return std::to_string(poses_before) + " 2D poses in " + std::to_string(views.size()) + " views make " +
         std::to_string(num_pairs) + " pairs across views, above triangulate.max_pairs_per_frame (" +
         std::to_string(max_pairs_per_frame) +
         "); raise it with --set triangulate.max_pairs_per_frame=N if this is a real scene";
}

}  // namespace rpt
