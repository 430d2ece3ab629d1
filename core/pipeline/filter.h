// SPDX-License-Identifier: MIT
// Step 8: drop pairs/proposals whose pair score is below min_match_score.
#pragma once

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

namespace steps {

// Compacts `proposals` to those with pair_score >= min_match_score. Returns the number kept.
int Filter(const FilterOptions& options, Proposals* proposals);

}  // namespace steps

}  // namespace rpt
