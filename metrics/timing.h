// SPDX-License-Identifier: MIT
// Timing statistics over frames: per-step and per-frame medians (robust to scheduler noise),
// means, and FPS = 1e6 / mean frame time (mean of times, not mean of per-frame FPS).
//
// Memory does not grow with frames: means are exact running sums; medians and the 90th percentile
// come from a LogHistogram (metrics/log_histogram.h) per series over [0.01 us, 100 s): exact for up
// to 64 frames, beyond that interpolated inside log-spaced bins of 0.48 % relative width (error
// below 0.48 %; times under 0.01 us count as the smallest time, e.g. 0 for a step that did not run).
#pragma once

#include <array>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "metrics/log_histogram.h"

namespace rpt::metrics {

struct TimingSummary {
  int frames = 0;
  double frame_us_median = 0;
  double frame_us_mean = 0;
  double frame_us_p90 = 0;
  double fps = 0;  // 1e6 / frame_us_median
  std::array<double, kNumSteps> step_us_median{};
  std::array<double, kNumSteps> step_us_mean{};
  // The reader's part-affinity grouping (SequenceFrame::paf_grouping_us), over the frames that
  // had one (paf_grouping_frames; 0 = none: readers of ready-made persons), and per frame the
  // pipeline plus that grouping.
  int paf_grouping_frames = 0;
  double paf_grouping_us_median = 0;
  double paf_grouping_us_mean = 0;
  double frame_with_grouping_us_median = 0;
  double frame_with_grouping_us_mean = 0;
};

class TimingAccumulator {
 public:
  // `warmup_frames` first frames are ignored (cold caches, first allocations).
  explicit TimingAccumulator(int warmup_frames = 0);
  // `paf_grouping_us`: the reader's grouping time of the frame (SequenceFrame::paf_grouping_us),
  // negative = none.
  void Add(const FrameStats& stats, double paf_grouping_us = -1);
  // Appends another accumulator's frames (e.g. from parallel runs over sequences); the means add
  // the other's sums, equal to adding its frames here up to rounding.
  void Merge(const TimingAccumulator& other);
  TimingSummary Finalize() const;

 private:
  int warmup_frames_;
  int seen_ = 0;
  double frame_us_sum_ = 0;
  std::array<double, kNumSteps> step_us_sum_{};
  LogHistogram frame_us_;
  std::vector<LogHistogram> step_us_;  // one per step
  double grouping_us_sum_ = 0;
  double frame_with_grouping_us_sum_ = 0;
  LogHistogram grouping_us_;             // frames with a reader grouping only
  LogHistogram frame_with_grouping_us_;  // total_us + grouping, the same frames
};

// Median of `values` (mean of the middle two for even counts); 0 for none.
double Median(std::vector<double> values);

}  // namespace rpt::metrics
