// SPDX-License-Identifier: MIT
// The configurations of `rpt sweep`: read from a --list file or expanded from --grid axes. Each is a
// name and the options it overrides (key, value text as --set takes it); the keys are checked when
// the sweep resolves its configurations, before anything runs.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "engine/input.h"

namespace rpt::engine {

struct SweepConfiguration {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;  // key, value
  std::string origin;  // where it was given, for messages: "FILE: /configurations/1" or "--grid"
};

// A --list file: a JSON list of {"name", "set": {key: value}} or {"configurations": [...]} around
// it; a missing name becomes "config <i>". Read through the guarded JSON path (depth and size
// limits); every wrong type, a key other than "name" and "set" (a typo would run the defaults) and
// a name given twice is an InputError naming the file and the JSON pointer.
std::vector<SweepConfiguration> ReadSweepList(const std::string& path);

// The grid of --grid axes "key=v1,v2,...": every combination, named "key=v1 key2=w1" ("default"
// for no axis). ConfigError for an axis without '=' or without values.
std::vector<SweepConfiguration> ExpandSweepGrid(const std::vector<std::string>& grid);

// What makes two shard files parts of one sweep: every configuration (names and overrides), the
// base configuration (`base_config`, the resolved options as text) and the input options. Each
// shard file records it ("sweep"); `rpt merge` joins only shards that record the same.
nlohmann::ordered_json SweepIdentity(const std::vector<SweepConfiguration>& all, const std::string& base_config,
                                     const InputSpec& input);

}  // namespace rpt::engine
