// SPDX-License-Identifier: MIT
#include "datasets/io/line_reader.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/errors.h"

namespace rpt::io {
namespace {

// Bytes asked of one read(): a frame line of a few cameras fits, and a burst of lines is taken in
// few calls.
constexpr std::size_t kReadBytes = 64 * 1024;

std::string LineReaderErrno() { return std::strerror(errno); }

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
}

LineReader::LineReader(int fd, std::string source, std::size_t max_line_bytes, std::shared_ptr<const StopRequest> stop)
    : fd_(fd), source_(std::move(source)), max_line_bytes_(max_line_bytes), stop_(std::move(stop)) {}

LineReader::~LineReader() {
  if (owns_fd_) close(fd_);
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
      ++line_number_;
      // Every line handed out was completed by the last read: a read happens only when no
      // complete line is buffered.
      line_time_ = read_time_;
      if (dropping_ || length > max_line_bytes_) {
        dropping_ = false;
        return Result::kTooLong;
      }
      if (length > 0 && start[length - 1] == '\r') --length;
      *line = std::string_view(start, length);
      return Result::kLine;
    }
    scanned_ = pending;
    if (dropping_ || scanned_ > max_line_bytes_) {  // a line too long to keep: drop what came of it
      dropping_ = true;
      begin_ = end_ = scanned_ = 0;
    }
    if (at_end_) {
      if (dropping_) {
        dropping_ = false;
        ++line_number_;
        line_time_ = read_time_;
        return Result::kTooLong;
      }
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
