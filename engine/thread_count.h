// SPDX-License-Identifier: MIT
// How many threads a parallel loop uses: the requested count (0 = automatic) clamped to the
// hardware and to the work, so `--threads 100000` cannot ask OpenMP for 100000 threads.
#pragma once

namespace rpt::engine {

// Threads for `work` independent items: `requested` (0 = automatic: OpenMP's default, i.e. the
// cores or OMP_NUM_THREADS) at most the hardware threads and at most `work` (at least 1). Prints
// "note: --threads N is more than the M hardware threads; using M" when the hardware cut it.
// Throws ConfigError when `requested` is negative.
int ClampThreads(int requested, long work);

}  // namespace rpt::engine
