// SPDX-License-Identifier: MIT
// rpt: multi-view multi-person 3D pose triangulation and its offline evaluation.
// Exit codes: 0 success, 2 bad input or configuration (message names the file and place),
// 1 internal error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cli/commands.h"
#include "cli/run_info.h"
#include "core/errors.h"

int main(int argc, char** argv) {
  CLI::App app{"rpt: RapidPoseTriangulation, learning-free multi-view multi-person 3D pose triangulation"};
  app.require_subcommand(1);
  rpt::cli::SetCommandLine(rpt::cli::CommandLine(argc, argv));
  rpt::cli::RegisterDemoCommand(app);
  rpt::cli::RegisterEvalCommand(app);
  rpt::cli::RegisterInspectCommand(app);
  rpt::cli::RegisterDetectorStatsCommand(app);
  rpt::cli::RegisterDatasetsCommand(app);
  rpt::cli::RegisterConvertCommand(app);
  rpt::cli::RegisterBenchCommand(app);
  rpt::cli::RegisterConfigCommand(app);
  int exit_code = 0;
  rpt::cli::RegisterCheckCommand(app, &exit_code);
  rpt::cli::RegisterSweepCommand(app);
  rpt::cli::RegisterMergeCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const rpt::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const rpt::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 1;
  }
  return exit_code;
}
