// SPDX-License-Identifier: MIT
// Ctrl-C (SIGINT), SIGTERM and SIGHUP: the process removes the temporaries of the outputs it was
// writing (datasets/io/staged_output.h) and exits with 128 + the signal number (130 for Ctrl-C).
// Outputs already in place stay as they were: an interrupted run never leaves a partial file.
#pragma once

namespace rpt::cli {

// Blocks the three signals in the calling thread (and so in every thread it starts later) and
// starts one thread that waits for them. Call first thing in main(), before any other thread.
void InstallInterruptHandler();

}  // namespace rpt::cli
