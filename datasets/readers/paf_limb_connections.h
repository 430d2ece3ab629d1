// SPDX-License-Identifier: MIT
// Step 1 of the PAF association (openpose_paf_association.h) for all limbs of an image: the keys
// (paf_connection_keys.h) of each limb's possible connections, and of those the ones the limb's
// greedy one-to-one matching keeps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "datasets/readers/paf_candidates.h"
#include "datasets/readers/paf_connection_keys.h"

namespace rpt::paf_internal {

// Writes to keys[0, n) the kept connections of every limb, limb after limb (within a limb in
// (a, b) order when all its possible connections are kept, else by decreasing score), and returns
// n. A possible connection has both candidate scores > 0 and a PAF score >= min_score (> 0).
// `keys` and `above_min` (scratch) only grow (allocation-free once warm); `used` has a zero flag
// per slot, and has it again on return.
size_t KeptLimbConnections(const PafSkeleton& skeleton, const PackedPafCandidates& candidates, PafConnectionKeys coding,
                           double min_score, std::vector<std::uint64_t>* keys, std::vector<std::uint64_t>* above_min,
                           unsigned char* used);

}  // namespace rpt::paf_internal
