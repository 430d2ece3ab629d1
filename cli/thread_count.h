// SPDX-License-Identifier: MIT
// How many threads a parallel loop of the CLI uses: the --threads value (0 = automatic) clamped to
// the hardware and to the work, so `--threads 100000` cannot ask OpenMP for 100000 threads.
#pragma once

#include <string_view>

#include <CLI/CLI.hpp>

namespace rpt::cli {

// Threads for `work` independent items: `requested` (0 = automatic: OpenMP's default, i.e. the
// cores or OMP_NUM_THREADS) at most the hardware threads and at most `work` (at least 1). Prints
// "note: --threads N is more than the M hardware threads; using M" when the hardware cut it.
// Throws ConfigError when `requested` is negative.
int ClampThreads(int requested, long work);

// Adds `--threads` to `command`: non-negative (a negative value is a usage error, exit 2).
void AddThreadsOption(CLI::App* command, int* threads, std::string_view what_runs_in_parallel);

}  // namespace rpt::cli
