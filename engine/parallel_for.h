// SPDX-License-Identifier: MIT
// Independent work items on several threads (OpenMP stays inside the engine: cli/ only calls this).
#pragma once

#include <functional>

namespace rpt::engine {

// Runs body(i, report_progress) for i in 0..count-1 on up to `threads` threads (0 = automatic;
// clamped by ClampThreads: at most the hardware threads and the work), dynamically scheduled;
// report_progress is true on one thread only. The first exception a body throws is rethrown once
// every item has run (exceptions must not cross the parallel region). Returns the threads used;
// 1 in a build without OpenMP.
int ParallelFor(int count, int threads, const std::function<void(int, bool)>& body);

}  // namespace rpt::engine
