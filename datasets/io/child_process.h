// SPDX-License-Identifier: MIT
// Runs a piece of work in a forked child process, bounded in time: for libraries that can crash
// or loop forever on a damaged file (HDF5's metadata, OpenCV's FileStorage parsers), so that rpt
// reports the file instead of crashing or hanging with it.
//
// The child is silent (its stdout and stderr go to /dev/null) and dies of what would kill it: the
// parent's signal handlers (interrupt clean-up, a fuzzer's crash report) and a sanitizer's death
// callback do not run in it. The parent waits on a pipe the child holds until it ends, which
// poll() bounds in time; a child past the limit is killed. Where fork() (or a pipe) is not
// available, nothing runs and the outcome says so: the caller goes on without the check.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace rpt::io {

struct ChildOutcome {
  enum class Kind {
    kNotRun,    // no fork (platform, process or descriptor limit): no verdict
    kExited,    // exit_code holds the body's return value (or 255 after an exception)
    kSignaled,  // killed by signal `signal` (a crash, a sanitizer's abort)
    kTimedOut,  // still running at the limit: killed
  };
  Kind kind = Kind::kNotRun;
  int exit_code = 0;
  int signal = 0;
};

// Runs body() in a forked child; its return value (0-254) is the child's exit code.
ChildOutcome RunInChild(const std::function<int()>& body, std::chrono::milliseconds limit);

// "signal 11, Segmentation fault".
std::string SignalName(int signal);

// "60 s" for whole seconds, else "250 ms".
std::string LimitText(std::chrono::milliseconds limit);

}  // namespace rpt::io
