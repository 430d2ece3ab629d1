// SPDX-License-Identifier: MIT
#include "datasets/io/number_text.h"

namespace rpt::io {
bool ParseNumber(std::string_view text, double* out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  if (first == last || (first != text.data() && *first == '-')) return false;  // "+-1" is not a number
  double value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last) return false;
  *out = value;
  return true;
}

bool ParseFiniteNumber(std::string_view text, double* out) {
  double value = 0;
  if (!ParseNumber(text, &value) || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

std::string IntegerRangeText(std::int64_t min_value, std::int64_t max_value) {
  return max_value == std::numeric_limits<std::int64_t>::max()
             ? ">= " + std::to_string(min_value)
             : "in [" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]";
}

}  // namespace rpt::io
