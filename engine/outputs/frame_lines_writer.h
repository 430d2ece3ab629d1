// SPDX-License-Identifier: MIT
// The live output of `rpt triangulate --follow` (docs/own_data.md, "Live input"): JSON lines on a
// file descriptor (standard output), each written whole by one write() as soon as its frame is
// triangulated, so a reader at the other end of a pipe gets every frame at once:
//   {"joints": [...], "units": {"position": "m", "time": "s", "score": "1"}, "provenance_names": [...], "sequence":
//   "...", "fps": F or null}
//   {"id": "...", "time": t, "persons": [...], "track_ids": [...], "provenance": [...]}   one per frame
// The frame objects are predictions.json's (engine/outputs/frame_json.h). The line buffer is
// reused: a warm writer allocates nothing. For one sequence at a time (a live input has one).
#pragma once

#include <string>

#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"

namespace rpt::engine {

class FrameLinesWriter final : public FrameSink {
 public:
  // Writes to `fd` (not closed); `name` names it in messages ("stdout").
  FrameLinesWriter(int fd, std::string name, ExportOptions options = {});

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int) override {}

  long lines() const { return lines_; }

 private:
  // Writes line_ and a newline; throws InputError naming the output when it cannot.
  void WriteLine();

  int fd_;
  std::string name_;
  ExportOptions options_;
  std::string line_;
  long lines_ = 0;
};

}  // namespace rpt::engine
