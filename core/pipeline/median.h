// SPDX-License-Identifier: MIT
// Medians of small sets of doubles, shared by the pipeline steps (internal header).
#pragma once

#include <algorithm>
#include <limits>

namespace rpt {

// Median of values[0..n) (may reorder them): the mean of the two middle values for an even
// count; +inf for none. Sets of a dozen values (a pair's core joints) are ranked without branches
// (nth_element's mispredicted branches cost several times more); larger sets use nth_element.
inline double Median(double* values, int n) {
  if (n <= 0) return std::numeric_limits<double>::infinity();
  if (n > 32) {
    double* mid = values + n / 2;
    std::nth_element(values, mid, values + n);
    if (n % 2 == 1) return *mid;
    return 0.5 * (*mid + *std::max_element(values, mid));
  }
  // Rank = values below, plus equal values earlier in the list: ranks are 0..n-1, each once.
  double lower = 0, upper = 0;  // the values of rank (n - 1) / 2 and n / 2
  for (int i = 0; i < n; ++i) {
    int rank = 0;
    for (int j = 0; j < n; ++j) rank += (values[j] < values[i]) | ((values[j] == values[i]) & (j < i));
    lower = rank == (n - 1) / 2 ? values[i] : lower;
    upper = rank == n / 2 ? values[i] : upper;
  }
  return 0.5 * (lower + upper);
}

// The upper median of values[0..n) (may reorder them): the value of rank n / 2, one of the
// values itself for every count; +inf for none.
inline double UpperMedian(double* values, int n) {
  if (n <= 0) return std::numeric_limits<double>::infinity();
  std::nth_element(values, values + n / 2, values + n);
  return values[n / 2];
}

}  // namespace rpt
