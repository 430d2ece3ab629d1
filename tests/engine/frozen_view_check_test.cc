// SPDX-License-Identifier: MIT
// engine::FrozenViewCheck: a camera whose detections repeat bit for bit while the others' change
// (a hung camera or detector) is named from kMinFrozenFrames frames on; a still scene under the
// perfect simulated detector and a shorter freeze are not.
#include "engine/frozen_view_check.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/engine/synthetic_scene.h"

namespace rpt::engine {
namespace {

using test::SyntheticScene;

// `sequence` with camera `camera` showing frame `from`'s detections in frames from..from+length-1.
Sequence Frozen(const Sequence& sequence, size_t camera, size_t from, size_t length) {
  Sequence out = sequence;
  for (size_t i = from; i < from + length && i < out.frames.size(); ++i) {
    out.frames[i].views[camera] = sequence.frames[from].views[camera];
  }
  return out;
}

std::vector<long> Longest(const Sequence& sequence) {
  FrozenViewCheck check(sequence.cameras.size());
  for (const SequenceFrame& frame : sequence.frames) check.Add(frame);
  return check.longest();
}

TEST(FrozenViewCheck, AFrozenCameraIsNamedWithHowLong) {
  const Sequence scene = SyntheticScene({"cameras=3", "people=2", "frames=300", "noise=clean"});
  EXPECT_EQ(Longest(scene), (std::vector<long>{0, 0, 0}));
  // Frames 100-249 show frame 100: 149 repeats of the frame before.
  const std::vector<long> longest = Longest(Frozen(scene, 2, 100, 150));
  EXPECT_EQ(longest, (std::vector<long>{0, 0, 149}));
  const std::vector<std::string> lines = FrozenViewWarnings("take", scene.cameras, longest, 25.0);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("take, camera 'cam2': its detections repeat the frame before, bit for bit, for 149 frames in a "
                           "row (6.0 s) while the other cameras' change: has its stream frozen",
                           0),
            0u)
      << lines[0];
  // 99 repeats: below kMinFrozenFrames.
  EXPECT_TRUE(FrozenViewWarnings("take", scene.cameras, Longest(Frozen(scene, 2, 100, 100)), 25.0).empty());
}

// The perfect detector repeats a standing person's view exactly; people wait up to 3 s. Frames
// whose every view repeats count for nothing.
TEST(FrozenViewCheck, StillPeopleUnderThePerfectDetectorAreNoFreeze) {
  const Sequence scene = SyntheticScene({"cameras=3", "people=4", "frames=1000", "noise=perfect"});
  for (const long run : Longest(scene)) EXPECT_LT(run, kMinFrozenFrames);
  Sequence still = scene;
  for (SequenceFrame& frame : still.frames) frame.views = scene.frames[0].views;  // nothing moves anywhere
  EXPECT_EQ(Longest(still), (std::vector<long>{0, 0, 0}));
}

}  // namespace
}  // namespace rpt::engine
