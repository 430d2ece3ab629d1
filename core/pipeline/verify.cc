// SPDX-License-Identifier: MIT
#include "core/pipeline/verify.h"

#include <algorithm>

namespace rpt {

int steps::Verify(const VerifyOptions& options, const VerifyInput& in, VerifyScratch* scratch, Poses3D* persons,
                  FrameStats* stats) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const Proposals& proposals = in.proposals;
  const Groups& groups = in.groups;
  if (!options.enabled || persons->num_persons() == 0) return persons->num_persons();
  const int num_views = static_cast<int>(geometry.size());
  const bool by_group = groups.size() == persons->num_persons();
  bool have_boxes = false;  // pose boxes are computed when first needed
  int kept = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    const auto person = persons->Person(p);
    int support = 0, empty = 0;
    scratch->own_view.assign(num_views, 0);
    if (by_group) {
      for (int m = groups.begin[p]; m < groups.begin[p + 1]; ++m) {
        scratch->own_view[views.view_of[proposals.pairs[m].a]] = 1;
        scratch->own_view[views.view_of[proposals.pairs[m].b]] = 1;
      }
      for (int v = 0; v < num_views; ++v) support += scratch->own_view[v];
    }
    // Empty views can only come from the other views: skip persons that cannot be dropped.
    const int others = num_views - support;
    const bool can_drop = others >= options.min_empty_views && others > support;
    for (int v = 0; can_drop && v < num_views; ++v) {
      if (scratch->own_view[v]) continue;
      if (!have_boxes) {
        PoseBoxes(views, &scratch->verdict.boxes);
        have_boxes = true;
      }
      const ViewVerdict verdict = JudgeView(views, geometry[v], v, in.core_joints, person, in.kernel.scale_m,
                                            options.min_inside_fraction, &scratch->verdict, nullptr);
      support += verdict == ViewVerdict::kSupport;
      empty += verdict == ViewVerdict::kEmpty;
    }
    if (empty >= options.min_empty_views && empty > support) {
      ++stats->unsupported_persons;
      continue;
    }
    if (kept != p) persons->MovePerson(p, kept);
    ++kept;
  }
  persons->Truncate(kept);
  return kept;
}

}  // namespace rpt
