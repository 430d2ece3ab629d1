// SPDX-License-Identifier: MIT
// `rpt config --dump`: the configuration (defaults, or a file plus overrides) with a comment per
// option; `--json` prints strict JSON that `--config` accepts.
#include <iostream>

#include "cli/commands.h"
#include "cli/config_args.h"

namespace rpt::cli {

void RegisterConfigCommand(CLI::App& app) {
  struct Options {
    ConfigArgs config;
    bool dump = false;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("config", "Print the configuration: every triangulator and metric option");
  command->add_flag("--dump", options->dump, "print the resolved configuration (default action)");
  command->add_flag("--json", options->json, "strict JSON without comments");
  AddConfigOptions(command, &options->config);
  command->callback([options] {
    const Config config = ResolveConfig(options->config);
    std::cout << DumpConfig(config, !options->json);
  });
}

}  // namespace rpt::cli
