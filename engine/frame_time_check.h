// SPDX-License-Identifier: MIT
// The times of one sequence's frames as they pass the triangulator: steps back (tracks end
// there and start anew) and steps that look like a video's frame times in milliseconds read as
// seconds (every track then ends after one frame). engine::Run and Python's Triangulator warn
// with them.
#pragma once

#include <string>
#include <vector>

#include "datasets/input_warnings.h"

namespace rpt::engine {

class FrameTimeCheck {
 public:
  // Steps longer than `max_gap_s` (track.max_gap_s) end every track. Reserves the step sample
  // once: Add allocates nothing.
  explicit FrameTimeCheck(double max_gap_s);

  // The next frame's time (s); unknown (not finite) times are skipped.
  void Add(double timestamp_s);

  // The unit the times look like, read as seconds: most steps beyond max_gap_s, regular (their
  // median absolute deviation within a tenth of the median) and of a camera's frame interval (14 to
  // 200 frames per second) in milliseconds (5-70), microseconds (5e3-7e4) or nanoseconds (5e6-7e7),
  // or, with a known frame rate (fps > 0), within a tenth of 1000 / fps, 1e6 / fps or 1e9 / fps.
  // Else seconds: images sampled seconds apart (MVOR's, every 75 s, are as regular) end every track
  // all the same, as they should; milliseconds of a camera below 14 frames per second cannot be
  // told from such images without the frame rate. Needs 3 steps at least.
  enum class Unit { kSeconds, kMilliseconds, kMicroseconds, kNanoseconds };
  Unit LikelyUnit(double fps) const;

  // The sequence's warnings under `source`: frames whose time is not after the previous one, times
  // in another unit (LikelyUnit), and pauses: a minority of steps beyond max_gap_s in seconds (a
  // stalled detector or camera; every track ends there, so the persons after it get new ids).
  // When most steps are beyond it the frames are images sampled seconds apart (MVOR's): not a pause.
  void AddWarnings(const std::string& source, double fps, InputWarnings* warnings) const;
  // Each alone.
  void AddStepBackWarning(const std::string& source, InputWarnings* warnings) const;
  void AddUnitWarning(const std::string& source, double fps, InputWarnings* warnings) const;
  void AddPauseWarning(const std::string& source, double fps, InputWarnings* warnings) const;

  // Warnings as they happen, for a run whose end may be hours away (a live stream, Python's
  // process()): a time not after the last at once, the unit when the 10th, 100th and 1000th step
  // are looked at (LikelyUnit sorts its sample: not every frame); each once. Call after Add.
  void AddEarlyWarnings(const std::string& source, double fps, InputWarnings* warnings);

  long steps() const { return steps_; }                        // forward steps between known times
  long times_not_after() const { return times_not_after_; }    // frames whose time is not after the last

 private:
  static constexpr size_t kStepSample = 1000;  // the first steps, for the medians

  double max_gap_s_;
  double last_time_s_;
  long times_not_after_ = 0;
  double largest_step_back_s_ = 0;
  long steps_ = 0, steps_beyond_gap_ = 0;
  double largest_step_s_ = 0;
  std::vector<double> step_sample_;
  bool warned_step_back_ = false, warned_unit_ = false;  // AddEarlyWarnings
};

}  // namespace rpt::engine
