// SPDX-License-Identifier: MIT
#include "engine/outputs/frame_lines_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "datasets/io/json_output.h"
#include "engine/outputs/frame_json.h"

namespace rpt::engine {

FrameLinesWriter::FrameLinesWriter(int fd, std::string name, ExportOptions options)
    : fd_(fd), name_(std::move(name)), options_(std::move(options)) {}

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
  line_.push_back('\n');
  const char* data = line_.data();
  size_t left = line_.size();
  while (left > 0) {
    const ssize_t written = write(fd_, data, left);
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
