// SPDX-License-Identifier: MIT
#include "core/pipeline/filter_proposals.h"

namespace rpt {

int FilterProposals(const FilterOptions& options, Proposals* proposals) {
  int kept = 0;
  for (int k = 0; k < proposals->size(); ++k) {
    if (proposals->pair_score[k] >= options.min_match_score) proposals->Move(k, kept++);
  }
  proposals->Truncate(kept);
  return kept;
}

}  // namespace rpt
