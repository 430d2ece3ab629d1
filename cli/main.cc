// SPDX-License-Identifier: MIT
// rpt: multi-view multi-person 3D pose triangulation and its offline evaluation.
// Exit codes: 0 success, 2 bad input or configuration (message names the file and place),
// 1 internal error, 128 + signal number when interrupted (130 for Ctrl-C; cli/interrupt.h).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/memory_reserve.h"
#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/inflate_budget.h"
#include "datasets/io/input_limits.h"
#include "datasets/io/staged_output.h"
#include "datasets/readers/hdf5_cache.h"
#include "engine/outputs/run_info.h"
#include "git_revision.h"

namespace {

std::vector<std::string> SubcommandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

// "unknown subcommand 'evl'; did you mean 'eval'?" when the first argument is not a subcommand
// (CLI11 would only say that a subcommand is required). Returns false when it printed the error.
bool CheckSubcommand(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return true;
  const std::vector<std::string> names = SubcommandNames(app);
  const std::string given = argv[1];
  for (const std::string& name : names) {
    if (name == given) return true;
  }
  const std::string closest = rpt::ClosestName(given, names);
  std::fprintf(stderr, "error: unknown subcommand '%s'%s\nRun with --help for the list.\n",
               rpt::PrintableText(given, rpt::LineBreaks::kEscape).c_str(),
               closest.empty() ? "" : ("; did you mean " + rpt::QuoteName(closest) + "?").c_str());
  return false;
}

// For flags a subcommand does not know: the closest option of that subcommand, e.g.
// "--thresold: did you mean '--thresholds'?" (CLI11 hands such flags back to the main app).
void PrintOptionSuggestions(CLI::App& app) {
  std::vector<std::string> options;
  std::vector<std::string> extras = app.remaining();
  for (CLI::App* sub : app.get_subcommands()) {
    for (const CLI::Option* option : sub->get_options()) {
      for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
    }
    for (const std::string& extra : sub->remaining()) extras.push_back(extra);
  }
  for (const std::string& extra : extras) {
    if (extra.size() < 3 || extra.rfind("--", 0) != 0) continue;
    const std::string flag = extra.substr(0, extra.find('='));
    const std::string closest = rpt::ClosestName(flag, options);
    if (!closest.empty()) {
      std::fprintf(stderr, "%s: did you mean '%s'?\n", rpt::PrintableText(flag, rpt::LineBreaks::kEscape).c_str(),
                   closest.c_str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool started = false;
  try {
    rpt::cli::InstallInterruptHandler();  // before any other thread starts
    started = rpt::cli::InstallMemoryReserve(32 << 20);  // out of memory ends in a message, not std::terminate
  } catch (const std::exception&) {  // the handler's thread could not start (std::system_error, bad_alloc)
  }
  if (!started) {
    std::fprintf(stderr, "error: out of memory starting rpt: the memory limit of this process (ulimit -v) leaves no room "
                 "to run\n");
    return 1;
  }
  rpt::SkipHdf5CleanupAtExit();          // before any other HDF5 call
  CLI::App app{"rpt: RapidPoseTriangulation, learning-free multi-view multi-person 3D pose triangulation"};
  app.require_subcommand(1);
  // CLI11 quotes the refused value as given: a value with terminal escapes (ESC ]0; ... BEL) reached
  // the terminal raw. Its message is printed with control characters escaped, line breaks kept,
  // and starts with "error: " as every other error does (a script greps for it).
  app.failure_message([](const CLI::App* failed, const CLI::Error& e) {
    return "error: " + rpt::PrintableText(CLI::FailureMessage::simple(failed, e));
  });
  app.set_version_flag("--version", std::string("rpt ") + RPT_VERSION + " (git " + RPT_GIT_REVISION + ")",
                       "print the version and git revision, then exit");
  // Global options, accepted before or after the subcommand (fallthrough).
  app.fallthrough();
  app.add_option_function<std::uint64_t>(
         "--max-inflate-mb", [](std::uint64_t megabytes) { rpt::io::SetInflateLimitMb(megabytes); },
         "limit on the data decompressed from one input file (MAT, NPZ, compressed HDF5; the detections a VoxelPose .pkl decodes to), in MiB "
         "(default: 64 x the file size, at least 64, at most 4096)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 24));
  app.add_option_function<std::uint64_t>(
         "--max-input-mb", [](std::uint64_t megabytes) { rpt::io::SetMaxInputMb(megabytes); },
         "limit on the size of an input file read whole (JSON, NPY, MAT, pickle), in MiB (default " +
             std::to_string(rpt::io::kDefaultMaxInputMb) + ")")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 24));
  app.add_option_function<std::uint64_t>(
         "--max-cameras", [](std::uint64_t count) { rpt::io::SetMaxCameras(count); },
         "limit on the cameras of one label, calibration file or frame (default " +
             std::to_string(rpt::io::kDefaultMaxCameras) + ")")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 24));
  rpt::engine::SetCommand(argc, argv);
  rpt::cli::RegisterDemoCommand(app);
  rpt::cli::RegisterEvalCommand(app);
  rpt::cli::RegisterFitAdapterCommand(app);
  int exit_code = 0;
  rpt::cli::RegisterTriangulateCommand(app, &exit_code);
  rpt::cli::RegisterInspectCommand(app);
  rpt::cli::RegisterDetectorStatsCommand(app);
  rpt::cli::RegisterRenderCommand(app);
  rpt::cli::RegisterDatasetsCommand(app);
  rpt::cli::RegisterCamerasCommand(app);
  rpt::cli::RegisterConvertCommand(app);
  rpt::cli::RegisterBenchCommand(app);
  rpt::cli::RegisterConfigCommand(app);
  rpt::cli::RegisterCheckCommand(app, &exit_code);
  rpt::cli::RegisterSweepCommand(app);
  rpt::cli::RegisterMergeCommand(app);
  rpt::cli::RegisterReportCommand(app);
  if (!CheckSubcommand(app, argc, argv)) return 2;
  // Whatever way the command ends: the temporaries of killed runs found beside its outputs.
  struct StaleTemporaries {
    ~StaleTemporaries() {
      for (const std::string& line : rpt::io::StaleTemporaryWarnings()) std::fprintf(stderr, "warning: %s\n", line.c_str());
    }
  } stale_temporaries;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0) PrintOptionSuggestions(app);  // also when a required option is missing because it was misspelt
    return code == 0 ? 0 : 2;
  } catch (const rpt::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const rpt::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const rpt::InstallationError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    // The places that read or process an input turn this into an InputError naming the input;
    // what is left is named by its command.
    const std::vector<CLI::App*> ran = app.get_subcommands();
    std::fprintf(stderr, "error: out of memory running `rpt %s`: the input is too large for this machine (see the "
                 "limits in `rpt --help`: --max-input-mb, --max-cameras)\n", ran.empty() ? "" : ran[0]->get_name().c_str());
    return 2;  // as the same failure named by its input: the input is what is too large
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 1;
  }
  // Printed results are outputs too: a full disk or closed pipe behind stdout is an error.
  std::cout.flush();
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
    std::fprintf(stderr, "error: standard output: write failed (%s)\n", std::strerror(errno));
    return 2;
  }
  return exit_code;
}
