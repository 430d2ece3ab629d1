// SPDX-License-Identifier: MIT
// Progress output on stderr for long runs: silent for the first seconds, then a bar on a
// terminal or a line every 10 % otherwise (CI logs). Never writes to stdout.
#pragma once

#include <chrono>
#include <string>

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

}  // namespace rpt::cli
