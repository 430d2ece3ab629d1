// SPDX-License-Identifier: MIT
#include "metrics/step_counts.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace rpt::metrics {
namespace {

FrameStats Frame(int poses, int persons, int filled, double noise_m) {
  FrameStats stats;
  stats.count[static_cast<int>(Step::kUndistort)] = poses;
  stats.count[static_cast<int>(Step::kMerge)] = persons;
  stats.filled_joints = filled;
  stats.noise_m = noise_m;
  return stats;
}

TEST(StepCountAccumulator, MeansPerFrameAndMedianNoiseOverFramesWithAnEstimate) {
  StepCountAccumulator counts;
  counts.Add(Frame(10, 2, 0, 0.0));
  counts.Add(Frame(12, 3, 4, 0.010));
  counts.Add(Frame(14, 4, 2, 0.030));
  StepCountAccumulator other;
  other.Add(Frame(0, 0, 0, 0.020));
  counts.Merge(other);
  const StepCountSummary s = counts.Finalize();
  EXPECT_EQ(s.frames, 4);
  EXPECT_DOUBLE_EQ(s.count_per_frame[static_cast<int>(Step::kUndistort)], 9.0);
  EXPECT_DOUBLE_EQ(s.count_per_frame[static_cast<int>(Step::kMerge)], 2.25);
  EXPECT_DOUBLE_EQ(s.count_per_frame[static_cast<int>(Step::kTrack)], 0.0);
  EXPECT_EQ(kCounterNames[7], "filled_joints");
  EXPECT_DOUBLE_EQ(s.counter_per_frame[7], 1.5);
  EXPECT_EQ(s.noise_frames, 3) << "frames with noise_m = 0 (fixed scale) have no estimate";
  EXPECT_DOUBLE_EQ(s.noise_m_median, 0.020);
}

TEST(StepCountAccumulator, NoFramesGiveZeros) {
  const StepCountSummary s = StepCountAccumulator().Finalize();
  EXPECT_EQ(s.frames, 0);
  EXPECT_EQ(s.noise_frames, 0);
  EXPECT_EQ(s.noise_m_median, 0.0);
}

TEST(StepCountAccumulator, CountersFollowTheirNames) {
  FrameStats stats;
  stats.pruned_limbs = 1;
  stats.small_groups = 2;
  stats.conflicting_proposals = 3;
  stats.mirrored_groups = 4;
  stats.unsupported_persons = 5;
  stats.single_view_persons = 6;
  stats.replaced_joints = 7;
  stats.filled_joints = 8;
  stats.new_tracks = 9;
  stats.coasting_tracks = 10;
  stats.bone_length_corrections = 11;
  stats.single_view_implausible = 12;
  stats.single_view_tracked = 13;
  stats.held_joints = 14;
  stats.one_view_joints = 15;
  stats.duplicate_persons = 16;
  const auto counters = Counters(stats);
  for (int c = 0; c < kNumCounters; ++c) EXPECT_EQ(counters[c], c + 1) << kCounterNames[c];
}

TEST(StepCountAccumulator, CounterTotalIsTheSumOverTheFrames) {
  StepCountAccumulator accumulator;
  for (const int started : {2, 0, 1}) {
    FrameStats stats;
    stats.new_tracks = started;
    stats.coasting_tracks = 1;
    accumulator.Add(stats);
  }
  const StepCountSummary summary = accumulator.Finalize();
  EXPECT_EQ(CounterTotal(summary, "new_tracks"), 3);
  EXPECT_EQ(CounterTotal(summary, "coasting_tracks"), 3);
  EXPECT_THROW(CounterTotal(summary, "new_track"), std::logic_error);
}

}  // namespace
}  // namespace rpt::metrics
