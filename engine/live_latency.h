// SPDX-License-Identifier: MIT
// The latency of the live output (`rpt triangulate --follow`): from the moment a frame's line was
// read (DetectionLinesCounts::frame_line_time) to the moment its output line was written, measured
// by a FrameSink placed after the writer (engine/outputs/frame_lines_writer.h) in a SinkList.
// With offline smoothing a frame is written once its window is complete: its latency then counts
// from the line that completed it. Memory does not grow with the frames (metrics/log_histogram.h).
#pragma once

#include "datasets/readers/detection_lines.h"
#include "engine/frame_sink.h"
#include "metrics/log_histogram.h"

namespace rpt::engine {

class LiveLatency final : public FrameSink {
 public:
  // `counts` is the live source's (engine/live_input.h).
  explicit LiveLatency(const DetectionLinesCounts* counts) : counts_(counts) {}

  void BeginSequence(int, const SequenceHeader&, const JointNames&) override {}
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int) override {}

  long frames() const { return us_.count(); }
  double median_us() const { return us_.Median(); }
  double p90_us() const { return us_.Quantile(0.9); }
  double max_us() const { return max_us_; }
  // What the live input adds to a frame: its latency less its triangulation time (FrameStats::total_us).
  double added_median_us() const { return added_us_.Median(); }

 private:
  const DetectionLinesCounts* counts_;
  metrics::LogHistogram us_{0.01, 10};  // [0.01 us, 100 s)
  metrics::LogHistogram added_us_{0.01, 10};
  double max_us_ = 0;
};

}  // namespace rpt::engine
