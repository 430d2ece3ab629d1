// SPDX-License-Identifier: MIT
#include "core/pipeline/filter.h"

namespace rpt {

int steps::Filter(const FilterOptions& options, Proposals* proposals) {
  int kept = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    if (proposals->pair_score[k] >= options.min_match_score) proposals->Move(k, kept++);
  }
  proposals->Truncate(kept);
  return kept;
}

}  // namespace rpt
