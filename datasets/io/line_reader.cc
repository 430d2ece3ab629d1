// SPDX-License-Identifier: MIT
#include "datasets/io/line_reader.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/errors.h"

namespace rpt::io {
namespace {

// Bytes asked of one read(): a frame line of a few cameras fits, and a burst of lines is taken in
// few calls.
constexpr std::size_t kReadBytes = 64 * 1024;

// Without inotify, the wait at the end of a growing file looks again this often.
constexpr int kGrowthPollMs = 10;

std::string LineReaderErrno() { return std::strerror(errno); }

bool IsRegularFile(int fd) {
  struct stat info {};
  return fstat(fd, &info) == 0 && S_ISREG(info.st_mode);
}

}  // namespace

StopRequest::StopRequest() {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) throw InputError("cannot create a pipe: " + LineReaderErrno());
  read_fd_ = fds[0];
  write_fd_ = fds[1];
}

StopRequest::~StopRequest() {
  close(read_fd_);
  close(write_fd_);
}

void StopRequest::Request() {
  requested_.store(true);
  const char byte = 1;
  // A full pipe (many requests) is readable already: nothing to add.
  while (write(write_fd_, &byte, 1) < 0 && errno == EINTR) {
  }
}

bool StopRequest::requested() const { return requested_.load(); }

LineReader::LineReader(const std::string& path, std::size_t max_line_bytes, std::shared_ptr<const StopRequest> stop)
    : source_(path == "-" ? "stdin" : path), max_line_bytes_(max_line_bytes), stop_(std::move(stop)) {
  if (path == "-") {
    fd_ = STDIN_FILENO;
    regular_file_ = IsRegularFile(fd_);
    return;
  }
  // Non-blocking, so that opening a named pipe does not wait for its writer (the wait is in poll(),
  // where a stop request ends it); blocking again for the reads.
  fd_ = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw InputError(path + ": cannot open: " + LineReaderErrno());
  owns_fd_ = true;
  struct stat info {};
  if (fstat(fd_, &info) != 0 || S_ISDIR(info.st_mode)) {
    close(fd_);
    throw InputError(path + ": a folder, expected a file, a named pipe or - (standard input)");
  }
  const int flags = fcntl(fd_, F_GETFL);
  if (flags < 0 || fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK) != 0) {
    const std::string error = LineReaderErrno();
    close(fd_);
    throw InputError(path + ": cannot read: " + error);
  }
  regular_file_ = S_ISREG(info.st_mode);
}

LineReader::LineReader(int fd, std::string source, std::size_t max_line_bytes, std::shared_ptr<const StopRequest> stop)
    : fd_(fd), source_(std::move(source)), max_line_bytes_(max_line_bytes), stop_(std::move(stop)) {
  regular_file_ = IsRegularFile(fd_);
}

LineReader::~LineReader() {
  if (watch_fd_ >= 0) close(watch_fd_);
  if (owns_fd_) close(fd_);
}

bool LineReader::WaitForGrowth() {
  if (!watch_tried_) {
    // Watched through /proc, which names the open file (also standard input redirected from a
    // file); where inotify is missing or full, the wait polls instead.
    watch_tried_ = true;
    watch_fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    const std::string self = "/proc/self/fd/" + std::to_string(fd_);
    if (watch_fd_ >= 0 && inotify_add_watch(watch_fd_, self.c_str(), IN_MODIFY) < 0) {
      close(watch_fd_);
      watch_fd_ = -1;
    }
    return true;  // read once more: data written before the watch began is not missed
  }
  const bool forever = !(wait_at_end_.count() < 1e9);  // infinity, or longer than anyone waits (no overflow below)
  const Clock::time_point until =
      forever ? Clock::time_point::max()
              : read_time_ + std::chrono::duration_cast<Clock::duration>(wait_at_end_);
  while (true) {
    const off_t at = lseek(fd_, 0, SEEK_CUR);
    struct stat info {};
    if (at >= 0 && fstat(fd_, &info) == 0 && info.st_size < at)
      throw InputError(source_ + ": the file shrank from " + std::to_string(at) + " to " +
                       std::to_string(info.st_size) + " bytes while its end was waited on (truncated?)");
    if (at >= 0 && info.st_size > at) return true;
    const Clock::time_point now = Clock::now();
    if (!forever && now >= until) return false;
    int timeout_ms = watch_fd_ >= 0 ? -1 : kGrowthPollMs;
    if (!forever) {
      // At most an hour per wait (the loop waits again): the milliseconds fit an int.
      const int left = static_cast<int>(
          std::min<long long>(std::chrono::ceil<std::chrono::milliseconds>(until - now).count(), 3'600'000));
      timeout_ms = timeout_ms < 0 ? left : std::min(timeout_ms, left);
    }
    pollfd fds[2] = {{watch_fd_, POLLIN, 0}, {stop_ ? stop_->fd() : -1, POLLIN, 0}};
    if (poll(fds, 2, timeout_ms) < 0 && errno != EINTR)
      throw InputError(source_ + ": cannot wait for input: " + LineReaderErrno());
    if (fds[1].revents != 0) {
      stopped_ = true;
      return false;
    }
    if (fds[0].revents != 0) {  // drain the events: the size test above decides
      char events[4096];
      while (read(watch_fd_, events, sizeof(events)) > 0) {
      }
    }
  }
}

void LineReader::Fill() {
  if (begin_ > 0) {  // keep the partial line at the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (buffer_.size() < end_ + kReadBytes) buffer_.resize(end_ + kReadBytes);
  pollfd fds[2] = {{fd_, POLLIN, 0}, {stop_ ? stop_->fd() : -1, POLLIN, 0}};
  Wait(fds);
  if (fds[1].revents != 0) {
    stopped_ = true;
    return;
  }
  while (true) {
    const ssize_t count = read(fd_, buffer_.data() + end_, buffer_.size() - end_);
    if (count > 0) {
      end_ += static_cast<std::size_t>(count);
      read_time_ = Clock::now();
      return;
    }
    if (count == 0) {
      if (regular_file_ && wait_at_end_.count() > 0) {
        if (read_time_ == Clock::time_point{}) read_time_ = Clock::now();  // an empty file: wait from now
        if (WaitForGrowth()) continue;
        if (stopped_) return;
      }
      at_end_ = true;
      return;
    }
    if (errno == EAGAIN || errno == EWOULDBLOCK) return;  // woken without data: wait again
    if (errno != EINTR) throw InputError(source_ + ": read failed: " + LineReaderErrno());
  }
}

void LineReader::Wait(pollfd* fds) {
  if (spin_.count() > 0) {
    const Clock::time_point until = Clock::now() + spin_;
    do {
      const int ready = poll(fds, 2, 0);
      if (ready > 0) return;
      if (ready < 0 && errno != EINTR) throw InputError(source_ + ": cannot wait for input: " + LineReaderErrno());
      sched_yield();  // a runnable thread of the machine goes first: polling must not slow what it waits for
    } while (Clock::now() < until);
  }
  while (poll(fds, 2, -1) < 0) {
    if (errno != EINTR) throw InputError(source_ + ": cannot wait for input: " + LineReaderErrno());
  }
}

LineReader::Result LineReader::Next(std::string_view* line) {
  while (true) {
    if (stopped_ || (stop_ && stop_->requested())) return Result::kStopped;
    const std::size_t pending = end_ - begin_;
    const char* start = buffer_.data() + begin_;
    const void* newline = pending > scanned_ ? std::memchr(start + scanned_, '\n', pending - scanned_) : nullptr;
    if (newline != nullptr) {
      std::size_t length = static_cast<std::size_t>(static_cast<const char*>(newline) - start);
      begin_ += length + 1;
      scanned_ = 0;
      if (dropping_) {  // the end of a line already reported as too long
        dropping_ = false;
        continue;
      }
      ++line_number_;
      // Every line handed out was completed by the last read: a read happens only when no
      // complete line is buffered.
      line_time_ = read_time_;
      if (length > max_line_bytes_) return Result::kTooLong;
      if (length > 0 && start[length - 1] == '\r') --length;
      *line = std::string_view(start, length);
      return Result::kLine;
    }
    scanned_ = pending;
    if (dropping_) {  // the rest of a line already reported: dropped as it comes
      begin_ = end_ = scanned_ = 0;
    } else if (scanned_ > max_line_bytes_) {
      // Reported as soon as it is too long, not at its newline: a line that never ends (a stream
      // of zeros) would otherwise be read for ever. Its rest is dropped up to its newline.
      dropping_ = true;
      begin_ = end_ = scanned_ = 0;
      ++line_number_;
      line_time_ = read_time_;
      return Result::kTooLong;
    }
    if (at_end_) {
      if (end_ == begin_) return Result::kEnd;
      // The last line, without a newline.
      std::size_t length = end_ - begin_;
      begin_ = end_;
      scanned_ = 0;
      ++line_number_;
      line_time_ = read_time_;
      if (length > 0 && start[length - 1] == '\r') --length;
      *line = std::string_view(start, length);
      return Result::kLine;
    }
    Fill();
  }
}

}  // namespace rpt::io
