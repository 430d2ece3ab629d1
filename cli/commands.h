// SPDX-License-Identifier: MIT
// The rpt subcommands. Each Register*Command adds one subcommand to the app; its callback runs
// the command and throws rpt::InputError / rpt::ConfigError on bad input (exit code 2).
#pragma once

#include <CLI/CLI.hpp>

namespace rpt::cli {

void RegisterDemoCommand(CLI::App& app);
void RegisterConfigCommand(CLI::App& app);

}  // namespace rpt::cli
