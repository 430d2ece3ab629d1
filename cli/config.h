// SPDX-License-Identifier: MIT
// The run configuration: every triangulator option (sections named like the pipeline steps) and
// every metric option (section "metrics"), settable from a JSON file and from
// `--set section.key=value`. Unknown keys and bad values are ConfigErrors naming the key and
// where it came from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/pipeline/options.h"
#include "metrics/eval_options.h"

namespace rpt::cli {

struct Config {
  TriangulatorOptions triangulator;
  metrics::EvalOptions metrics;
};

struct ConfigOptionInfo {
  std::string key;   // "section.name"
  std::string type;  // bool, int, number, one of a|b|c, list of joint names, [x, y, z]
  std::string help;  // unit, effect
};
// Every option, in documentation order.
std::vector<ConfigOptionInfo> ConfigOptions();

// Sets one option from text (`--set key=value`; booleans true/false, lists "a,b", vectors "x,y,z").
// `where` names the source in error messages.
void SetConfigOption(const std::string& key, const std::string& value, const std::string& where, Config* config);
// Parses "key=value" and calls SetConfigOption.
void ApplyConfigOverride(const std::string& assignment, Config* config);
// Current value of an option as text (same syntax SetConfigOption accepts).
std::string GetConfigOption(const Config& config, const std::string& key);

// Applies a JSON config file {"section": {"key": value, ...}, ...} on top of `config`.
void LoadConfigFile(const std::filesystem::path& path, Config* config);
// The configuration as JSON text; with comments, each option gets a trailing "// help" (then it
// is documentation, not strict JSON).
std::string DumpConfig(const Config& config, bool with_comments);

// Runs the options' own checks; throws ConfigError.
void CheckConfig(const Config& config);

}  // namespace rpt::cli
