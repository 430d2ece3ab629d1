// SPDX-License-Identifier: MIT
// Step 1: every pair of poses from two different views (the association is not known yet).
#pragma once

#include <vector>

#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Whether make_pairs writes the pairs out. The pre-filter, when it acts (PrefilterActs), builds
// the pairs it keeps from its classification of the poses and never reads the full list: with 31
// cameras and 8 people that list has 30,000 pairs of which a few thousand are kept.
enum class PairListing { kAll, kCountOnly };

namespace steps {

// The number of cross-view pairs (view(a) < view(b)); with PairListing::kAll they are written to
// `pairs` (cleared first) by view pair, then pose a, then pose b; with kCountOnly `pairs` is
// cleared and left empty.
int MakePairs(const PreparedViews& views, PairListing listing, std::vector<PosePair>* pairs);

}  // namespace steps

}  // namespace rpt
