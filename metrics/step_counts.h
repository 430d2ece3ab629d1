// SPDX-License-Identifier: MIT
// What the triangulator produced per frame, step by step: the mean over frames of each step's
// item count (FrameStats::count), of the extra counters, and the median estimated detection
// noise of the adaptive score. The companion of TimingAccumulator for counts instead of times.
// Memory does not grow with frames: the means are running sums; the noise median comes from a
// LogHistogram over [1 um, 1 km) (exact for up to 64 frames with an estimate, beyond that within
// 0.48 %, metrics/log_histogram.h).
#pragma once

#include <array>
#include <string_view>

#include "core/pipeline/frame_stats.h"
#include "metrics/log_histogram.h"

namespace rpt::metrics {

// The extra counters of FrameStats, by name (the member names).
inline constexpr int kNumCounters = 16;
inline constexpr std::array<std::string_view, kNumCounters> kCounterNames = {
    "pruned_limbs",        "small_groups",        "conflicting_proposals", "mirrored_groups",
    "unsupported_persons", "single_view_persons", "replaced_joints",       "filled_joints",
    "new_tracks",          "coasting_tracks",     "bone_length_corrections", "single_view_implausible",
    "single_view_tracked", "held_joints",         "one_view_joints",       "duplicate_persons"};

struct StepCountSummary {
  long frames = 0;
  std::array<double, kNumSteps> count_per_frame{};       // mean of FrameStats::count over frames
  std::array<double, kNumCounters> counter_per_frame{};  // mean of the extra counters (kCounterNames)
  long noise_frames = 0;     // frames with an estimated detection noise (noise_m > 0)
  double noise_m_median = 0; // median of noise_m over those frames; 0 when none (fixed scale)
};

class StepCountAccumulator {
 public:
  void Add(const FrameStats& stats);
  // Appends another accumulator's frames (e.g. from parallel runs over sequences).
  void Merge(const StepCountAccumulator& other);
  StepCountSummary Finalize() const;

 private:
  long frames_ = 0;
  std::array<double, kNumSteps> count_sum_{};
  std::array<double, kNumCounters> counter_sum_{};
  LogHistogram noise_m_{1e-6, 9};  // frames with an estimate
};

// The extra counters of `stats` in kCounterNames order.
std::array<int, kNumCounters> Counters(const FrameStats& stats);

// The total of counter `name` (one of kCounterNames) over the summarised frames: its mean per
// frame times the frames, rounded (e.g. "new_tracks": the track ids a run started).
long CounterTotal(const StepCountSummary& counts, std::string_view name);

}  // namespace rpt::metrics
