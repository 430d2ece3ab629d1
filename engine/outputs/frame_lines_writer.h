// SPDX-License-Identifier: MIT
// The live output of `rpt triangulate --follow` (docs/own_data.md, "Live input"): JSON lines on a
// file descriptor (standard output), each written as soon as its frame is triangulated (by one
// write(), or with a StopRequest in writes of at most PIPE_BUF bytes), so a reader at the other end
// of a pipe gets every frame at once:
//   {"joints": [...], "units": {"position": "m", "time": "s", "score": "1"}, "provenance_names": [...], "sequence":
//   "...", "fps": F or null}
//   {"id": "...", "time": t, "persons": [...], "track_ids": [...], "provenance": [...]}   one per frame
// The frame objects are predictions.json's (engine/outputs/frame_json.h). The line buffer is
// reused: a warm writer allocates nothing. For one sequence at a time (a live input has one).
//
// With a StopRequest (Ctrl-C), a reader that does not take the output cannot hold the process: the
// writer waits for the output to be writable (poll) and writes at most PIPE_BUF bytes at a time,
// so it never blocks inside write(); once a stop is requested it gives a blocked line
// `stop_grace_s` more, then gives up: that line and the ones after are not written (the line
// given up may be cut if part of it was taken), said by abandoned() and cut_bytes().
#pragma once

#include <memory>
#include <string>

#include "datasets/io/line_reader.h"
#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"

namespace rpt::engine {

class FrameLinesWriter final : public FrameSink {
 public:
  // Writes to `fd` (not closed); `name` names it in messages ("stdout").
  FrameLinesWriter(int fd, std::string name, ExportOptions options = {},
                   std::shared_ptr<const io::StopRequest> stop = nullptr, double stop_grace_s = 2.0);

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int) override {}

  long lines() const { return lines_; }
  // A stop was requested while the output did not drain: the lines from the one given up on were
  // not written; of that one, cut_bytes() bytes were (0: no line is cut).
  bool abandoned() const { return abandoned_; }
  long cut_bytes() const { return cut_bytes_; }

 private:
  // Writes line_ and a newline; throws InputError naming the output when it cannot.
  void WriteLine();

  int fd_;
  std::string name_;
  ExportOptions options_;
  std::string line_;
  long lines_ = 0;
  std::shared_ptr<const io::StopRequest> stop_;
  double stop_grace_s_ = 2.0;
  bool abandoned_ = false;
  long cut_bytes_ = 0;
};

}  // namespace rpt::engine
