// SPDX-License-Identifier: MIT
#include "metrics/step_counts.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rpt::metrics {

std::array<int, kNumCounters> Counters(const FrameStats& stats) {
  return {stats.pruned_limbs,        stats.small_groups,        stats.conflicting_proposals, stats.mirrored_groups,
          stats.unsupported_persons, stats.single_view_persons, stats.replaced_joints,       stats.filled_joints,
          stats.new_tracks,          stats.coasting_tracks,     stats.bone_length_corrections,
          stats.single_view_implausible, stats.single_view_tracked, stats.held_joints,
          stats.one_view_joints,     stats.duplicate_persons};
}

void StepCountAccumulator::Add(const FrameStats& stats) {
  ++frames_;
  for (int s = 0; s < kNumSteps; ++s) count_sum_[s] += stats.count[s];
  const std::array<int, kNumCounters> counters = Counters(stats);
  for (int c = 0; c < kNumCounters; ++c) counter_sum_[c] += counters[c];
  if (stats.noise_m > 0) noise_m_.Add(stats.noise_m);
}

void StepCountAccumulator::Merge(const StepCountAccumulator& other) {
  frames_ += other.frames_;
  for (int s = 0; s < kNumSteps; ++s) count_sum_[s] += other.count_sum_[s];
  for (int c = 0; c < kNumCounters; ++c) counter_sum_[c] += other.counter_sum_[c];
  noise_m_.Merge(other.noise_m_);
}

StepCountSummary StepCountAccumulator::Finalize() const {
  StepCountSummary summary;
  summary.frames = frames_;
  if (frames_ == 0) return summary;
  for (int s = 0; s < kNumSteps; ++s) summary.count_per_frame[s] = count_sum_[s] / frames_;
  for (int c = 0; c < kNumCounters; ++c) summary.counter_per_frame[c] = counter_sum_[c] / frames_;
  summary.noise_frames = noise_m_.count();
  summary.noise_m_median = noise_m_.Median();
  return summary;
}

long CounterTotal(const StepCountSummary& counts, std::string_view name) {
  const auto it = std::find(kCounterNames.begin(), kCounterNames.end(), name);
  if (it == kCounterNames.end()) throw std::logic_error("CounterTotal: no counter " + std::string(name));
  return std::lround(counts.counter_per_frame[static_cast<size_t>(it - kCounterNames.begin())] *
                     static_cast<double>(counts.frames));
}

}  // namespace rpt::metrics
