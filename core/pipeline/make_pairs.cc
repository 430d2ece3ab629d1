// SPDX-License-Identifier: MIT
#include "core/pipeline/make_pairs.h"

namespace rpt {

int steps::MakePairs(const PreparedViews& views, PairListing listing, std::vector<PosePair>* pairs) {
  pairs->clear();
  const int num_views = static_cast<int>(views.view_begin.size()) - 1;
  int count = 0, poses_before = 0;
  for (int v = 0; v < num_views; ++v) {
    const int poses = views.view_begin[v + 1] - views.view_begin[v];
    count += poses_before * poses;
    poses_before += poses;
  }
  if (listing == PairListing::kCountOnly) return count;
  for (int va = 0; va < num_views; ++va) {
    for (int vb = va + 1; vb < num_views; ++vb) {
      for (int a = views.view_begin[va]; a < views.view_begin[va + 1]; ++a) {
        for (int b = views.view_begin[vb]; b < views.view_begin[vb + 1]; ++b) {
          pairs->push_back(PosePair{a, b});
        }
      }
    }
  }
  return count;
}

}  // namespace rpt
