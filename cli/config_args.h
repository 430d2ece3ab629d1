// SPDX-License-Identifier: MIT
// The --config FILE / --set key=value options shared by every command that runs the pipeline.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "engine/config.h"

namespace rpt::cli {

struct ConfigArgs {
  std::string config_file;
  std::vector<std::string> overrides;
};

void AddConfigOptions(CLI::App* command, ConfigArgs* args);
// engine::ResolveConfig of the options; settings without effect are printed to stderr as
// "warning: ...".
engine::Config ResolveConfig(const ConfigArgs& args);

}  // namespace rpt::cli
