// SPDX-License-Identifier: MIT
// The greedy PAF association as it was before PafAssociator (datasets/readers/
// openpose_paf_association.h): the same rules, a vector allocated per limb and per person. The
// reference the fast one must equal, and the "before" of its benchmark.
#pragma once

#include <vector>

#include "datasets/readers/openpose_paf_association.h"

namespace rpt::bench {

std::vector<PafPerson> AssociatePafsBaseline(const PafSkeleton& skeleton, const PafCandidates& candidates,
                                             const PafAssociationOptions& options);

}  // namespace rpt::bench
