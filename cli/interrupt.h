// SPDX-License-Identifier: MIT
// Ctrl-C (SIGINT), SIGTERM and SIGHUP: the process removes the temporaries of the outputs it was
// writing (datasets/io/staged_output.h) and exits with 128 + the signal number (130 for Ctrl-C).
// Outputs already in place stay as they were: an interrupted run never leaves a partial file.
#pragma once

#include <functional>

namespace rpt::cli {

// Blocks the three signals in the calling thread (and so in every thread it starts later) and
// starts one thread that waits for them. Call first thing in main(), before any other thread.
void InstallInterruptHandler();

// While one is alive (a command reading a live stream: `rpt triangulate --follow`), the first of
// the three signals calls `stop` on the signal thread instead of ending the process: the command
// ends as at the end of its input (finishes the frame in hand, writes its outputs, prints its
// summary) and then exits with 128 + signal_number() itself. A second signal ends the process as
// above. One at a time.
class StopOnInterrupt {
 public:
  explicit StopOnInterrupt(std::function<void()> stop);
  ~StopOnInterrupt();
  StopOnInterrupt(const StopOnInterrupt&) = delete;
  StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;

  // The signal that called `stop`, 0 while none did.
  int signal_number() const;
  // "SIGINT", "SIGTERM" or "SIGHUP".
  static const char* SignalName(int signal_number);
};

}  // namespace rpt::cli
