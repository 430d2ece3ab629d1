// SPDX-License-Identifier: MIT
#include "datasets/io/child_process.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>

#if defined(__linux__) || defined(__FreeBSD__)
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#define RPT_CHILD_PROCESS_FORK 1
#endif

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define RPT_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define RPT_SANITIZED 1
#endif
#endif
#ifdef RPT_SANITIZED
#include <sanitizer/common_interface_defs.h>
#endif

namespace rpt::io {

#ifdef RPT_CHILD_PROCESS_FORK
namespace {

[[noreturn]] void RunChild(const std::function<int()>& body) {
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
    std::signal(signal, SIG_DFL);
  }
#ifdef RPT_SANITIZED
  __sanitizer_set_death_callback(nullptr);
#endif
  int code = 255;
  try {
    code = std::clamp(body(), 0, 254);
  } catch (...) {
    code = 255;
  }
  _exit(code);
}

}  // namespace
#endif

ChildOutcome RunInChild(const std::function<int()>& body, std::chrono::milliseconds limit) {
  ChildOutcome outcome;
#ifdef RPT_CHILD_PROCESS_FORK
  int pipe_ends[2];
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) return outcome;  // no pipe (descriptor limit)
  const pid_t child = fork();
  if (child < 0) {  // no child (process limit, memory)
    close(pipe_ends[0]);
    close(pipe_ends[1]);
    return outcome;
  }
  if (child == 0) {
    close(pipe_ends[0]);
    RunChild(body);
  }
  close(pipe_ends[1]);
  const auto deadline = std::chrono::steady_clock::now() + limit;
  bool ended = false;
  while (!ended) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd wait_for_end{pipe_ends[0], POLLIN, 0};
    const int ready = poll(&wait_for_end, 1, static_cast<int>(std::min<long long>(left.count(), 1 << 30)));
    if (ready < 0 && errno != EINTR) {
      ended = true;  // cannot wait with a limit: wait for the child without one
      break;
    }
    char byte;
    ended = ready > 0 && read(pipe_ends[0], &byte, 1) <= 0;  // end of file: the child has ended
  }
  close(pipe_ends[0]);
  if (!ended) kill(child, SIGKILL);
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return outcome;  // the child was reaped elsewhere (SIGCHLD ignored): no verdict
  }
  if (!ended) {
    outcome.kind = ChildOutcome::Kind::kTimedOut;
  } else if (WIFEXITED(status)) {
    outcome.kind = ChildOutcome::Kind::kExited;
    outcome.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    outcome.kind = ChildOutcome::Kind::kSignaled;
    outcome.signal = WTERMSIG(status);
  }
#else
  (void)body, (void)limit;
#endif
  return outcome;
}

std::string SignalName(int signal) {
  const char* name = strsignal(signal);
  return "signal " + std::to_string(signal) + (name ? std::string(", ") + name : std::string());
}

std::string LimitText(std::chrono::milliseconds limit) {
  return limit.count() >= 1000 && limit.count() % 1000 == 0 ? std::to_string(limit.count() / 1000) + " s"
                                                             : std::to_string(limit.count()) + " ms";
}

}  // namespace rpt::io
