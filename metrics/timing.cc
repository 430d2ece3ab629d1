// SPDX-License-Identifier: MIT
#include "metrics/timing.h"

#include <algorithm>

namespace rpt::metrics {
namespace {

// The range of the time histograms: [0.01 us, 100 s).
constexpr double kMinTimeUs = 0.01;
constexpr int kTimeDecades = 10;

}  // namespace

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + mid);
  return 0.5 * (lower + upper);
}

TimingAccumulator::TimingAccumulator(int warmup_frames)
    : warmup_frames_(warmup_frames),
      frame_us_(kMinTimeUs, kTimeDecades),
      step_us_(kNumSteps, LogHistogram(kMinTimeUs, kTimeDecades)),
      grouping_us_(kMinTimeUs, kTimeDecades),
      frame_with_grouping_us_(kMinTimeUs, kTimeDecades) {}

void TimingAccumulator::Add(const FrameStats& stats, double paf_grouping_us) {
  if (seen_++ < warmup_frames_) return;
  if (paf_grouping_us >= 0) {
    grouping_us_sum_ += paf_grouping_us;
    frame_with_grouping_us_sum_ += stats.total_us + paf_grouping_us;
    grouping_us_.Add(paf_grouping_us);
    frame_with_grouping_us_.Add(stats.total_us + paf_grouping_us);
  }
  frame_us_sum_ += stats.total_us;
  frame_us_.Add(stats.total_us);
  for (int s = 0; s < kNumSteps; ++s) {
    step_us_sum_[s] += stats.time_us[s];
    step_us_[s].Add(stats.time_us[s]);
  }
}

void TimingAccumulator::Merge(const TimingAccumulator& other) {
  frame_us_sum_ += other.frame_us_sum_;
  frame_us_.Merge(other.frame_us_);
  for (int s = 0; s < kNumSteps; ++s) {
    step_us_sum_[s] += other.step_us_sum_[s];
    step_us_[s].Merge(other.step_us_[s]);
  }
  grouping_us_sum_ += other.grouping_us_sum_;
  frame_with_grouping_us_sum_ += other.frame_with_grouping_us_sum_;
  grouping_us_.Merge(other.grouping_us_);
  frame_with_grouping_us_.Merge(other.frame_with_grouping_us_);
}

TimingSummary TimingAccumulator::Finalize() const {
  TimingSummary summary;
  summary.frames = static_cast<int>(frame_us_.count());
  if (summary.frames == 0) return summary;
  summary.frame_us_median = frame_us_.Median();
  summary.frame_us_mean = frame_us_sum_ / summary.frames;
  summary.frame_us_p90 = frame_us_.Quantile(0.9);
  // From the median, not the mean: one slow frame (a page fault, the other process on a shared
  // core, the first frame before the pre-filter has persons) moves the mean of a short run by
  // a factor, the median hardly at all.
  summary.fps = summary.frame_us_median > 0 ? 1e6 / summary.frame_us_median : 0;
  for (int s = 0; s < kNumSteps; ++s) {
    summary.step_us_median[s] = step_us_[s].Median();
    summary.step_us_mean[s] = step_us_sum_[s] / summary.frames;
  }
  summary.paf_grouping_frames = static_cast<int>(grouping_us_.count());
  if (summary.paf_grouping_frames > 0) {
    summary.paf_grouping_us_median = grouping_us_.Median();
    summary.paf_grouping_us_mean = grouping_us_sum_ / summary.paf_grouping_frames;
    summary.frame_with_grouping_us_median = frame_with_grouping_us_.Median();
    summary.frame_with_grouping_us_mean = frame_with_grouping_us_sum_ / summary.paf_grouping_frames;
  }
  return summary;
}

}  // namespace rpt::metrics
