// SPDX-License-Identifier: MIT
#include "cli/config_args.h"

namespace rpt::cli {

void AddConfigOptions(CLI::App* command, ConfigArgs* args) {
  command->add_option("--config", args->config_file, "JSON configuration file (see `rpt config --dump`)");
  command->add_option("--set", args->overrides, "override one option, e.g. --set prefilter.enabled=false (repeatable)")
      ->take_all();
}

Config ResolveConfig(const ConfigArgs& args) {
  Config config;
  if (!args.config_file.empty()) LoadConfigFile(args.config_file, &config);
  for (const std::string& assignment : args.overrides) ApplyConfigOverride(assignment, &config);
  CheckConfig(config);
  return config;
}

}  // namespace rpt::cli
