// SPDX-License-Identifier: MIT
#include "engine/live_latency.h"

#include <algorithm>
#include <chrono>

namespace rpt::engine {

void LiveLatency::Frame(const FrameOutput& frame) {
  const double us =
      std::chrono::duration<double, std::micro>(io::LineReader::Clock::now() - counts_->frame_line_time).count();
  us_.Add(us);
  added_us_.Add(us - frame.stats->total_us);
  max_us_ = std::max(max_us_, us);
}

}  // namespace rpt::engine
