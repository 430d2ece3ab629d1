// SPDX-License-Identifier: MIT
// AppendFixedDecimal writes exactly what std::to_chars(value, fixed, decimals) writes: random
// values of every size and sign, values a hair from a rounding tie, exact binary ties, zeros of
// both signs, and values past the fast path's range.
#include "engine/outputs/fixed_decimal.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace rpt::engine {
namespace {

std::string ToChars(double value, int decimals) {
  char text[400];
  const auto end = std::to_chars(text, text + sizeof(text), value, std::chars_format::fixed, decimals).ptr;
  return std::string(text, end);
}

std::string Fast(double value, int decimals) {
  std::string out = "x";  // appended to what is there
  AppendFixedDecimal(value, decimals, &out);
  return out.substr(1);
}

TEST(FixedDecimal, WritesWhatToCharsWrites) {
  std::vector<double> values = {0.0,           -0.0,         1e-9,
                                -1e-9,         0.5,          -0.5,
                                2.5,           0.25,         0.125,
                                0.0625,        0.03125,      1.0000005,
                                4294.967295,   4294.967296,  4294.967297,
                                4294967295.5,  4294967296.5, 1e15,
                                -1e15,         1e300,        std::numeric_limits<double>::denorm_min(),
                                123456.7890125};
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-12, 12);
  for (int i = 0; i < 200000; ++i) values.push_back(unit(random) * std::pow(10.0, exponent(random)));
  // A hair from a tie: (k + 0.5) / 10^d and its neighbours, for every d.
  std::uniform_int_distribution<long> integer(0, 100000000);
  for (int d = 0; d <= 6; ++d) {
    for (int i = 0; i < 20000; ++i) {
      const double tie = (static_cast<double>(integer(random)) + 0.5) / std::pow(10.0, d);
      for (const double v : {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e300)}) {
        values.push_back(v);
        values.push_back(-v);
      }
    }
  }
  long checked = 0;
  for (const double v : values) {
    for (int d = 0; d <= 8; ++d) {
      ASSERT_EQ(Fast(v, d), ToChars(v, d)) << "value " << ToChars(v, 20) << ", " << d << " decimals";
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000000);
}

TEST(FixedDecimal, HandWorkedValues) {
  EXPECT_EQ(Fast(1.5, 0), "2");
  EXPECT_EQ(Fast(2.5, 0), "2") << "an exact tie: to even";
  EXPECT_EQ(Fast(-0.0, 6), "-0.000000");
  EXPECT_EQ(Fast(-1e-9, 6), "-0.000000");
  EXPECT_EQ(Fast(12.3456789, 6), "12.345679");
  EXPECT_EQ(Fast(0.05, 4), "0.0500");
  EXPECT_EQ(Fast(-3.14159, 2), "-3.14");
  EXPECT_EQ(Fast(999.9999996, 6), "1000.000000");
}

}  // namespace
}  // namespace rpt::engine
