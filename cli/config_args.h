// SPDX-License-Identifier: MIT
// The --config FILE / --set key=value options shared by every command that runs the pipeline.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/config.h"

namespace rpt::cli {

struct ConfigArgs {
  std::string config_file;
  std::vector<std::string> overrides;
};

void AddConfigOptions(CLI::App* command, ConfigArgs* args);
// Defaults, then the file, then the overrides in order; checked (throws ConfigError). Settings
// without effect are printed to stderr as "warning: ...".
Config ResolveConfig(const ConfigArgs& args);

}  // namespace rpt::cli
