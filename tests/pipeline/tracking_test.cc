// SPDX-License-Identifier: MIT
// Steps 13-14: tracking ids over time and clipping joint speed.
#include <gtest/gtest.h>

#include "core/joints.h"
#include "core/pipeline/clip_speed.h"
#include "core/pipeline/track_persons.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

std::vector<int> Core() {
  std::vector<int> out;
  for (const auto& n : DefaultCoreJoints()) out.push_back(FindJoint(CocoBodyJoints(), n));
  return out;
}

Poses3D Persons(const std::vector<Eigen::Matrix4Xd>& bodies) {
  Poses3D persons;
  persons.Clear(17);
  for (const auto& b : bodies) persons.AddPerson() = b;
  return persons;
}

TEST(Tracker, KeepsIdsWhenPersonOrderChanges) {
  Tracker tracker;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(-1, 0), test::StandingPerson(1, 0)});
  ASSERT_EQ(tracker.Assign(options, Core(), &frame0, &stats), 2);
  tracker.Commit(frame0, 2, 0.0);
  EXPECT_EQ(stats.new_tracks, 2);
  // Next frame: both moved 5 cm, order swapped.
  Poses3D frame1 = Persons({test::StandingPerson(1.05, 0), test::StandingPerson(-0.95, 0)});
  stats.Reset();
  tracker.Assign(options, Core(), &frame1, &stats);
  EXPECT_EQ(stats.new_tracks, 0);
  EXPECT_EQ(frame1.track_ids[0], frame0.track_ids[1]);
  EXPECT_EQ(frame1.track_ids[1], frame0.track_ids[0]);
}

TEST(Tracker, LostPersonCoastsThenEnds) {
  Tracker tracker;
  TrackOptions options;
  options.max_missing_frames = 2;
  FrameStats stats;
  Poses3D frame = Persons({test::StandingPerson(0, 0)});
  tracker.Assign(options, Core(), &frame, &stats);
  tracker.Commit(frame, 1, 0.0);
  const int id = frame.track_ids[0];
  for (int f = 1; f <= 3; ++f) {
    Poses3D empty = Persons({});
    stats.Reset();
    EXPECT_EQ(tracker.Assign(options, Core(), &empty, &stats), 0);
    if (f <= 2) {
      ASSERT_EQ(empty.num_persons(), 1) << "frame " << f;
      EXPECT_EQ(empty.track_ids[0], id);
      EXPECT_EQ(stats.coasting_tracks, 1);
      EXPECT_LT((empty.Person(0) - frame.Person(0)).norm(), 1e-12) << "last pose returned";
    } else {
      EXPECT_EQ(empty.num_persons(), 0) << "track ended after max_missing_frames";
    }
    tracker.Commit(empty, 0, f * 0.04);
  }
  // A person appearing far away later gets a new id.
  Poses3D later = Persons({test::StandingPerson(3, 3)});
  tracker.Assign(options, Core(), &later, &stats);
  EXPECT_NE(later.track_ids[0], id);
}

TEST(Tracker, FarPersonStartsNewTrack) {
  Tracker tracker;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(0, 0)});
  tracker.Assign(options, Core(), &frame0, &stats);
  tracker.Commit(frame0, 1, 0.0);
  Poses3D frame1 = Persons({test::StandingPerson(0.8, 0)});  // 0.8 m > max_distance_m
  stats.Reset();
  tracker.Assign(options, Core(), &frame1, &stats);
  EXPECT_EQ(stats.new_tracks, 1);
  EXPECT_NE(frame1.track_ids[0], frame0.track_ids[0]);
  EXPECT_EQ(frame1.num_persons(), 2) << "the old track coasts";
}

TEST(ClipSpeed, LimitsJointDisplacementPerSecond) {
  Tracker tracker;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(0, 0)});
  tracker.Assign(options, Core(), &frame0, &stats);
  tracker.Commit(frame0, 1, 0.0);
  Eigen::Matrix4Xd moved = test::StandingPerson(0.02, 0);  // 2 cm: fine at 10 m/s over 0.1 s
  moved.col(9).head<3>() += Eigen::Vector3d(0, 0, 0.3);   // wrist jumps 30 cm in 0.1 s (3 m/s)
  Poses3D frame1 = Persons({moved});
  tracker.Assign(options, Core(), &frame1, &stats);
  ClipSpeedOptions clip;
  clip.max_speed_m_s = 1.0;  // 10 cm per 0.1 s
  EXPECT_EQ(ClipSpeed(clip, tracker, 0.1, 1, &frame1), 1);
  const Eigen::Vector3d step = frame1.Person(0).col(9).head<3>() - frame0.Person(0).col(9).head<3>();
  EXPECT_NEAR(step.norm(), 0.1, 1e-12);
  EXPECT_LT((frame1.Person(0).col(0) - moved.col(0)).norm(), 1e-12) << "slow joints untouched";
  clip.enabled = false;
  EXPECT_EQ(ClipSpeed(clip, tracker, 0.1, 1, &frame1), 0);
}

}  // namespace
}  // namespace rpt
