// SPDX-License-Identifier: MIT
#include "metrics/timing.h"

#include <gtest/gtest.h>

namespace rpt::metrics {
namespace {

TEST(Median, OddEvenAndEmpty) {
  EXPECT_EQ(Median({}), 0.0);
  EXPECT_EQ(Median({3, 1, 2}), 2.0);
  EXPECT_EQ(Median({4, 1, 3, 2}), 2.5);
}

TEST(TimingAccumulator, MediansMeansFpsAndWarmup) {
  TimingAccumulator timing(/*warmup_frames=*/1);
  for (double t : {1000.0, 10.0, 20.0, 30.0, 100.0}) {
    FrameStats stats;
    stats.total_us = t;
    stats.time_us[static_cast<int>(Step::kMerge)] = t / 10;
    timing.Add(stats);
  }
  const TimingSummary s = timing.Finalize();
  EXPECT_EQ(s.frames, 4) << "the warm-up frame is ignored";
  EXPECT_DOUBLE_EQ(s.frame_us_median, 25.0);
  EXPECT_DOUBLE_EQ(s.frame_us_mean, 40.0);
  EXPECT_DOUBLE_EQ(s.fps, 1e6 / 40.0);
  EXPECT_DOUBLE_EQ(s.step_us_median[static_cast<int>(Step::kMerge)], 2.5);
  EXPECT_DOUBLE_EQ(s.frame_us_p90, 100.0);
  TimingAccumulator other;
  FrameStats one;
  one.total_us = 5;
  other.Add(one);
  timing.Merge(other);
  EXPECT_EQ(timing.Finalize().frames, 5);
}

}  // namespace
}  // namespace rpt::metrics
