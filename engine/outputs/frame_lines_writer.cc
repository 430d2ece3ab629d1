// SPDX-License-Identifier: MIT
#include "engine/outputs/frame_lines_writer.h"

#include <limits.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "datasets/io/json_output.h"
#include "engine/outputs/frame_json.h"

namespace rpt::engine {

FrameLinesWriter::FrameLinesWriter(int fd, std::string name, ExportOptions options,
                                   std::shared_ptr<const io::StopRequest> stop, double stop_grace_s)
    : fd_(fd), name_(std::move(name)), options_(std::move(options)), stop_(std::move(stop)), stop_grace_s_(stop_grace_s) {}

void FrameLinesWriter::BeginSequence(int, const SequenceHeader& header, const JointNames& output_joints) {
  using Json = nlohmann::json;
  line_ = "{\"joints\": " + io::DumpJson(Json(output_joints)) +
          ", \"units\": {\"position\": \"m\", \"time\": \"s\", \"score\": \"1\"}, \"provenance_names\": " +
          io::DumpJson(Json(ProvenanceNames())) + ", \"sequence\": " + io::DumpJson(Json(header.name)) +
          ", \"fps\": " + (header.fps > 0 ? io::DumpJson(Json(header.fps)) : std::string("null")) + "}";
  WriteLine();
}

void FrameLinesWriter::Frame(const FrameOutput& frame) {
  line_.clear();
  AppendFrameJson(frame, options_, &line_);
  WriteLine();
}

void FrameLinesWriter::WriteLine() {
  if (abandoned_) return;
  line_.push_back('\n');
  const char* data = line_.data();
  size_t left = line_.size();
  std::chrono::steady_clock::time_point stopped_at{};
  while (left > 0) {
    if (stop_ != nullptr) {
      // Wait until the output takes PIPE_BUF bytes, or a stop is requested; after the request, at
      // most stop_grace_s_ more (a slow reader still gets the line, a stalled one cannot hold us).
      pollfd fds[2] = {{fd_, POLLOUT, 0}, {stop_->fd(), POLLIN, 0}};
      int timeout_ms = -1;
      if (stop_->requested()) {
        const auto now = std::chrono::steady_clock::now();
        if (stopped_at == std::chrono::steady_clock::time_point{}) stopped_at = now;
        const double left_s = stop_grace_s_ - std::chrono::duration<double>(now - stopped_at).count();
        if (left_s <= 0) {
          abandoned_ = true;
          cut_bytes_ = static_cast<long>(line_.size() - left);
          return;
        }
        timeout_ms = static_cast<int>(std::ceil(left_s * 1000));
      }
      const int ready = poll(fds, stop_->requested() ? 1 : 2, timeout_ms);
      if (ready < 0 && errno != EINTR) {
        throw InputError(name_ + ": cannot wait for the output: " + std::strerror(errno));
      }
      if (ready <= 0 || (fds[0].revents & (POLLOUT | POLLERR | POLLHUP | POLLNVAL)) == 0) continue;  // write() names an error
    }
    const ssize_t written = write(fd_, data, stop_ != nullptr ? std::min<size_t>(left, PIPE_BUF) : left);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw InputError(name_ + ": cannot write the output line: " + std::strerror(errno));
    }
    data += written;
    left -= static_cast<size_t>(written);
  }
  ++lines_;
}

}  // namespace rpt::engine
