// SPDX-License-Identifier: MIT
// LogHistogram: exact quantiles for few values, within a bin's 0.48 % for many, bounded memory.
#include "metrics/log_histogram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "metrics/timing.h"

namespace rpt::metrics {
namespace {

// Deterministic values spread over three decades (log-uniform in [5, 5000)).
std::vector<double> Spread(int n, std::uint64_t seed) {
  std::vector<double> values;
  for (int i = 0; i < n; ++i) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    const double unit = static_cast<double>(seed >> 11) * 0x1.0p-53;
    values.push_back(5.0 * std::pow(10.0, 3.0 * unit));
  }
  return values;
}

double ExactQuantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(q * values.size()))];
}

TEST(LogHistogram, UpToSixtyFourValuesQuantilesAreExact) {
  LogHistogram histogram(0.01, 10);
  const std::vector<double> values = Spread(64, 1);
  for (const double v : values) histogram.Add(v);
  EXPECT_EQ(histogram.Median(), Median(values));
  EXPECT_EQ(histogram.Quantile(0.9), ExactQuantile(values, 0.9));
  EXPECT_EQ(LogHistogram(0.01, 10).Median(), 0.0);
  EXPECT_EQ(LogHistogram(0.01, 10).Quantile(0.9), 0.0);
}

TEST(LogHistogram, ManyValuesWithinTheRelativeBinWidth) {
  for (const int n : {65, 1000, 100001}) {
    LogHistogram histogram(0.01, 10);
    const std::vector<double> values = Spread(n, 7);
    for (const double v : values) histogram.Add(v);
    const double width = std::pow(10.0, 1.0 / LogHistogram::kBinsPerDecade) - 1.0;  // 0.48 %
    EXPECT_LT(width, 0.005);
    EXPECT_NEAR(histogram.Median(), Median(values), width * Median(values)) << n;
    for (const double q : {0.1, 0.5, 0.9, 0.99}) {
      const double exact = ExactQuantile(values, q);
      EXPECT_NEAR(histogram.Quantile(q), exact, width * exact) << n << " values, q " << q;
    }
    EXPECT_EQ(histogram.count(), n);
  }
}

TEST(LogHistogram, ConstantValuesZerosAndOutOfRange) {
  LogHistogram constant(0.01, 10), zeros(0.01, 10), huge(0.01, 10);
  for (int i = 0; i < 1000; ++i) {
    constant.Add(123.456);
    zeros.Add(0.0);
    huge.Add(i < 600 ? 1e12 : 1.0);
  }
  EXPECT_EQ(constant.Median(), 123.456) << "an estimate never leaves [smallest, largest]";
  EXPECT_EQ(zeros.Median(), 0.0) << "values below the range count as the smallest";
  EXPECT_EQ(zeros.Quantile(0.9), 0.0);
  EXPECT_EQ(huge.Median(), 1e12) << "values above the range count as the largest";
  EXPECT_NEAR(huge.Quantile(0.3), 1.0, 0.005);
}

TEST(LogHistogram, MergeEqualsAddingEverything) {
  for (const int split : {10, 50, 600}) {
    const std::vector<double> values = Spread(1000, 3);
    LogHistogram all(0.01, 10), first(0.01, 10), second(0.01, 10);
    for (int i = 0; i < static_cast<int>(values.size()); ++i) {
      all.Add(values[i]);
      (i < split ? first : second).Add(values[i]);
    }
    first.Merge(second);
    EXPECT_EQ(first.count(), all.count());
    EXPECT_EQ(first.Median(), all.Median()) << split;
    EXPECT_EQ(first.Quantile(0.9), all.Quantile(0.9)) << split;
  }
  // Few values merged stay exact.
  LogHistogram a(0.01, 10), b(0.01, 10);
  a.Add(10);
  a.Add(30);
  b.Add(20);
  a.Merge(b);
  EXPECT_EQ(a.Median(), 20.0);
}

}  // namespace
}  // namespace rpt::metrics
