// SPDX-License-Identifier: MIT
// The --threads option of the commands that run sequences in parallel.
#pragma once

#include <string_view>

#include <CLI/CLI.hpp>

namespace rpt::cli {

// Adds `--threads` to `command`: non-negative (a negative value is a usage error, exit 2); the
// run clamps it to the cores and the work (engine/thread_count.h).
inline void AddThreadsOption(CLI::App* command, int* threads, std::string_view what_runs_in_parallel) {
  command
      ->add_option("--threads", *threads,
                   std::string(what_runs_in_parallel) + " in parallel (0 = automatic: all cores; at most the cores)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace rpt::cli
