// SPDX-License-Identifier: MIT
// Progress output on stderr for long runs: silent for the first seconds, then a bar on a
// terminal or a line every 10 % otherwise (CI logs). Never writes to stdout.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "engine/input.h"

namespace rpt::cli {

class Progress {
 public:
  // `total` items; < 0: unknown (a count every 10 s instead of a bar); 0: nothing to show.
  Progress(std::string label, long total, bool enabled = true);
  ~Progress();
  void Update(long done);  // cheap; call every item

 private:
  std::string label_;
  long total_;
  bool enabled_;
  bool tty_;
  bool shown_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

// A progress display for the frames of `input` (labelled with the sequence's name when there is
// one, else "triangulating"), and the callback a run reports to (engine::RunOptions::progress).
std::unique_ptr<Progress> ProgressOf(engine::Input& input, bool enabled);
std::function<void(long)> ReportTo(Progress* progress);

}  // namespace rpt::cli
