// SPDX-License-Identifier: MIT
// The unit frame times look like when read as seconds (engine/frame_time_check.h): a camera's
// frame interval in milliseconds, microseconds or nanoseconds, not images sampled seconds apart.
#include "engine/frame_time_check.h"

#include <gtest/gtest.h>

#include <string>

namespace rpt::engine {
namespace {

using Unit = FrameTimeCheck::Unit;

// `frames` times `step` apart from `start` (as the input wrote them, read as seconds).
FrameTimeCheck Steps(double start, double step, int frames) {
  FrameTimeCheck check(1.0);
  for (int f = 0; f < frames; ++f) check.Add(start + step * f);
  return check;
}

TEST(FrameTimeCheck, TellsTheUnitOfACamerasFrameInterval) {
  EXPECT_EQ(Steps(0, 0.04, 50).LikelyUnit(0), Unit::kSeconds);
  EXPECT_EQ(Steps(0, 40, 50).LikelyUnit(0), Unit::kMilliseconds);         // 25 frames/s in ms
  EXPECT_EQ(Steps(0, 40000, 50).LikelyUnit(0), Unit::kMicroseconds);      // ... in us (it said nothing)
  EXPECT_EQ(Steps(1.7e18, 4e7, 50).LikelyUnit(0), Unit::kNanoseconds);    // epoch ns (time.time_ns())
  EXPECT_EQ(Steps(0, 75, 50).LikelyUnit(0), Unit::kSeconds) << "MVOR: images 75 s apart";
  EXPECT_EQ(Steps(0, 100, 50).LikelyUnit(0), Unit::kSeconds) << "10 frames/s in ms: not told from images without fps";
  EXPECT_EQ(Steps(0, 100, 50).LikelyUnit(10), Unit::kMilliseconds);
  EXPECT_EQ(Steps(0, 1e5, 50).LikelyUnit(10), Unit::kMicroseconds);
  EXPECT_EQ(Steps(0, 1e8, 50).LikelyUnit(10), Unit::kNanoseconds);
  EXPECT_EQ(Steps(0, 40, 3).LikelyUnit(0), Unit::kSeconds) << "2 steps: too few";
  FrameTimeCheck irregular(1.0);
  for (const double t : {0.0, 40.0, 200.0, 230.0, 600.0, 610.0, 900.0}) irregular.Add(t);
  EXPECT_EQ(irregular.LikelyUnit(0), Unit::kSeconds);
}

TEST(FrameTimeCheck, TheWarningNamesTheUnit) {
  InputWarnings warnings;
  Steps(0, 40000, 20).AddWarnings("stdin", 0, &warnings);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_NE(warnings.items()[0].Line().find("19 frames more than track.max_gap_s (1.0 s) after the previous frame, at "
                                            "regular steps of microseconds' size: are the times in microseconds?"),
            std::string::npos)
      << warnings.items()[0].Line();
  InputWarnings none;
  Steps(0, 0.04, 20).AddWarnings("stdin", 0, &none);
  EXPECT_TRUE(none.items().empty());
}

// A stream at 25 frames/s that pauses twice (3 s, then 1.5 s): every track ended at each pause,
// said and counted (the track ids changed with no word); images sampled seconds apart (most steps
// beyond the gap) are no pause, and a pause of exactly max_gap_s ends nothing.
TEST(FrameTimeCheck, PausesLongerThanTheGapAreCounted) {
  FrameTimeCheck paused(1.0);
  double t = 0;
  for (int f = 0; f < 100; ++f) {
    t += f == 40 ? 3.0 : f == 70 ? 1.5 : 0.04;
    paused.Add(t);
  }
  InputWarnings warnings;
  paused.AddWarnings("stdin", 0, &warnings);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].Line(),
            "stdin: 2 pauses of more than track.max_gap_s (1.0 s) between frames (every track ended there: the persons "
            "after a pause got new track ids) (longest in s = 3)");
  InputWarnings sampled;
  Steps(0, 75, 20).AddWarnings("mvor", 0, &sampled);
  EXPECT_TRUE(sampled.items().empty()) << sampled.items()[0].Line();
  FrameTimeCheck exact(1.0);
  for (const double time : {0.0, 0.04, 1.04, 1.08}) exact.Add(time);
  InputWarnings at_gap;
  exact.AddWarnings("stdin", 0, &at_gap);
  EXPECT_TRUE(at_gap.items().empty()) << at_gap.items()[0].Line();
}

}  // namespace
}  // namespace rpt::engine
