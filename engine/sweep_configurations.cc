// SPDX-License-Identifier: MIT
#include "engine/sweep_configurations.h"

#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/text.h"
#include "datasets/io/json_file.h"
#include "engine/json_text.h"

namespace rpt::engine {

std::vector<SweepConfiguration> ReadSweepList(const std::string& path) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string list_pointer = root.is_object() ? "/configurations" : "";
  const nlohmann::json* items = io::JsonFind(root, list_pointer);
  if (!items || !items->is_array()) {
    throw InputError(path + ": " + (list_pointer.empty() ? "/" : list_pointer) +
                     ": expected a list of {\"name\", \"set\"} or {\"configurations\": [...]}, got " +
                     (items ? items->type_name() : "nothing"));
  }
  std::vector<SweepConfiguration> configurations;
  configurations.reserve(items->size());
  for (size_t i = 0; i < items->size(); ++i) {
    const std::string pointer = io::JsonPointerJoin(list_pointer, i);
    const nlohmann::json& item = (*items)[i];
    if (!item.is_object()) {
      throw InputError(path + ": " + pointer + ": expected {\"name\", \"set\"}, got " + item.type_name());
    }
    SweepConfiguration configuration;
    configuration.name =
        item.contains("name") ? io::JsonString(root, pointer + "/name", path) : "config " + std::to_string(i);
    if (item.contains("set")) {
      const nlohmann::json& set = item["set"];
      if (!set.is_object()) {
        throw InputError(path + ": " + pointer + "/set: expected an object {option: value}, got " + set.type_name());
      }
      for (const auto& [key, value] : set.items()) configuration.overrides.emplace_back(key, JsonValueText(value));
    }
    configurations.push_back(std::move(configuration));
  }
  return configurations;
}

std::vector<SweepConfiguration> ExpandSweepGrid(const std::vector<std::string>& grid) {
  std::vector<SweepConfiguration> configurations = {SweepConfiguration{}};
  for (const std::string& axis : grid) {
    const size_t eq = axis.find('=');
    if (eq == std::string::npos) throw ConfigError("--grid " + axis + ": expected key=value1,value2,...");
    const std::string key = axis.substr(0, eq);
    const std::vector<std::string> values = SplitList(axis.substr(eq + 1));
    if (values.empty()) throw ConfigError("--grid " + axis + ": no values");
    std::vector<SweepConfiguration> next;
    next.reserve(configurations.size() * values.size());
    for (const SweepConfiguration& configuration : configurations) {
      for (const std::string& value : values) {
        SweepConfiguration combined = configuration;
        combined.overrides.emplace_back(key, value);
        next.push_back(std::move(combined));
      }
    }
    configurations = std::move(next);
  }
  for (SweepConfiguration& configuration : configurations) {
    for (const auto& [key, value] : configuration.overrides) AppendItem(&configuration.name, key + "=" + value, " ");
    if (configuration.name.empty()) configuration.name = "default";
  }
  return configurations;
}

}  // namespace rpt::engine
