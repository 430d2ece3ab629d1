// SPDX-License-Identifier: MIT
#include "metrics/timing.h"

#include <algorithm>
#include <numeric>

namespace rpt::metrics {

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + mid);
  return 0.5 * (lower + upper);
}

namespace {
double Mean(const std::vector<double>& values) {
  return values.empty() ? 0 : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}
}  // namespace

void TimingAccumulator::Add(const FrameStats& stats) {
  if (seen_++ < warmup_frames_) return;
  frame_us_.push_back(stats.total_us);
  for (int s = 0; s < kNumSteps; ++s) step_us_[s].push_back(stats.time_us[s]);
}

void TimingAccumulator::Merge(const TimingAccumulator& other) {
  frame_us_.insert(frame_us_.end(), other.frame_us_.begin(), other.frame_us_.end());
  for (int s = 0; s < kNumSteps; ++s) {
    step_us_[s].insert(step_us_[s].end(), other.step_us_[s].begin(), other.step_us_[s].end());
  }
}

TimingSummary TimingAccumulator::Finalize() const {
  TimingSummary summary;
  summary.frames = static_cast<int>(frame_us_.size());
  if (frame_us_.empty()) return summary;
  summary.frame_us_median = Median(frame_us_);
  summary.frame_us_mean = Mean(frame_us_);
  std::vector<double> sorted = frame_us_;
  std::sort(sorted.begin(), sorted.end());
  summary.frame_us_p90 = sorted[std::min(sorted.size() - 1, static_cast<size_t>(0.9 * sorted.size()))];
  summary.fps = summary.frame_us_mean > 0 ? 1e6 / summary.frame_us_mean : 0;
  for (int s = 0; s < kNumSteps; ++s) {
    summary.step_us_median[s] = Median(step_us_[s]);
    summary.step_us_mean[s] = Mean(step_us_[s]);
  }
  return summary;
}

}  // namespace rpt::metrics
