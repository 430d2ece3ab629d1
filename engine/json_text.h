// SPDX-License-Identifier: MIT
// A JSON value as the text `--set` / `--param` accept (strings unquoted, numbers and booleans as written).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rpt::engine {

inline std::string JsonValueText(const nlohmann::json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

}  // namespace rpt::engine
