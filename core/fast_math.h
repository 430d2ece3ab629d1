// SPDX-License-Identifier: MIT
// Small deterministic math kernels for the hot path.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__GNUC__)
#define RPT_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RPT_ALWAYS_INLINE inline
#endif

namespace rpt {

// exp(-x) for x >= 0 with a relative error below 1e-8, without libm: exp(-x) = 2^t, t = -x log2(e),
// split into an integer power (exponent bits) and 2^f for |f| <= 0.5 (degree-7 Taylor series).
// Identical on every platform; used for scores, where this precision is far more than needed.
RPT_ALWAYS_INLINE double FastExpNeg(double x) {
  if (!(x < 700.0)) return 0.0;  // also NaN -> 0
  const double t = -x * 1.4426950408889634;
  const double n = std::nearbyint(t);  // f in [-0.5, 0.5]: the series below is accurate there
  const double f = t - n;
  // 2^f = exp(f ln2), |f ln2| <= 0.35: Taylor series truncated at degree 7 (error < 1e-8 relative).
  const double l = 0.6931471805599453 * f;
  const double p =
      1.0 + l * (1.0 + l * (0.5 + l * (1.0 / 6 + l * (1.0 / 24 + l * (1.0 / 120 + l * (1.0 / 720 + l * (1.0 / 5040)))))));
  const int64_t exponent = static_cast<int64_t>(n) + 1023;
  if (exponent <= 0) return 0.0;
  const uint64_t bits = static_cast<uint64_t>(exponent) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof(scale));
  return p * scale;
}

}  // namespace rpt
