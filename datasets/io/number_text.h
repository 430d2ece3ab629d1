// SPDX-License-Identifier: MIT
// The one parser of numbers written as text (file tokens, file-name digits, JSON keys, --param
// values): the whole text must be the number, in C locale, with an optional leading '+'.
// The Parse* functions return false on anything else (empty text, trailing characters, a value
// outside the type's range); callers phrase the error with their own place and range ("gt.txt:17:
// token 9: identity: '1.5' is not an integer >= 0", IntegerRangeText).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace rpt::io {

template <class Int>
  requires std::is_integral_v<Int>
bool ParseInteger(std::string_view text, Int* out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  if (first == last || (first != text.data() && *first == '-')) return false;  // "+-1" is not a number
  Int value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last) return false;
  *out = value;
  return true;
}

// Any double, including "inf" and "nan" (as from_chars spells them).
bool ParseNumber(std::string_view text, double* out);
// A finite double.
bool ParseFiniteNumber(std::string_view text, double* out);

// "in [a, b]" or ">= a" (b = the int64 maximum), for messages about integer ranges.
std::string IntegerRangeText(std::int64_t min_value, std::int64_t max_value);

}  // namespace rpt::io
