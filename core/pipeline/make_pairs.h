// SPDX-License-Identifier: MIT
// Step 1: every pair of poses from two different views (the association is not known yet).
#pragma once

#include <vector>

#include "core/pipeline/pipeline_types.h"

namespace rpt {

namespace steps {

// Appends all cross-view pairs (view(a) < view(b)) to `pairs` (cleared first). Returns the count.
int MakePairs(const PreparedViews& views, std::vector<PosePair>* pairs);

}  // namespace steps

}  // namespace rpt
