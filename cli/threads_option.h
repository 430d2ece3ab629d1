// SPDX-License-Identifier: MIT
// The --threads option of the commands that run sequences in parallel.
#pragma once

#include <string_view>

#include <CLI/CLI.hpp>

namespace rpt::cli {

// Adds `--threads` to `command`: non-negative (a negative value is a usage error, exit 2); the
// run clamps it to the cores and the work (engine/thread_count.h). `one_sequence_stages`: the
// command runs through engine::Run, where one sequence runs its stages in parallel (engine/run.h).
inline void AddThreadsOption(CLI::App* command, int* threads, std::string_view what_runs_in_parallel,
                             bool one_sequence_stages = false) {
  std::string help = std::string(what_runs_in_parallel) + " in parallel";
  if (one_sequence_stages) {
    help +=
        ", or for one sequence its reading, triangulation and measuring + writing (at most 8 threads; the "
        "results of 1 thread)";
  }
  command->add_option("--threads", *threads, help + " (0 = automatic: all cores; at most the cores)")
      // Digits only (a count above the cores is clamped with a note); CLI::NonNegativeNumber quoted
      // its bound, DBL_MAX, as 309 digits when it refused 1e400.
      ->check(CLI::Validator(
          [](const std::string& value) {
            const bool digits = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
            return digits ? std::string() : "'" + value + "' is not a whole number >= 0";
          },
          "INT >= 0"));
}

}  // namespace rpt::cli
