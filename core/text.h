// SPDX-License-Identifier: MIT
// Small string helpers for messages and listings.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rpt {

// Appends `item` to `list`, separated by `separator` when `list` is not empty.
inline void AppendItem(std::string* list, std::string_view item, std::string_view separator = ", ") {
  if (!list->empty()) list->append(separator);
  list->append(item);
}

// "a, b, c".
inline std::string Join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string out;
  for (const std::string& item : items) AppendItem(&out, item, separator);
  return out;
}

}  // namespace rpt
