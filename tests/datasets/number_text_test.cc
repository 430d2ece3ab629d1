// SPDX-License-Identifier: MIT
// The one number parser of datasets/ (datasets/io/number_text.h).
#include "datasets/io/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace rpt::io {
namespace {

TEST(NumberText, IntegersAreTheWholeText) {
  int value = 0;
  EXPECT_TRUE(ParseInteger("17", &value));
  EXPECT_EQ(value, 17);
  EXPECT_TRUE(ParseInteger("+5", &value));
  EXPECT_EQ(value, 5);
  EXPECT_TRUE(ParseInteger("-3", &value));
  EXPECT_EQ(value, -3);
  value = 99;
  for (const char* bad : {"", "+", "-", "1.5", "12a", " 1", "3000000000", "+-1"}) {
    EXPECT_FALSE(ParseInteger(bad, &value)) << bad;
  }
  EXPECT_EQ(value, 99);  // untouched on failure
  std::uint64_t seed = 0;
  EXPECT_TRUE(ParseInteger("18446744073709551615", &seed));
  EXPECT_FALSE(ParseInteger("-1", &seed));
}

TEST(NumberText, NumbersAndFiniteNumbers) {
  double value = 0;
  EXPECT_TRUE(ParseNumber("+1.5e3", &value));
  EXPECT_DOUBLE_EQ(value, 1500);
  EXPECT_TRUE(ParseNumber("inf", &value));
  EXPECT_TRUE(std::isinf(value));
  EXPECT_FALSE(ParseFiniteNumber("inf", &value));
  EXPECT_FALSE(ParseFiniteNumber("nan", &value));
  EXPECT_FALSE(ParseNumber("1e999", &value));  // out of range
  EXPECT_FALSE(ParseNumber("1,5", &value));
  EXPECT_FALSE(ParseNumber("", &value));
  EXPECT_FALSE(ParseNumber("+-2", &value));
  EXPECT_EQ(IntegerRangeText(0, 25), "in [0, 25]");
  EXPECT_EQ(IntegerRangeText(2, INT64_MAX), ">= 2");
}

}  // namespace
}  // namespace rpt::io
