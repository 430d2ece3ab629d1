// SPDX-License-Identifier: MIT
// Timing statistics over frames: per-step and per-frame medians (robust to scheduler noise),
// means, and FPS = 1e6 / mean frame time (mean of times, not mean of per-frame FPS).
#pragma once

#include <array>
#include <vector>

#include "core/pipeline/frame_stats.h"

namespace rpt::metrics {

struct TimingSummary {
  int frames = 0;
  double frame_us_median = 0;
  double frame_us_mean = 0;
  double frame_us_p90 = 0;
  double fps = 0;  // 1e6 / frame_us_mean
  std::array<double, kNumSteps> step_us_median{};
  std::array<double, kNumSteps> step_us_mean{};
};

class TimingAccumulator {
 public:
  // `warmup_frames` first frames are ignored (cold caches, first allocations).
  explicit TimingAccumulator(int warmup_frames = 0) : warmup_frames_(warmup_frames) {}
  void Add(const FrameStats& stats);
  // Appends another accumulator's frames (e.g. from parallel runs over sequences).
  void Merge(const TimingAccumulator& other);
  TimingSummary Finalize() const;

 private:
  int warmup_frames_;
  int seen_ = 0;
  std::vector<double> frame_us_;
  std::array<std::vector<double>, kNumSteps> step_us_;
};

// Median of `values` (mean of the middle two for even counts); 0 for none.
double Median(std::vector<double> values);

}  // namespace rpt::metrics
