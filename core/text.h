// SPDX-License-Identifier: MIT
// Small string helpers for messages and listings.
#pragma once

#include <charconv>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace rpt {

// Appends `item` to `list`, separated by `separator` when `list` is not empty.
inline void AppendItem(std::string* list, std::string_view item, std::string_view separator = ", ") {
  if (!list->empty()) list->append(separator);
  list->append(item);
}

// `text` without leading and trailing blanks (spaces, tabs, line breaks).
inline std::string_view TrimBlanks(std::string_view text) {
  constexpr std::string_view kBlanks = " \t\r\n";
  const size_t first = text.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlanks) - first + 1);
}

// Numbers as text and back without the C library's locale: printf and strtod follow LC_NUMERIC,
// which a host program (Python's locale.setlocale, a GUI toolkit) may set to a decimal comma.

// `value` with `decimals` digits after the point: printf's "%.*f" in the C locale.
inline std::string FixedText(double value, int decimals) {
  char text[400];
  const auto result = std::to_chars(text, text + sizeof(text), value, std::chars_format::fixed, decimals);
  return result.ec == std::errc() ? std::string(text, result.ptr) : std::string("?");
}

// `value` with `significant` digits: printf's "%.*g" in the C locale.
inline std::string GeneralText(double value, int significant) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof(text), value, std::chars_format::general, significant);
  return result.ec == std::errc() ? std::string(text, result.ptr) : std::string("?");
}

// The whole of `text` as a number (decimal point, optional exponent, "inf"/"nan"); false when it
// is not one or lies beyond the double range.
inline bool ParseNumber(std::string_view text, double* value) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);  // from_chars takes no '+'
  const auto result = std::from_chars(text.data(), text.data() + text.size(), *value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

// A share (0.42) as a rounded percentage for messages ("42 %").
inline std::string PercentText(double share) { return FixedText(100.0 * share, 0) + " %"; }

// "a, b, c".
inline std::string Join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string out;
  for (const std::string& item : items) AppendItem(&out, item, separator);
  return out;
}

}  // namespace rpt
