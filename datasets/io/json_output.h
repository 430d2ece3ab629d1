// SPDX-License-Identifier: MIT
// JSON text for output files. nlohmann writes every string escaped (a joint name with a quote
// stays valid JSON); bytes that are not valid UTF-8 (e.g. a frame id read from a binary cache)
// are written as U+FFFD and counted instead of throwing after other outputs were written.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.h"
#include "core/utf8.h"

namespace rpt::io {

namespace json_output_internal {
template <class Json>
int CountInvalidStrings(const Json& value) {
  if (value.is_string()) return IsValidUtf8(value.template get_ref<const std::string&>()) ? 0 : 1;
  int count = 0;
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      count += (IsValidUtf8(it.key()) ? 0 : 1) + CountInvalidStrings(it.value());
    }
  } else if (value.is_array()) {
    for (const Json& item : value) count += CountInvalidStrings(item);
  }
  return count;
}
}  // namespace json_output_internal

// `value.dump(indent)`, with invalid UTF-8 replaced by U+FFFD; adds the number of strings (keys
// and values) that needed it to `*replaced` (when given).
template <class Json>
std::string DumpJson(const Json& value, int indent = -1, int* replaced = nullptr) {
  try {
    return value.dump(indent);
  } catch (const nlohmann::json::type_error&) {  // 316: invalid UTF-8
    if (replaced != nullptr) *replaced += json_output_internal::CountInvalidStrings(value);
    return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
  }
}

// `text` with bytes that are not valid UTF-8 replaced by U+FFFD, for other text formats (XML);
// adds 1 to `*replaced` (when given) when it had to.
inline std::string ValidUtf8(const std::string& text, int* replaced = nullptr) {
  if (IsValidUtf8(text)) return text;
  if (replaced != nullptr) ++*replaced;
  return nlohmann::json::parse(nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))
      .get<std::string>();
}

// Throws InputError "<source>: cannot write <where>: value is not finite" for NaN and infinities,
// which JSON cannot hold.
inline void CheckFiniteToWrite(double value, const std::string& source, const std::string& where) {
  if (!std::isfinite(value)) throw InputError(source + ": cannot write " + where + ": value is not finite");
}

}  // namespace rpt::io
