// SPDX-License-Identifier: MIT
// The signals are not handled in a signal handler (only a few system calls are allowed there) but
// by a thread blocked in sigwait(): it runs as ordinary code, so it can take the temporaries'
// registry lock and remove folders. It keeps that lock until _exit, so no other thread can create
// or commit an output in between.
#include "cli/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <mutex>
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

// The stop of the StopOnInterrupt alive, and the signal that called it.
struct StopHook {
  std::mutex mutex;
  std::function<void()> stop;
  std::atomic<int> signal_number{0};
};
StopHook& Hook() {
  static StopHook hook;
  return hook;
}

[[noreturn]] void WaitForInterrupt(sigset_t signals) {
  int signal_number = 0;
  while (true) {
    while (sigwait(&signals, &signal_number) != 0) {
    }
    StopHook& hook = Hook();
    std::lock_guard<std::mutex> lock(hook.mutex);
    if (!hook.stop || hook.signal_number.load() != 0) break;
    hook.signal_number.store(signal_number);
    hook.stop();
  }
  const int removed = io::RemoveTemporariesForExit();
  std::fprintf(stderr, "\ninterrupted (%s): %d unfinished output(s) removed, finished outputs unchanged\n",
               StopOnInterrupt::SignalName(signal_number), removed);
  std::fflush(stderr);
  _exit(128 + signal_number);
}

}  // namespace

const char* StopOnInterrupt::SignalName(int signal_number) {
  switch (signal_number) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal";
  }
}

StopOnInterrupt::StopOnInterrupt(std::function<void()> stop) {
  StopHook& hook = Hook();
  std::lock_guard<std::mutex> lock(hook.mutex);
  hook.stop = std::move(stop);
  hook.signal_number.store(0);
}

StopOnInterrupt::~StopOnInterrupt() {
  StopHook& hook = Hook();
  std::lock_guard<std::mutex> lock(hook.mutex);
  hook.stop = nullptr;
}

int StopOnInterrupt::signal_number() const { return Hook().signal_number.load(); }

void InstallInterruptHandler() {
  // A file size limit (ulimit -f) sends SIGXFSZ, whose default action killed rpt without a word
  // and left its temporaries; ignored, the write fails with EFBIG instead, which is the error naming
  // the file (exit 2) that every other failed write gives, and the temporaries are removed.
  signal(SIGXFSZ, SIG_IGN);
  const sigset_t signals = InterruptSignals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(WaitForInterrupt, signals).detach();
}

}  // namespace rpt::cli
