// SPDX-License-Identifier: MIT
#include "cli/config_args.h"

#include <iostream>

namespace rpt::cli {

void AddConfigOptions(CLI::App* command, ConfigArgs* args) {
  command->add_option("--config", args->config_file, "JSON configuration file (the format `rpt config --dump` prints)");
  command
      ->add_option("--set", args->overrides,
                   "override one option, e.g. --set prefilter.enabled=false; lists as JSON or comma list: "
                   "--set 'triangulate.core_joints=[\"shoulder_left\",\"shoulder_right\",\"hip_left\",\"hip_right\"]' "
                   "or ...=shoulder_left,shoulder_right,hip_left,hip_right "
                   "(repeatable, after --config)")
      ->take_all();
}

engine::Config ResolveConfig(const ConfigArgs& args) {
  const engine::Config config = engine::ResolveConfig(args.config_file, args.overrides);
  for (const std::string& warning : engine::ConfigWarnings(config)) std::cerr << "warning: " << warning << "\n";
  return config;
}

}  // namespace rpt::cli
