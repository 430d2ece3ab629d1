// SPDX-License-Identifier: MIT
// The run configuration: every triangulator option (sections named like the pipeline steps) and
// every metric option (section "metrics"), settable from a JSON file and from
// `--set section.key=value`. Keys, help texts, units and ranges come from the VisitFields
// functions beside the options structs (core/pipeline/options.h, metrics/eval_options.h); this
// file only reads and writes them. Unknown keys and bad values are ConfigErrors naming the key and
// where it came from, with a "did you mean" for typos.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/option_spec.h"
#include "core/pipeline/options.h"
#include "metrics/eval_options.h"

namespace rpt::engine {

struct Config {
  TriangulatorOptions triangulator;
  metrics::EvalOptions metrics;
};

// The sections of a Config in dump order: the triangulator's, then "metrics".
template <class Visitor, OptionsOf<Config> Self>
void VisitSections(Visitor& v, Self& config) {
  VisitSections(v, config.triangulator);
  v("metrics", config.metrics);
}

struct ConfigOptionInfo {
  std::string key;            // "section.name"
  std::string type;           // what a value must be (OptionTypeText): "number in [0, 1]", "a | b", ...
  std::string default_value;  // as --set text (FormatOption)
  OptionSpec spec;            // help, unit, range
};
// Every option, in dump order.
std::vector<ConfigOptionInfo> ConfigOptions();

// Sets one option from text (`--set key=value`) by the rules of core/option_codec.h; a bad value
// throws ConfigError "<where>: <key>: '<value>' is not ...", an unknown key one with "did you mean".
void SetConfigOption(const std::string& key, const std::string& value, const std::string& where, Config* config);
// Parses "key=value" and calls SetConfigOption.
void ApplyConfigOverride(const std::string& assignment, Config* config);
// Current value of an option as text (same syntax SetConfigOption accepts).
std::string GetConfigOption(const Config& config, const std::string& key);

// Applies a JSON config file {"section": {"key": value, ...}, ...} on top of `config`: each value
// goes through SetConfigOption as its text (a JSON string as is, others as JSON writes them), with
// the file and the JSON pointer as `where`; then CheckConfig.
void LoadConfigFile(const std::filesystem::path& path, Config* config);
// The configuration as JSON text that LoadConfigFile reads back. With comments, each option gets a
// trailing "// value, unit: help" and the text is documentation, no longer JSON.
std::string DumpConfig(const Config& config, bool with_comments);
// docs/options.md: every option's default, type, unit, range and help as Markdown tables.
std::string ConfigMarkdown();

// Defaults, then the file (when not empty), then the `overrides` ("section.key=value") in order;
// checked (throws ConfigError naming the file or the override). Settings without effect are in
// ConfigWarnings.
Config ResolveConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides);

// Runs the options' Check(); throws ConfigError "section.key: problem".
void CheckConfig(const Config& config);
// Valid settings without effect (TriangulatorOptions::Warnings), one line each.
std::vector<std::string> ConfigWarnings(const Config& config);

}  // namespace rpt::engine
