// SPDX-License-Identifier: MIT
// The configurations of `rpt sweep`: read from a --list file or expanded from --grid axes. Each is a
// name and the options it overrides (key, value text as --set takes it); the keys are checked when
// the sweep resolves its configurations, before anything runs.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rpt::engine {

struct SweepConfiguration {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;  // key, value
};

// A --list file: a JSON list of {"name", "set": {key: value}} or {"configurations": [...]} around
// it; a missing name becomes "config <i>". Read through the guarded JSON path (depth and size
// limits); every wrong type is an InputError naming the file and the JSON pointer.
std::vector<SweepConfiguration> ReadSweepList(const std::string& path);

// The grid of --grid axes "key=v1,v2,...": every combination, named "key=v1 key2=w1" ("default"
// for no axis). ConfigError for an axis without '=' or without values.
std::vector<SweepConfiguration> ExpandSweepGrid(const std::vector<std::string>& grid);

}  // namespace rpt::engine
