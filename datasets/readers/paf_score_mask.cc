// SPDX-License-Identifier: MIT
// The kernel of paf_score_mask.h, written once with Highway and compiled for each instruction set
// below (foreach_target.h re-includes this file per target); HWY_DYNAMIC_DISPATCH picks the best
// one the CPU supports, as for core's kernels (core/pipeline/simd_kernels.cc).

// Targets: the portable fallback (EMU128), SSE4, AVX2 and AVX-512 (AVX3), as in core.
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SSSE3 | HWY_AVX3_DL)
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "datasets/readers/paf_score_mask.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "datasets/readers/paf_score_mask.h"

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace rpt::paf_internal {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void MarkAtLeastImpl(const double* values, size_t n, double threshold, const double* readable_end,
                     std::uint64_t* bits) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d);  // 1 to 8 here: divides 64
  const auto threshold_v = hn::Set(d, threshold);
  for (size_t first = 0; first < n; first += 64) {
    std::uint64_t word = 0;
    for (size_t lane0 = 0; lane0 < 64 && first + lane0 < n; lane0 += lanes) {
      const double* p = values + first + lane0;
      hn::Vec<decltype(d)> v;
      if (p + lanes <= readable_end) {
        v = hn::LoadU(d, p);
      } else {  // the last values: through a copy, so nothing past readable_end is read
        HWY_ALIGN double copy[HWY_MAX_BYTES / sizeof(double)] = {};
        std::copy(p, values + n, copy);
        v = hn::Load(d, copy);
      }
      std::uint8_t mask_bytes[8] = {};
      hn::StoreMaskBits(d, hn::Ge(v, threshold_v), mask_bytes);
      std::uint64_t mask = 0;
      std::memcpy(&mask, mask_bytes, sizeof mask);
      word |= mask << lane0;
    }
    const size_t valid = std::min<size_t>(64, n - first);
    bits[first / 64] = valid == 64 ? word : word & ((std::uint64_t{1} << valid) - 1);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace rpt::paf_internal
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rpt::paf_internal {

HWY_EXPORT(MarkAtLeastImpl);

void MarkAtLeast(const double* values, size_t n, double threshold, const double* readable_end, std::uint64_t* bits) {
  HWY_DYNAMIC_DISPATCH(MarkAtLeastImpl)(values, n, threshold, readable_end, bits);
}

}  // namespace rpt::paf_internal
#endif  // HWY_ONCE
