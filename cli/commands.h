// SPDX-License-Identifier: MIT
// The rpt subcommands. Each Register*Command adds one subcommand to the app; its callback runs
// the command and throws rpt::InputError / rpt::ConfigError on bad input (exit code 2).
#pragma once

#include <CLI/CLI.hpp>

namespace rpt::cli {

void RegisterDemoCommand(CLI::App& app);
void RegisterConfigCommand(CLI::App& app);
void RegisterEvalCommand(CLI::App& app);
void RegisterFitAdapterCommand(CLI::App& app);
// triangulate --follow: 128 + the signal when Ctrl-C ended the stream.
void RegisterTriangulateCommand(CLI::App& app, int* exit_code);
void RegisterDatasetsCommand(CLI::App& app);
void RegisterCamerasCommand(CLI::App& app);
void RegisterConvertCommand(CLI::App& app);
void RegisterBenchCommand(CLI::App& app);
void RegisterInspectCommand(CLI::App& app);
void RegisterDetectorStatsCommand(CLI::App& app);
void RegisterRenderCommand(CLI::App& app);
// Commands whose success is not binary set *exit_code (check: 1 when a threshold failed).
void RegisterCheckCommand(CLI::App& app, int* exit_code);
void RegisterSweepCommand(CLI::App& app);
void RegisterMergeCommand(CLI::App& app);
void RegisterReportCommand(CLI::App& app);

}  // namespace rpt::cli
