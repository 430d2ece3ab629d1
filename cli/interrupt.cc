// SPDX-License-Identifier: MIT
// The signals are not handled in a signal handler (only a few system calls are allowed there) but
// by a thread blocked in sigwait(): it runs as ordinary code, so it can take the temporaries'
// registry lock and remove folders. It keeps that lock until _exit, so no other thread can create
// or commit an output in between.
#include "cli/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <thread>

#include "datasets/io/staged_output.h"

namespace rpt::cli {
namespace {

// The three signals, except those the process was started ignoring (nohup, a background job of a
// script): they stay ignored.
sigset_t InterruptSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    sigaddset(&signals, signal_number);
  }
  return signals;
}

const char* SignalName(int signal_number) {
  switch (signal_number) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal";
  }
}

[[noreturn]] void WaitForInterrupt(sigset_t signals) {
  int signal_number = 0;
  while (sigwait(&signals, &signal_number) != 0) {
  }
  const int removed = io::RemoveTemporariesForExit();
  std::fprintf(stderr, "\ninterrupted (%s): %d unfinished output(s) removed, finished outputs unchanged\n",
               SignalName(signal_number), removed);
  std::fflush(stderr);
  _exit(128 + signal_number);
}

}  // namespace

void InstallInterruptHandler() {
  const sigset_t signals = InterruptSignals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(WaitForInterrupt, signals).detach();
}

}  // namespace rpt::cli
