// SPDX-License-Identifier: MIT
// `rpt config`: the configuration (defaults, or a file plus overrides) as JSON that `--config`
// reads back (`--dump`, the default), with a comment per option (`--comments`, then not JSON), or
// as the Markdown tables of docs/options.md (`--markdown`).
#include <iostream>

#include "cli/commands.h"
#include "cli/config_args.h"

namespace rpt::cli {

void RegisterConfigCommand(CLI::App& app) {
  struct Options {
    ConfigArgs config;
    bool dump = false;
    bool comments = false;
    bool json = false;
    bool markdown = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("config", "Print the configuration: every triangulator and metric option");
  command->footer(
      "Options are set with --config FILE (JSON, any subset of sections and keys) and --set section.key=value\n"
      "(repeatable, after the file). List values: JSON\n"
      "(--set 'triangulate.core_joints=[\"shoulder_left\",\"shoulder_right\",\"hip_left\",\"hip_right\"]') or comma\n"
      "lists (--set triangulate.core_joints=shoulder_left,shoulder_right,hip_left,hip_right); \"\" is the empty list;\n"
      "3-vectors: [8,8,3] or 8,8,3.\n"
      "Every option with its default, range and meaning: docs/options.md (rpt config --markdown).");
  command->add_flag("--dump", options->dump, "print the resolved configuration as JSON (default action)");
  CLI::Option* comments = command->add_flag(
      "--comments", options->comments, "add each option's type, unit, range and meaning as // comments (then not JSON)");
  command->add_flag("--json", options->json, "strict JSON (the default; kept for older scripts)")->excludes(comments);
  command->add_flag("--markdown", options->markdown, "print the option tables of docs/options.md (defaults)")
      ->excludes(comments);
  AddConfigOptions(command, &options->config);
  command->callback([options] {
    if (options->markdown) {
      std::cout << engine::ConfigMarkdown();
      return;
    }
    const engine::Config config = ResolveConfig(options->config);
    std::cout << engine::DumpConfig(config, options->comments);
  });
}

}  // namespace rpt::cli
