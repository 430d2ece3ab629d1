// SPDX-License-Identifier: MIT
// Medians of small sets of doubles, shared by the pipeline steps (internal header).
#pragma once

#include <algorithm>
#include <limits>

#include "core/pipeline/simd_kernels.h"

namespace rpt {

// Median of values[0..n), n in [1, 32], ranked without branches: rank = values below, plus equal
// values earlier in the list (0..n-1, each once, for values that are not NaN); the value of rank
// (n - 1) / 2 and of rank n / 2, the last one where several share a rank (NaN has rank 0), else 0.
// The scalar reference of simd::RankMedian, which computes the same ranks lane-parallel.
inline double RankMedianScalar(const double* values, int n) {
  double lower = 0, upper = 0;  // the values of rank (n - 1) / 2 and n / 2
  for (int i = 0; i < n; ++i) {
    int rank = 0;
    for (int j = 0; j < n; ++j) rank += (values[j] < values[i]) | ((values[j] == values[i]) & (j < i));
    lower = rank == (n - 1) / 2 ? values[i] : lower;
    upper = rank == n / 2 ? values[i] : upper;
  }
  return 0.5 * (lower + upper);
}

// Median of values[0..n) (may reorder them): the mean of the two middle values for an even
// count; +inf for none. Sets of up to 32 values (a pair's core joints) are ranked without
// branches (nth_element's mispredicted branches cost several times more), by the SIMD kernel
// unless it is switched off; larger sets use nth_element.
inline double Median(double* values, int n) {
  if (n <= 0) return std::numeric_limits<double>::infinity();
  if (n > simd::kRankMedianMax) {
    double* mid = values + n / 2;
    std::nth_element(values, mid, values + n);
    if (n % 2 == 1) return *mid;
    return 0.5 * (*mid + *std::max_element(values, mid));
  }
  return simd::Enabled() ? simd::RankMedian(values, n) : RankMedianScalar(values, n);
}

// The upper median of values[0..n) (may reorder them): the value of rank n / 2, one of the
// values itself for every count; +inf for none.
inline double UpperMedian(double* values, int n) {
  if (n <= 0) return std::numeric_limits<double>::infinity();
  std::nth_element(values, values + n / 2, values + n);
  return values[n / 2];
}

}  // namespace rpt
