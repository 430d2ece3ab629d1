// SPDX-License-Identifier: MIT
#include "engine/frame_time_check.h"

#include <algorithm>
#include <cmath>

#include "core/option_codec.h"
#include "datasets/sequence.h"
#include "metrics/timing.h"

namespace rpt::engine {

FrameTimeCheck::FrameTimeCheck(double max_gap_s) : max_gap_s_(max_gap_s), last_time_s_(kUnknownTime) {
  step_sample_.reserve(kStepSample);
}

void FrameTimeCheck::Add(double t) {
  if (!std::isfinite(t)) return;
  if (std::isfinite(last_time_s_) && !(t > last_time_s_)) {
    ++times_not_after_;
    largest_step_back_s_ = std::max(largest_step_back_s_, last_time_s_ - t);
  } else if (std::isfinite(last_time_s_)) {
    ++steps_;
    if (t - last_time_s_ > max_gap_s_) ++steps_beyond_gap_;
    largest_step_s_ = std::max(largest_step_s_, t - last_time_s_);
    if (step_sample_.size() < kStepSample) step_sample_.push_back(t - last_time_s_);
  }
  last_time_s_ = t;
}

FrameTimeCheck::Unit FrameTimeCheck::LikelyUnit(double fps) const {
  if (steps_ < 3 || 2 * steps_beyond_gap_ <= steps_) return Unit::kSeconds;
  const double median = metrics::Median(step_sample_);
  constexpr Unit kUnits[] = {Unit::kMilliseconds, Unit::kMicroseconds, Unit::kNanoseconds};
  constexpr double kPerSecond[] = {1e3, 1e6, 1e9};
  if (fps > 0) {
    for (int u = 0; u < 3; ++u) {
      if (std::abs(median - kPerSecond[u] / fps) <= 0.1 * kPerSecond[u] / fps) return kUnits[u];
    }
    return Unit::kSeconds;
  }
  std::vector<double> deviations = step_sample_;
  for (double& step : deviations) step = std::abs(step - median);
  if (metrics::Median(std::move(deviations)) > 0.1 * median) return Unit::kSeconds;
  for (int u = 0; u < 3; ++u) {  // 14 to 200 frames per second
    if (median >= 5e-3 * kPerSecond[u] && median <= 7e-2 * kPerSecond[u]) return kUnits[u];
  }
  return Unit::kSeconds;
}

void FrameTimeCheck::AddWarnings(const std::string& source, double fps, InputWarnings* warnings) const {
  AddStepBackWarning(source, warnings);
  AddUnitWarning(source, fps, warnings);
  AddPauseWarning(source, fps, warnings);
}

void FrameTimeCheck::AddEarlyWarnings(const std::string& source, double fps, InputWarnings* warnings) {
  if (!warned_step_back_ && times_not_after_ > 0) {
    warned_step_back_ = true;
    AddStepBackWarning(source, warnings);
  }
  if (!warned_unit_ && (steps_ == 10 || steps_ == 100 || steps_ == 1000) && LikelyUnit(fps) != Unit::kSeconds) {
    warned_unit_ = true;
    AddUnitWarning(source, fps, warnings);
  }
}

void FrameTimeCheck::AddStepBackWarning(const std::string& source, InputWarnings* warnings) const {
  warnings->Add(source, "frames whose time is not after the previous frame's (tracks end there, and start anew)",
                "largest step back in s", largest_step_back_s_, times_not_after_);
}

void FrameTimeCheck::AddPauseWarning(const std::string& source, double fps, InputWarnings* warnings) const {
  if (steps_beyond_gap_ == 0 || 2 * steps_beyond_gap_ > steps_ || LikelyUnit(fps) != Unit::kSeconds) return;
  warnings->Add(source,
                "pauses of more than track.max_gap_s (" + FormatNumber(max_gap_s_) +
                    " s) between frames (every track ended there: the persons after a pause got new track ids)",
                "longest in s", largest_step_s_, steps_beyond_gap_);
}

void FrameTimeCheck::AddUnitWarning(const std::string& source, double fps, InputWarnings* warnings) const {
  const Unit unit = LikelyUnit(fps);
  if (unit == Unit::kSeconds) return;
  const std::string name = unit == Unit::kMilliseconds   ? "milliseconds"
                           : unit == Unit::kMicroseconds ? "microseconds"
                                                         : "nanoseconds";
  warnings->Add(source,
                "frames more than track.max_gap_s (" + FormatNumber(max_gap_s_) + " s) after the previous frame, at " +
                    "regular steps of " + name + "' size: are the times in " + name +
                    "? They must be seconds; as they are, every track ends after a frame (no tracking, no smoothing)",
                "largest step in s", largest_step_s_, steps_beyond_gap_);
}

}  // namespace rpt::engine
