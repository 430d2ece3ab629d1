// SPDX-License-Identifier: MIT
// The whole pipeline on hand-made scenes, and configuration errors.
#include <gtest/gtest.h>

#include <limits>

#include "core/errors.h"
#include "core/pipeline/triangulator.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

TEST(Triangulator, RecoversTwoPersonsExactly) {
  const auto cameras = test::RingCameras(4);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-1, 0.2, 0.5), test::StandingPerson(1, -0.3, 2.5)};
  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  EXPECT_EQ(tri.output_joints().size(), 20u);
  Poses3D persons;
  FrameStats stats;
  tri.Process(test::ProjectPersons(cameras, bodies), 0.0, &persons, &stats);
  ASSERT_EQ(persons.num_persons(), 2);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kMakePairs)], 6 * 4);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kFilter)], 12) << "only the 6 correct pairs per person survive";
  for (const auto& body : bodies) {
    double best = 1e9;
    for (int p = 0; p < 2; ++p) best = std::min(best, (persons.Person(p).leftCols(17).topRows(3) - body.topRows(3)).norm());
    EXPECT_LT(best, 1e-6);
  }
  EXPECT_GT(stats.total_us, 0.0);
  // Derived joints are the means of their sources.
  const auto p0 = persons.Person(0);
  EXPECT_LT((p0.col(17).head<3>() - 0.5 * (p0.col(11).head<3>() + p0.col(12).head<3>())).norm(), 1e-3);
}

TEST(Triangulator, StepsThatDoNotRunRecordNoTimeAndNoCount) {
  const auto cameras = test::RingCameras(4);
  const auto views = test::ProjectPersons(cameras, {test::StandingPerson(0, 0)});
  TriangulatorOptions no_track;
  no_track.track.enabled = false;  // clip_speed is enabled, but needs tracking
  ASSERT_TRUE(no_track.clip_speed.enabled);
  Triangulator tri(cameras, CocoBodyJoints(), no_track);
  Poses3D persons;
  FrameStats stats;
  for (double t : {0.0, 0.04}) {
    tri.Process(views, t, &persons, &stats);
    ASSERT_EQ(persons.num_persons(), 1);
    for (Step step : {Step::kTrack, Step::kClipSpeed, Step::kBoneLengths, Step::kSmooth}) {
      EXPECT_EQ(stats.time_us[static_cast<int>(step)], 0.0) << Info(step).key;
      EXPECT_EQ(stats.count[static_cast<int>(step)], 0) << Info(step).key;
    }
    EXPECT_EQ(stats.count[static_cast<int>(Step::kRemember)], 1) << "the person is kept for the pre-filter";
  }
  // With tracking on, track and clip_speed run; bone_lengths and smooth are off by default.
  Triangulator tracked(cameras, CocoBodyJoints(), TriangulatorOptions{});
  tracked.Process(views, 0.0, &persons, &stats);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kTrack)], 1);
  EXPECT_GT(stats.time_us[static_cast<int>(Step::kTrack)], 0.0);
  EXPECT_EQ(stats.time_us[static_cast<int>(Step::kBoneLengths)], 0.0);
  EXPECT_EQ(stats.time_us[static_cast<int>(Step::kSmooth)], 0.0);
}

TEST(Triangulator, KeepsTheOptionsAsGiven) {
  TriangulatorOptions options;
  ASSERT_EQ(options.group.min_group_size, 0) << "automatic";
  const Triangulator tri(test::RingCameras(10), CocoBodyJoints(), options);
  EXPECT_EQ(tri.options().group.min_group_size, 0) << "the resolved value (2 with 10 cameras) stays internal";
}

TEST(Triangulator, EmptyFramesAndFramesWithOneViewGiveNobody) {
  const auto cameras = test::RingCameras(3);
  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D persons;
  FrameStats stats;
  std::vector<Poses2D> empty(3);
  tri.Process(empty, 0.0, &persons, &stats);
  EXPECT_EQ(persons.num_persons(), 0);
  auto views = test::ProjectPersons(cameras, {test::StandingPerson(0, 0)});
  views[1].Clear(17);
  views[2].Clear(17);
  TriangulatorOptions no_track;
  no_track.track.enabled = false;
  EXPECT_EQ(test::ProcessOneFrame(cameras, views, no_track).num_persons(), 0);
}

TEST(Triangulator, RejectsBadConfigurationAndShapes) {
  const auto cameras = test::RingCameras(3);
  TriangulatorOptions bad;
  bad.filter.min_match_score = 1.5;
  EXPECT_THROW(Triangulator(cameras, CocoBodyJoints(), bad), ConfigError);
  TriangulatorOptions unknown;
  unknown.triangulate.core_joints = {"shoulder_left", "shoulder_right", "tail"};
  try {
    Triangulator(cameras, CocoBodyJoints(), unknown);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("tail"), std::string::npos);
  }
  // Upper-body input with the default core joints: the message gives the default ones it has.
  const JointNames upper_body = {"nose", "shoulder_left", "shoulder_right", "elbow_left", "elbow_right",
                                 "wrist_left", "wrist_right", "hip_left", "hip_right"};
  try {
    Triangulator(cameras, upper_body, TriangulatorOptions{});
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "triangulate.core_joints: the default core joints include 'knee_left', which the input joints do not "
              "have; set triangulate.core_joints to joints the input has, e.g. the default ones it has: "
              "shoulder_left,shoulder_right,hip_left,hip_right,elbow_left,elbow_right,wrist_left,wrist_right");
  }
  TriangulatorOptions given;
  given.triangulate.core_joints = {"shoulder_left", "shoulder_right", "hip_left", "hip_right",
                                   "elbow_left",    "elbow_right",    "wrist_left", "wrist_right"};
  EXPECT_NO_THROW(Triangulator(cameras, upper_body, given));
  EXPECT_THROW(Triangulator({cameras[0]}, CocoBodyJoints(), TriangulatorOptions{}), ConfigError);
  EXPECT_THROW(Triangulator(cameras, {"nose", "nose"}, TriangulatorOptions{}), ConfigError);
  TriangulatorOptions too_many;
  too_many.undistort.min_core_joints = 13;  // of the 12 default core joints
  try {
    Triangulator(cameras, CocoBodyJoints(), too_many);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("undistort.min_core_joints: 13 exceeds the number of core joints (12, "
                                         "triangulate.core_joints)"),
              std::string::npos)
        << e.what();
  }
  // The options alone tell it (Options.check() in Python, `rpt config` before any input is read).
  EXPECT_NE(too_many.Check().find("undistort.min_core_joints: 13 exceeds"), std::string::npos) << too_many.Check();
  TriangulatorOptions one_core;
  one_core.triangulate.core_joints = {"nose"};
  EXPECT_EQ(one_core.Check(), "triangulate.min_core_joints: 3 exceeds the number of core joints (1, triangulate.core_joints)");
  one_core.triangulate.min_core_joints = 1;
  one_core.undistort.min_core_joints = 1;
  EXPECT_EQ(one_core.Check(), "");

  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D persons;
  FrameStats stats;
  std::vector<Poses2D> two_views(2);
  EXPECT_THROW(tri.Process(two_views, 0, &persons, &stats), InputError);
  std::vector<Poses2D> wrong_joints(3);
  wrong_joints[0].Clear(5);
  wrong_joints[0].AddPerson();
  EXPECT_THROW(tri.Process(wrong_joints, 0, &persons, &stats), InputError);
  // A Poses2D filled by hand with a length that is not whole persons (it was dropped unseen), or a
  // negative joint count (std::length_error).
  std::vector<Poses2D> ragged(3);
  ragged[1].num_joints = static_cast<int>(CocoBodyJoints().size());
  ragged[1].data.assign(3 * ragged[1].num_joints + 2, 1.0);
  try {
    tri.Process(ragged, 0, &persons, &stats);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "view 1: 53 values for poses of 17 joints (3 per joint and person)");
  }
  ragged[1].num_joints = -1;
  EXPECT_THROW(tri.Process(ragged, 0, &persons, &stats), InputError);
  ragged[1].num_joints = 0;
  EXPECT_THROW(tri.Process(ragged, 0, &persons, &stats), InputError);
}

// 1600 persons in one view took 4.7 s and 1 GB for one frame (issue 10): association is quadratic
// in the persons per view, so a frame above triangulate.max_persons_per_view is refused up front.
TEST(Triangulator, RefusesMorePersonsPerViewThanTheCap) {
  const auto cameras = test::RingCameras(3);
  TriangulatorOptions options;
  options.triangulate.max_persons_per_view = 2;
  Triangulator tri(cameras, CocoBodyJoints(), options);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-1, 0.2, 0.5), test::StandingPerson(1, -0.3, 2.5)};
  Poses3D persons;
  FrameStats stats;
  tri.Process(test::ProjectPersons(cameras, bodies), 0.0, &persons, &stats);  // at the cap: fine
  EXPECT_EQ(persons.num_persons(), 2);
  const std::vector<Eigen::Matrix4Xd> three = {bodies[0], bodies[1], test::StandingPerson(0, 1.0, 1.0)};
  try {
    tri.Process(test::ProjectPersons(cameras, three), 0.1, &persons, &stats);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("view 0 (camera '" + cameras[0].name +
                                         "') has 3 2D poses, above triangulate.max_persons_per_view (2)"),
              std::string::npos)
        << e.what();
  }
}

TEST(Triangulator, PrefilterUsesLastFrameAndResetForgetsIt) {
  const auto cameras = test::RingCameras(4);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-1, 0), test::StandingPerson(1, 0)};
  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D persons;
  FrameStats stats;
  const auto views = test::ProjectPersons(cameras, bodies);
  tri.Process(views, 0.0, &persons, &stats);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kPrefilter)], 24) << "first frame: nothing to filter with";
  tri.Process(views, 0.04, &persons, &stats);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kPrefilter)], 12) << "mixed pairs dropped";
  ASSERT_EQ(persons.num_persons(), 2);
  tri.Reset();
  tri.Process(views, 0.08, &persons, &stats);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kPrefilter)], 24);
}

// Recording a trace makes make_pairs list every pair even where the pre-filter lists what it keeps
// itself (PairListing): over a tracked sequence the persons are the same either way, and the
// traced list is as long as make_pairs' count.
TEST(Triangulator, TracedAndUntracedRunsAgreeWhileThePrefilterActs) {
  const auto cameras = test::RingCameras(5);
  Triangulator traced(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Triangulator plain(cameras, CocoBodyJoints(), TriangulatorOptions{});
  const int make_pairs = static_cast<int>(Step::kMakePairs), prefilter = static_cast<int>(Step::kPrefilter);
  for (int f = 0; f < 6; ++f) {
    const double t = 0.04 * f;
    const auto views = test::ProjectPersons(cameras, {test::StandingPerson(-1 + 0.05 * f, 0),
                                                      test::StandingPerson(0.8, 0.4 - 0.05 * f, 1.0),
                                                      test::StandingPerson(0.1, -1.2, 2.0)});
    Poses3D with_trace, without;
    FrameStats traced_stats, plain_stats;
    FrameTrace trace;
    traced.Process(views, t, &with_trace, &traced_stats, &trace);
    plain.Process(views, t, &without, &plain_stats);
    EXPECT_EQ(with_trace.data, without.data) << "frame " << f;
    EXPECT_EQ(with_trace.track_ids, without.track_ids) << "frame " << f;
    EXPECT_EQ(plain_stats.count[make_pairs], 90) << "frame " << f;  // 10 view pairs x 3 x 3
    EXPECT_EQ(static_cast<int>(trace.pairs[FrameTrace::kMakePairs].size()), traced_stats.count[make_pairs]);
    EXPECT_EQ(plain_stats.count[prefilter], f == 0 ? 90 : 30) << "frame " << f;  // then each person's own 10
  }
}

// Continuity: only frames at most track.max_gap_s after the last one use it.
TEST(Triangulator, UnknownTimesAndLargeGapsStartAfresh) {
  const auto cameras = test::RingCameras(4);
  const auto both = test::ProjectPersons(cameras, {test::StandingPerson(-1, 0), test::StandingPerson(1, 0)});
  const auto one = test::ProjectPersons(cameras, {test::StandingPerson(-1, 0)});
  const int prefilter = static_cast<int>(Step::kPrefilter);
  TriangulatorOptions options;
  options.track.max_gap_s = 0.5;
  Triangulator tri(cameras, CocoBodyJoints(), options);
  Poses3D persons;
  FrameStats stats;
  tri.Process(both, 0.0, &persons, &stats);
  ASSERT_EQ(persons.num_persons(), 2);
  const int first_id = persons.track_ids[0];

  // 0.4 s later (within the gap): pre-filter active, the missing person coasts with its id.
  tri.Process(one, 0.4, &persons, &stats);
  EXPECT_EQ(stats.count[prefilter], 6) << "one person in 4 views: 6 pairs, all kept";
  EXPECT_EQ(stats.coasting_tracks, 1);
  EXPECT_EQ(persons.num_persons(), 2);

  // 0.6 s after that (beyond the gap): no pre-filter, nobody coasts, new track ids.
  tri.Process(both, 1.0, &persons, &stats);
  EXPECT_EQ(stats.count[prefilter], 24) << "the pre-filter does not use a frame 0.6 s old";
  tri.Process(one, 2.0, &persons, &stats);
  EXPECT_EQ(stats.coasting_tracks, 0) << "no coasting over a 1 s gap";
  ASSERT_EQ(persons.num_persons(), 1);
  EXPECT_GT(persons.track_ids[0], first_id + 1) << "tracks ended at the gap";

  // Unknown time (NaN), time going backwards, the same time twice: never continuous.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [before, t] : std::vector<std::pair<double, double>>{{3.0, nan}, {4.0, 3.9}, {5.0, 5.0}}) {
    tri.Process(both, before, &persons, &stats);  // a reference frame with two persons
    tri.Process(one, t, &persons, &stats);
    EXPECT_EQ(stats.count[prefilter], 6);
    EXPECT_EQ(stats.coasting_tracks, 0) << "t = " << t;
    EXPECT_EQ(persons.num_persons(), 1) << "t = " << t;
  }
}

// A view that repeats a pose exactly: the copy is dropped before pairing (undistort), so the frame
// gives what it gives without it; a pose that differs in one score is no copy.
TEST(Triangulator, ExactCopiesOfAPoseAreDropped) {
  const auto cameras = test::RingCameras(3);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-0.8, 0.2), test::StandingPerson(0.9, -0.3, 2.0)};
  const std::vector<Poses2D> clean = test::ProjectPersons(cameras, bodies);
  std::vector<Poses2D> copied = clean;
  Poses2D& view = copied[0];  // poses: body 0, its copy, body 1, body 1 with one score changed
  view.Clear(clean[0].num_joints);
  view.AddPerson() = clean[0].Person(0);
  view.AddPerson() = clean[0].Person(0);
  view.AddPerson() = clean[0].Person(1);
  auto changed = view.AddPerson();
  changed = clean[0].Person(1);
  changed(2, 0) = 0.5;
  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D persons, expected;
  FrameStats stats;
  FrameTrace trace;
  tri.Process(copied, std::numeric_limits<double>::quiet_NaN(), &persons, &stats, &trace);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kUndistort)], 3 + 2 + 2);
  EXPECT_EQ(trace.pose_person, (std::vector<int>{0, 2, 3, 0, 1, 0, 1}));
  EXPECT_EQ(trace.pose_view, (std::vector<int>{0, 0, 0, 1, 1, 2, 2}));

  TriangulatorOptions keep;
  keep.undistort.drop_exact_copies = false;
  Triangulator with_copies(cameras, CocoBodyJoints(), keep);
  with_copies.Process(copied, std::numeric_limits<double>::quiet_NaN(), &expected, &stats);
  EXPECT_EQ(stats.count[static_cast<int>(Step::kUndistort)], 4 + 2 + 2);

  // Without the copy: the same persons, bit for bit.
  std::vector<Poses2D> without = copied;
  without[0].Clear(clean[0].num_joints);
  for (int p : {0, 2, 3}) without[0].AddPerson() = copied[0].Person(p);
  Triangulator reference(cameras, CocoBodyJoints(), TriangulatorOptions{});
  reference.Process(without, std::numeric_limits<double>::quiet_NaN(), &expected, &stats);
  EXPECT_EQ(persons.data, expected.data);
}

// The trace of a clean frame: every pair survives to the filter but the cross-person ones, each
// person's pairs form one group, merged into one person each, and all are kept.
TEST(Triangulator, TraceRecordsWhatTheAssociationDid) {
  const auto cameras = test::RingCameras(3);
  const std::vector<Eigen::Matrix4Xd> bodies = {test::StandingPerson(-0.8, 0.2), test::StandingPerson(0.9, -0.3, 2.0)};
  Triangulator tri(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D persons;
  FrameStats stats;
  FrameTrace trace;
  tri.Process(test::ProjectPersons(cameras, bodies), 0.0, &persons, &stats, &trace);
  ASSERT_EQ(trace.pose_person, (std::vector<int>{0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(trace.pairs[FrameTrace::kMakePairs].size(), 12u);  // 3 view pairs x 2 x 2
  EXPECT_EQ(trace.pairs[FrameTrace::kPrefilter].size(), 12u);
  const auto& filtered = trace.pairs[FrameTrace::kFilter];
  ASSERT_EQ(filtered.size(), 6u);
  ASSERT_EQ(trace.group_of_pair.size(), 6u);
  for (size_t i = 0; i < filtered.size(); ++i) {
    const int person = trace.pose_person[filtered[i][0]];
    EXPECT_EQ(trace.pose_person[filtered[i][1]], person) << "pair " << i;
    // The groups are numbered in creation order; both hold one person's three pairs.
    EXPECT_EQ(trace.group_of_pair[i], trace.group_of_pair[0] == 0 ? person : 1 - person) << "pair " << i;
  }
  EXPECT_EQ(trace.merged.num_persons(), 2);
  EXPECT_EQ(trace.after_verify, (std::vector<int>{0, 1}));
  EXPECT_EQ(trace.after_postprocess, (std::vector<int>{0, 1}));
  // The persons carry no trace label out of the triangulator: tracking numbers them.
  EXPECT_EQ(persons.num_persons(), 2);
  for (int id : persons.track_ids) EXPECT_GE(id, 0);
  // Without a trace, the same persons.
  Triangulator untraced(cameras, CocoBodyJoints(), TriangulatorOptions{});
  Poses3D same;
  untraced.Process(test::ProjectPersons(cameras, bodies), 0.0, &same, &stats);
  EXPECT_EQ(same.data, persons.data);
  EXPECT_EQ(same.track_ids, persons.track_ids);
}

}  // namespace
}  // namespace rpt
