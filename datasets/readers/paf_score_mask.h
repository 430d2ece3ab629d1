// SPDX-License-Identifier: MIT
// A bit per value: which values are >= a threshold. Step 1 of the PAF association
// (paf_limb_connections.h) marks with it which PAF scores of an image can make a connection, all
// limbs in one pass. A SIMD kernel (Highway), compiled for several instruction sets and chosen at
// run time like core's (core/pipeline/simd_kernels.h); a comparison per value, so every
// instruction set gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rpt::paf_internal {

// Sets bit e % 64 of bits[e / 64] to values[e] >= threshold for e in [0, n), and the bits from n
// to the end of the last word to 0; bits has (n + 63) / 64 words. Reads nothing past
// `readable_end` (>= values + n).
void MarkAtLeast(const double* values, size_t n, double threshold, const double* readable_end, std::uint64_t* bits);

}  // namespace rpt::paf_internal
