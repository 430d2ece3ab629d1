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
  EXPECT_DOUBLE_EQ(s.fps, 1e6 / 25.0) << "FPS from the median frame time, not the mean";
  EXPECT_DOUBLE_EQ(s.step_us_median[static_cast<int>(Step::kMerge)], 2.5);
  EXPECT_DOUBLE_EQ(s.frame_us_p90, 100.0);
  TimingAccumulator other;
  FrameStats one;
  one.total_us = 5;
  other.Add(one);
  timing.Merge(other);
  EXPECT_EQ(timing.Finalize().frames, 5);
}

// The reader's grouping time (SequenceFrame::paf_grouping_us): summarised over the frames that
// have one, after the same warm-up, and added to the frame time in frame_with_grouping.
TEST(TimingAccumulator, ReaderGroupingOverTheFramesThatHaveOne) {
  TimingAccumulator timing(/*warmup_frames=*/1);
  const double totals[] = {1000, 10, 20, 30, 40};
  const double grouping[] = {500, 4, 6, -1, 11};
  for (int f = 0; f < 5; ++f) {
    FrameStats stats;
    stats.total_us = totals[f];
    timing.Add(stats, grouping[f]);
  }
  const TimingSummary s = timing.Finalize();
  EXPECT_EQ(s.frames, 4);
  EXPECT_EQ(s.paf_grouping_frames, 3) << "the warm-up frame and the frame without grouping are not counted";
  EXPECT_DOUBLE_EQ(s.paf_grouping_us_median, 6.0);
  EXPECT_DOUBLE_EQ(s.paf_grouping_us_mean, 7.0);
  EXPECT_DOUBLE_EQ(s.frame_with_grouping_us_median, 26.0);  // 14, 26, 51
  EXPECT_DOUBLE_EQ(s.frame_with_grouping_us_mean, 91.0 / 3);
  EXPECT_DOUBLE_EQ(s.frame_us_median, 25.0) << "the pipeline's frame time does not include the grouping";
  TimingAccumulator other;
  FrameStats one;
  one.total_us = 5;
  other.Add(one, 2);
  timing.Merge(other);
  EXPECT_EQ(timing.Finalize().paf_grouping_frames, 4);
  EXPECT_DOUBLE_EQ(timing.Finalize().paf_grouping_us_mean, 23.0 / 4);

  TimingAccumulator none;
  FrameStats stats;
  stats.total_us = 3;
  none.Add(stats);
  EXPECT_EQ(none.Finalize().paf_grouping_frames, 0);
}

}  // namespace
}  // namespace rpt::metrics
