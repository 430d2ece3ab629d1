// SPDX-License-Identifier: MIT
#include "core/pipeline/make_pairs.h"

namespace rpt {

int steps::MakePairs(const PreparedViews& views, std::vector<PosePair>* pairs) {
  pairs->clear();
  const int num_views = static_cast<int>(views.view_begin.size()) - 1;
  for (int va = 0; va < num_views; ++va) {
    for (int vb = va + 1; vb < num_views; ++vb) {
      for (int a = views.view_begin[va]; a < views.view_begin[va + 1]; ++a) {
        for (int b = views.view_begin[vb]; b < views.view_begin[vb + 1]; ++b) {
          pairs->push_back(PosePair{a, b});
        }
      }
    }
  }
  return static_cast<int>(pairs->size());
}

}  // namespace rpt
