// SPDX-License-Identifier: MIT
// Small string helpers for messages and listings.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
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

// A share (0.42) as a rounded percentage for messages ("42 %").
inline std::string PercentText(double share) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.0f %%", 100.0 * share);
  return text;
}

// "a, b, c".
inline std::string Join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string out;
  for (const std::string& item : items) AppendItem(&out, item, separator);
  return out;
}

}  // namespace rpt
