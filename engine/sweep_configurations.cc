// SPDX-License-Identifier: MIT
#include "engine/sweep_configurations.h"

#include <nlohmann/json.hpp>

#include <cstdio>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/io/file_digest.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_string_scanner.h"
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
    for (const auto& [key, value] : item.items()) {
      if (key == "name" || key == "set") continue;
      throw InputError(path + ": " + io::JsonPointerJoin(pointer, key) + ": " +
                       UnknownNameProblem("key", key, {"name", "set"}, "a configuration has \"name\" and \"set\""));
    }
    SweepConfiguration configuration;
    configuration.origin = path + ": " + pointer;
    // Unnamed: "configuration K", counted from 1 as the messages and --shard count.
    configuration.name = item.contains("name") ? io::JsonString(root, pointer + "/name", path)
                                               : "configuration " + std::to_string(i + 1);
    if (configuration.name.empty()) throw InputError(path + ": " + pointer + "/name: empty (names tell the rows apart)");
    for (size_t earlier = 0; earlier < configurations.size(); ++earlier) {
      if (configurations[earlier].name != configuration.name) continue;
      throw InputError(path + ": " + pointer + "/name: " + QuoteName(configuration.name) + " names configuration " +
                       std::to_string(earlier + 1) + " too (names tell the rows apart)");
    }
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

namespace {

// The values of a --grid axis: split at commas outside JSON lists and strings, so a list option
// is one value (`triangulate.core_joints=[],["hip_left","hip_right"]`: two values); blanks trimmed,
// empty items dropped.
std::vector<std::string> SplitGridValues(std::string_view text) {
  std::vector<std::string> items;
  int depth = 0;
  io::JsonStringScanner strings;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : ',';
    if (strings.InString(c) && i < text.size()) continue;
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && depth > 0) --depth;
    if (c == ',' && (depth == 0 || i == text.size())) {
      const std::string_view item = TrimBlanks(text.substr(start, i - start));
      if (!item.empty()) items.emplace_back(item);
      start = i + 1;
    }
  }
  return items;
}

}  // namespace

std::vector<SweepConfiguration> ExpandSweepGrid(const std::vector<std::string>& grid) {
  std::vector<SweepConfiguration> configurations = {SweepConfiguration{}};
  for (const std::string& axis : grid) {
    const size_t eq = axis.find('=');
    if (eq == std::string::npos) throw ConfigError("--grid " + axis + ": expected key=value1,value2,...");
    const std::string key = axis.substr(0, eq);
    const std::vector<std::string> values = SplitGridValues(axis.substr(eq + 1));
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
    configuration.origin = "--grid";
  }
  return configurations;
}

nlohmann::ordered_json SweepIdentity(const std::vector<SweepConfiguration>& all, const std::string& base_config,
                                     const InputSpec& input) {
  nlohmann::ordered_json identity;
  nlohmann::ordered_json configurations = nlohmann::ordered_json::array();
  for (const SweepConfiguration& c : all) {
    nlohmann::ordered_json set = nlohmann::ordered_json::object();
    for (const auto& [key, value] : c.overrides) set[key] = value;
    configurations.push_back({{"name", c.name}, {"set", set}});
  }
  identity["configurations"] = configurations;
  char digest[16];
  std::snprintf(digest, sizeof(digest), "crc32:%08x", io::Crc32(0, base_config));
  identity["base_config"] = digest;
  identity["input"] = {{"dataset", input.dataset},
                       {"root", input.root},
                       {"params", input.params},
                       {"labels", input.labels},
                       {"cameras", input.cameras},
                       {"detections", input.detections},
                       {"simulate", input.simulate || input.simulate_perfect},
                       {"detector", input.simulate_perfect ? std::string("perfect") : input.detector},
                       {"seed", input.seed}};
  return identity;
}

}  // namespace rpt::engine
