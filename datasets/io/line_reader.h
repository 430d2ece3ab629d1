// SPDX-License-Identifier: MIT
// Lines of a stream read as they arrive (standard input, a named pipe, a file), for input that is
// written while rpt reads it (`rpt triangulate --follow`, datasets/readers/detection_lines.h).
// A line is handed out as soon as its newline has been read; reading waits in poll() on the
// stream and on a StopRequest, so another thread (the interrupt handler, cli/interrupt.h) can end
// the wait at any time. With a spin time (set_spin) the reader first polls without sleeping for up
// to that long after each read, so a line that follows soon is taken without the wake-up of a
// sleeping thread (slow on an idle machine; `rpt triangulate --follow --spin-us`). At the end of a
// regular file the reader can wait for the file to grow (set_wait_at_end: a detector still writing
// it, like `tail -f`), woken by inotify when the file is written. Memory is bounded: the buffer
// holds at most one line of max_line_bytes plus one read; a longer line is reported as too long as
// soon as it passes the limit (a line that never ends is not read for ever), and its rest is
// dropped up to its newline.
#pragma once

#include <poll.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace rpt::io {

// A request to stop reading, made from any thread: wakes a LineReader waiting for input.
class StopRequest {
 public:
  StopRequest();  // throws InputError when the process is out of file descriptors
  ~StopRequest();
  StopRequest(const StopRequest&) = delete;
  StopRequest& operator=(const StopRequest&) = delete;

  // Safe to call from any thread, any number of times.
  void Request();
  bool requested() const;
  // Readable once requested (for poll()).
  int fd() const { return read_fd_; }

 private:
  int read_fd_ = -1, write_fd_ = -1;
  std::atomic<bool> requested_{false};
};

class LineReader {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Result {
    kLine,     // a line (without its "\n" or "\r\n")
    kTooLong,  // a line longer than max_line_bytes: reported once it passes the limit; its rest is dropped
    kEnd,      // end of the stream (a last line without "\n" is handed out before)
    kStopped,  // the StopRequest was made
  };

  // Opens `path` for reading: "-" is standard input; else a file or a named pipe (opening a pipe
  // does not wait for its writer: reading does, and a stop request ends that wait). `source` is
  // "stdin" or the path. Throws InputError naming the path when it cannot be opened or is a folder.
  // `stop` may be null.
  LineReader(const std::string& path, std::size_t max_line_bytes, std::shared_ptr<const StopRequest> stop);
  // Reads the file descriptor `fd` (not closed by the reader), named `source` in messages.
  LineReader(int fd, std::string source, std::size_t max_line_bytes, std::shared_ptr<const StopRequest> stop);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // The next line in *line, valid until the next call. Throws InputError naming the source when
  // reading fails.
  Result Next(std::string_view* line);

  // Polls for input without sleeping for up to `spin` before each wait (zero: sleep at once).
  void set_spin(std::chrono::microseconds spin) { spin_ = spin; }
  // At the end of a regular file, waits up to `idle` seconds (infinity: until the stop request)
  // for it to grow before the end: lines appended meanwhile are read, and a last line without a
  // newline waits for its newline. Zero (the default): the file's end is the end. No effect on a
  // pipe or a terminal (their end is the writer closing them). A file that shrinks while waited
  // on (truncated) is an InputError.
  void set_wait_at_end(std::chrono::duration<double> idle) { wait_at_end_ = idle; }
  // Whether the stream is a regular file (set_wait_at_end applies).
  bool regular_file() const { return regular_file_; }

  const std::string& source() const { return source_; }
  // The number of the line handed out last (1-based; too-long lines count).
  long line_number() const { return line_number_; }
  // When the last line handed out was read (its newline arrived): the start of its latency.
  Clock::time_point line_time() const { return line_time_; }

 private:
  // Waits for input and reads once more into the buffer; sets at_end_ or stopped_ instead.
  void Fill();
  // Waits until the stream or the stop request is readable: polls for up to spin_, then sleeps.
  void Wait(pollfd* fds);
  // At the end of a regular file: waits for it to grow (true: read again), for the stop request
  // (sets stopped_) or until wait_at_end_ has passed since the last data (false: the end).
  bool WaitForGrowth();

  bool regular_file_ = false;
  std::chrono::duration<double> wait_at_end_{0};
  int watch_fd_ = -1;  // inotify on the file while waiting at its end (-1: none, or polling)
  bool watch_tried_ = false;
  int fd_ = -1;
  bool owns_fd_ = false;
  std::string source_;
  std::size_t max_line_bytes_;
  std::shared_ptr<const StopRequest> stop_;
  std::chrono::microseconds spin_{0};
  std::string buffer_;
  std::size_t begin_ = 0;  // the unconsumed bytes are buffer_[begin_, end_)
  std::size_t end_ = 0;
  std::size_t scanned_ = 0;  // bytes from begin_ known to hold no newline
  bool at_end_ = false;
  bool stopped_ = false;
  bool dropping_ = false;  // inside a too-long line, up to its newline
  long line_number_ = 0;
  Clock::time_point read_time_{}, line_time_{};
};

}  // namespace rpt::io
