// SPDX-License-Identifier: MIT
// Steps 13-14: tracking ids over time and clipping joint speed.
#include <gtest/gtest.h>

#include "core/joints.h"
#include "core/pipeline/clip_speed.h"
#include "core/pipeline/postprocess.h"
#include "core/pipeline/track.h"
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

// Step 13 on `persons`; returns the number detected (before the coasting ones).
// `timestamp_s`: the frame's time.
int RunTrack(const TrackOptions& options, Tracks* tracks, Poses3D* persons, FrameStats* stats,
             double timestamp_s = 0) {
  TrackScratch scratch;
  const int num_detected = persons->num_persons();
  const std::vector<int> core = Core();
  const int count =
      steps::Track(options, {.match_joints = core, .timestamp_s = timestamp_s}, tracks, &scratch, persons, stats);
  EXPECT_EQ(count, persons->num_persons()) << "count: detected and coasting persons";
  return num_detected;
}

TEST(Track, KeepsIdsWhenPersonOrderChanges) {
  Tracks tracks;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(-1, 0), test::StandingPerson(1, 0)});
  ASSERT_EQ(RunTrack(options, &tracks, &frame0, &stats), 2);
  tracks.Commit(frame0, 2, 0.0);
  EXPECT_EQ(stats.new_tracks, 2);
  // Next frame: both moved 5 cm, order swapped.
  Poses3D frame1 = Persons({test::StandingPerson(1.05, 0), test::StandingPerson(-0.95, 0)});
  stats.Reset();
  RunTrack(options, &tracks, &frame1, &stats);
  EXPECT_EQ(stats.new_tracks, 0);
  EXPECT_EQ(frame1.track_ids[0], frame0.track_ids[1]);
  EXPECT_EQ(frame1.track_ids[1], frame0.track_ids[0]);
}

TEST(Track, LostPersonCoastsThenEnds) {
  Tracks tracks;
  TrackOptions options;
  options.max_missing_frames = 2;
  FrameStats stats;
  Poses3D frame = Persons({test::StandingPerson(0, 0)});
  RunTrack(options, &tracks, &frame, &stats);
  tracks.Commit(frame, 1, 0.0);
  const int id = frame.track_ids[0];
  for (int f = 1; f <= 3; ++f) {
    Poses3D empty = Persons({});
    stats.Reset();
    EXPECT_EQ(RunTrack(options, &tracks, &empty, &stats), 0);
    if (f <= 2) {
      ASSERT_EQ(empty.num_persons(), 1) << "frame " << f;
      EXPECT_EQ(empty.track_ids[0], id);
      EXPECT_EQ(stats.coasting_tracks, 1);
      EXPECT_LT((empty.Person(0) - frame.Person(0)).norm(), 1e-12) << "last pose returned";
    } else {
      EXPECT_EQ(empty.num_persons(), 0) << "track ended after max_missing_frames";
    }
    tracks.Commit(empty, 0, f * 0.04);
  }
  // A person appearing far away later gets a new id.
  Poses3D later = Persons({test::StandingPerson(3, 3)});
  RunTrack(options, &tracks, &later, &stats);
  EXPECT_NE(later.track_ids[0], id);
}

TEST(ClipSpeed, NewTrackInAnEndedTracksSlotIsNotClipped) {
  // A track ends; a person appearing 4.2 m from its last pose 0.16 s later starts a new track in
  // the freed slot. The slot still holds the ended track's pose and time, which are not the new
  // track's: nothing is clipped (at 10 m/s the stale pose would have pulled it 2.6 m back).
  Tracks tracks;
  TrackOptions options;
  options.max_missing_frames = 2;
  FrameStats stats;
  Poses3D first = Persons({test::StandingPerson(-2, 0)});
  RunTrack(options, &tracks, &first, &stats);
  tracks.Commit(first, 1, 0.0);
  for (int f = 1; f <= 3; ++f) {
    Poses3D empty = Persons({});
    RunTrack(options, &tracks, &empty, &stats);
    tracks.Commit(empty, 0, f * 0.04);
  }
  const Eigen::Matrix4Xd body = test::StandingPerson(2.2, 0);
  Poses3D later = Persons({body});
  stats.Reset();
  ASSERT_EQ(RunTrack(options, &tracks, &later, &stats), 1);
  ASSERT_EQ(stats.new_tracks, 1);
  ASSERT_EQ(tracks.slots.size(), 1u) << "the ended track's slot is reused";
  double time = -1;
  EXPECT_EQ(tracks.LastPose(later.track_ids[0], &time), nullptr) << "a new track has no last pose";
  const steps::ClipSpeedInput input{.tracks = tracks, .timestamp_s = 0.16, .num_detected = 1};
  EXPECT_EQ(steps::ClipSpeed(ClipSpeedOptions{}, input, &later), 0);
  EXPECT_LT((later.Person(0) - body).norm(), 1e-12);
}

// The fill rule of the COCO body (post-processing's neighbours).
std::vector<int> CocoNeighbours() { return NeighbourIndices(CocoBodyJoints()); }

// `body` with joints `missing` filled as post-processing fills them: on their neighbour, at the
// filled score, provenance kFilled (from the torso outwards).
Poses3D WithFilledJoints(const Eigen::Matrix4Xd& body, const std::vector<int>& missing, double filled_score) {
  Poses3D persons = Persons({body});
  auto person = persons.Person(0);
  for (int j : missing) person(3, j) = 0;
  FillMissingJoints(CocoNeighbours(), filled_score, person, persons.PersonProvenance(0));
  return persons;
}

constexpr int kShoulderL = 5, kElbowL = 7, kWristL = 9;

// The track step on frames of one person: the core joints matched, the COCO fill rule for held
// joints, a standing person at the origin.
class TrackStep : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_GE(core_.size(), 12u);
    ASSERT_EQ(neighbour_[kWristL], kElbowL);
    ASSERT_EQ(neighbour_[kElbowL], kShoulderL);
  }
  // Runs the track step on `persons` (stats reset first).
  void Run(Poses3D* persons, const TrackOptions& options = {}) {
    stats_.Reset();
    steps::Track(options, input_, &tracks_, &scratch_, persons, &stats_);
  }
  // Starts the track with `persons` at time 0.
  void Start(Poses3D* persons) {
    Run(persons);
    tracks_.Commit(*persons, 1, 0.0);
  }
  const std::vector<int> core_ = Core();
  const std::vector<int> neighbour_ = CocoNeighbours();
  const steps::TrackInput input_{.match_joints = core_, .neighbour = neighbour_, .unobserved_score = 0.05};
  const Eigen::Matrix4Xd body_ = test::StandingPerson(0, 0);
  TrackScratch scratch_;
  Tracks tracks_;
  FrameStats stats_;
};

TEST_F(TrackStep, HoldsAFilledJointAtItsOffsetInTheTracksLastPose) {
  Eigen::Matrix4Xd body = body_;
  body.col(kWristL).head<3>() += Eigen::Vector3d(0.05, -0.02, 0.1);  // a pose of its own
  Poses3D first = Persons({body});
  Start(&first);
  EXPECT_EQ(stats_.held_joints, 0);

  // The person moves 0.1 m; its left wrist is missing and filled onto the elbow.
  const Eigen::Vector3d shift(0.1, 0.0, 0.0);
  Eigen::Matrix4Xd moved = body;
  moved.topRows(3).colwise() += shift;
  Poses3D second = WithFilledJoints(moved, {kWristL}, 0.05);
  ASSERT_EQ(second.Provenance(0, kWristL), JointProvenance::kFilled);
  Run(&second);
  ASSERT_EQ(second.track_ids[0], first.track_ids[0]);
  EXPECT_EQ(stats_.held_joints, 1);
  EXPECT_LT((second.Person(0).col(kWristL).head<3>() - moved.col(kWristL).head<3>()).norm(), 1e-12)
      << "elbow now + (wrist - elbow) in the last pose";
  EXPECT_EQ(second.Person(0)(3, kWristL), 0.05) << "still a filled joint: its score stays";
  EXPECT_EQ(second.Provenance(0, kWristL), JointProvenance::kFilled);
  for (int j = 0; j < 17; ++j) {
    if (j != kWristL) {
      EXPECT_LT((second.Person(0).col(j) - moved.col(j)).norm(), 1e-12) << j;
    }
  }

  // Elbow and wrist missing: the elbow is held from the shoulder, then the wrist from the elbow.
  tracks_.Commit(second, 1, 0.04);
  moved.topRows(3).colwise() += shift;
  Poses3D third = WithFilledJoints(moved, {kElbowL, kWristL}, 0.05);
  Run(&third);
  EXPECT_EQ(stats_.held_joints, 2);
  for (int j : {kElbowL, kWristL}) EXPECT_LT((third.Person(0).col(j).head<3>() - moved.col(j).head<3>()).norm(), 1e-12) << j;

  // Off: the joints stay where post-processing put them.
  tracks_.Commit(third, 1, 0.08);
  moved.topRows(3).colwise() += shift;
  Poses3D off = WithFilledJoints(moved, {kElbowL, kWristL}, 0.05);
  const Poses3D filled = off;
  TrackOptions options;
  options.hold_missing_joints = false;
  Run(&off, options);
  EXPECT_EQ(stats_.held_joints, 0);
  EXPECT_LT((off.Person(0) - filled.Person(0)).norm(), 1e-12);
}

TEST_F(TrackStep, AJointTheLastPoseLacksFollowsItsHeldNeighbour) {
  // The last pose has the elbow but no wrist. Both missing now: the elbow is held (shoulder + its
  // offset), the wrist cannot be and sits on the elbow where the hold put it, not on the shoulder
  // where post-processing's fill had put the elbow.
  const Eigen::Matrix4Xd& body = body_;
  Poses3D first = Persons({body});
  first.Person(0)(3, kWristL) = 0;  // missing, not filled (post-processing off, say)
  Start(&first);
  Poses3D second = WithFilledJoints(body, {kElbowL, kWristL}, 0.05);
  ASSERT_LT((second.Person(0).col(kWristL).head<3>() - body.col(kShoulderL).head<3>()).norm(), 1e-12);
  Run(&second);
  EXPECT_EQ(stats_.held_joints, 1);
  const auto person = second.Person(0);
  EXPECT_LT((person.col(kElbowL).head<3>() - body.col(kElbowL).head<3>()).norm(), 1e-12);
  EXPECT_LT((person.col(kWristL).head<3>() - body.col(kElbowL).head<3>()).norm(), 1e-12);
}

// `body` 2 cm further along x, with the first six of `core` filled (score 0.05) 1.5 m above.
Eigen::Matrix4Xd MovedWithSixFarFilledJoints(const Eigen::Matrix4Xd& body, const std::vector<int>& core) {
  Eigen::Matrix4Xd next = body;
  next.topRows(3).colwise() += Eigen::Vector3d(0.02, 0, 0);
  for (int c = 0; c < 6; ++c) {
    next.col(core[c]).head<3>() += Eigen::Vector3d(0, 0, 1.5);
    next(3, core[c]) = 0.05;
  }
  return next;
}

TEST_F(TrackStep, HoldsAJointPlacedFromOneViewButNotAPersonPlacedFromOne) {
  const Eigen::Matrix4Xd& body = body_;
  Poses3D first = Persons({body});
  Start(&first);
  // The wrist placed from one view 10 cm off (its elbow triangulated): held at its offset.
  Poses3D second = Persons({body});
  second.Person(0).col(kWristL).head<3>() += Eigen::Vector3d(0.1, 0, 0);
  second.PersonProvenance(0)[kWristL] = static_cast<uint8_t>(JointProvenance::kLifted);
  Run(&second);
  EXPECT_EQ(stats_.held_joints, 1);
  EXPECT_LT((second.Person(0).col(kWristL).head<3>() - body.col(kWristL).head<3>()).norm(), 1e-12);
  // A person single_view placed (every joint lifted, 10 cm off) with its wrist filled onto the
  // elbow: its lifted joints stay, the filled wrist is held from the lifted elbow.
  tracks_.Commit(first, 1, 0.04);
  Poses3D lifted = Persons({body});
  lifted.Person(0).topRows(3).colwise() += Eigen::Vector3d(0.1, 0, 0);
  for (uint8_t& source : lifted.PersonProvenance(0)) source = static_cast<uint8_t>(JointProvenance::kLifted);
  lifted.Person(0).col(kWristL).head<3>() = lifted.Person(0).col(kElbowL).head<3>();
  lifted.Person(0)(3, kWristL) = 0.05;
  lifted.PersonProvenance(0)[kWristL] = static_cast<uint8_t>(JointProvenance::kFilled);
  const Poses3D before = lifted;
  Run(&lifted);
  EXPECT_EQ(stats_.held_joints, 1);
  for (int j = 0; j < 17; ++j) {
    if (j == kWristL) continue;
    EXPECT_EQ(Eigen::Vector4d(lifted.Person(0).col(j)), Eigen::Vector4d(before.Person(0).col(j))) << j;
  }
  const Eigen::Vector3d offset = body.col(kWristL).head<3>() - body.col(kElbowL).head<3>();
  EXPECT_LT((lifted.Person(0).col(kWristL).head<3>() - (before.Person(0).col(kElbowL).head<3>() + offset)).norm(),
            1e-12);
}

TEST_F(TrackStep, ComparesObservedJointsBeforeFilledOnes) {
  // Six core joints filled far from where the track held them, six observed 2 cm off: observed
  // joints decide (mean 0.02 m, the track continues); with every valid joint the mean would be
  // above max_distance_m.
  Poses3D first = Persons({body_});
  Start(&first);
  Poses3D second = Persons({MovedWithSixFarFilledJoints(body_, core_)});
  Run(&second);
  EXPECT_EQ(stats_.new_tracks, 0);
  EXPECT_EQ(second.track_ids[0], first.track_ids[0]);
  // Fewer than 3 observed in common: every valid joint counts (and here breaks the track).
  for (int c = 6; c < static_cast<int>(core_.size()) - 2; ++c) second.Person(0)(3, core_[c]) = 0.05;
  tracks_.Commit(first, 1, 0.04);
  Poses3D third = second;
  Run(&third);
  EXPECT_EQ(stats_.new_tracks, 1);
}

TEST_F(TrackStep, ComparesJointsObservedNowWithTheLastPosesHeldOnes) {
  // The last output observed only 2 core joints (the others held, score 0.05, where they were);
  // now 6 are observed 2 cm off and 6 filled 1.5 m away. Observed in both: 2, too few; observed
  // now against the last output's valid joints: mean 0.02 m, the track continues (over every
  // valid joint the mean would be 0.76 m).
  Poses3D first = Persons({body_});
  Run(&first);
  for (int c = 2; c < static_cast<int>(core_.size()); ++c) first.Person(0)(3, core_[c]) = 0.05;
  tracks_.Commit(first, 1, 0.0);
  Poses3D second = Persons({MovedWithSixFarFilledJoints(body_, core_)});
  Run(&second);
  EXPECT_EQ(stats_.new_tracks, 0);
  EXPECT_EQ(second.track_ids[0], first.track_ids[0]);
}

TEST(Track, FarPersonStartsNewTrack) {
  Tracks tracks;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(0, 0)});
  RunTrack(options, &tracks, &frame0, &stats);
  tracks.Commit(frame0, 1, 0.0);
  Poses3D frame1 = Persons({test::StandingPerson(0.8, 0)});  // 0.8 m > max_distance_m
  stats.Reset();
  RunTrack(options, &tracks, &frame1, &stats);
  EXPECT_EQ(stats.new_tracks, 1);
  EXPECT_NE(frame1.track_ids[0], frame0.track_ids[0]);
  EXPECT_EQ(frame1.num_persons(), 2) << "the old track coasts";
}

// At 2 fps a person walking 1.6 m/s is 0.8 m further each frame, beyond max_distance_m (0.5): the
// gate grows to max_person_speed_m_s (2) x 0.5 s = 1 m, and after a missed frame to 2 m. At 25
// fps the distance decides, as before: 0.8 m in 0.04 s is someone else.
TEST(Track, AtLowFrameRatesTheGateGrowsWithTheTimeSinceLastSeen) {
  TrackOptions options;
  const auto continued = [&](double step_s, double moved_m, int missed_frames) {
    Tracks tracks;
    FrameStats stats;
    Poses3D frame0 = Persons({test::StandingPerson(0, 0)});
    RunTrack(options, &tracks, &frame0, &stats, 10.0);
    tracks.Commit(frame0, 1, 10.0);
    double now = 10.0;
    for (int k = 0; k < missed_frames; ++k) {  // nobody detected: the track coasts
      now += step_s;
      Poses3D none = Persons({});
      RunTrack(options, &tracks, &none, &stats, now);
      tracks.Commit(none, 0, now);
    }
    now += step_s;
    Poses3D frame1 = Persons({test::StandingPerson(moved_m, 0)});
    stats.Reset();
    RunTrack(options, &tracks, &frame1, &stats, now);
    return stats.new_tracks == 0 && frame1.track_ids[0] == frame0.track_ids[0];
  };
  EXPECT_TRUE(continued(0.5, 0.8, 0));
  EXPECT_FALSE(continued(0.5, 1.1, 0)) << "beyond 2 m/s x 0.5 s";
  EXPECT_TRUE(continued(0.5, 1.6, 1)) << "last seen 1 s ago: within 2 m";
  EXPECT_FALSE(continued(0.04, 0.8, 0)) << "25 fps: 0.8 m > max_distance_m";
  EXPECT_TRUE(continued(0.04, 0.45, 0));
  options.max_person_speed_m_s = 0;  // the distance alone, whatever the rate
  EXPECT_FALSE(continued(0.5, 0.8, 0));
}

TEST(ClipSpeed, LimitsJointDisplacementPerSecond) {
  Tracks tracks;
  TrackOptions options;
  FrameStats stats;
  Poses3D frame0 = Persons({test::StandingPerson(0, 0)});
  RunTrack(options, &tracks, &frame0, &stats);
  tracks.Commit(frame0, 1, 0.0);
  Eigen::Matrix4Xd moved = test::StandingPerson(0.02, 0);  // 2 cm: fine at 10 m/s over 0.1 s
  moved.col(9).head<3>() += Eigen::Vector3d(0, 0, 0.3);   // wrist jumps 30 cm in 0.1 s (3 m/s)
  Poses3D frame1 = Persons({moved});
  RunTrack(options, &tracks, &frame1, &stats);
  ClipSpeedOptions clip;
  clip.max_speed_m_s = 1.0;  // 10 cm per 0.1 s
  const steps::ClipSpeedInput input{.tracks = tracks, .timestamp_s = 0.1, .num_detected = 1};
  EXPECT_EQ(steps::ClipSpeed(clip, input, &frame1), 1);
  const Eigen::Vector3d step = frame1.Person(0).col(9).head<3>() - frame0.Person(0).col(9).head<3>();
  EXPECT_NEAR(step.norm(), 0.1, 1e-12);
  EXPECT_LT((frame1.Person(0).col(0) - moved.col(0)).norm(), 1e-12) << "slow joints untouched";
  clip.enabled = false;
  EXPECT_EQ(steps::ClipSpeed(clip, input, &frame1), 0);
}

}  // namespace
}  // namespace rpt

// End to end: people walking towards each other and passing closely keep their track ids.
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt {
namespace {

TEST(TrackingEndToEnd, IdsSurvivePeopleCrossing) {
  for (uint64_t seed : {1, 2, 3, 4}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    synthetic::CrossingOptions options;
    options.num_people = seed == 4 ? 3 : 2;
    options.lane_spacing_m = 0.55;
    options.seed = seed;
    const synthetic::Scene scene = synthetic::MakeCrossingScene(options);
    const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, seed);
    Triangulator tri(scene.cameras, scene.joint_names, TriangulatorOptions{});
    std::vector<Poses2D> views;
    Poses3D persons;
    FrameStats stats;
    std::vector<int> id_of(scene.gt[0].num_persons(), -2);
    int matched_frames = 0;
    for (size_t f = 0; f < scene.gt.size(); ++f) {
      detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views);
      tri.Process(views, f / scene.fps, &persons, &stats);
      for (int g = 0; g < scene.gt[f].num_persons(); ++g) {
        int best_p = -1;
        double best = 0.15;  // metres, mean over body joints
        for (int p = 0; p < persons.num_persons(); ++p) {
          const double e = (persons.Person(p).leftCols(17).topRows(3) - scene.gt[f].Person(g).topRows(3))
                               .colwise()
                               .norm()
                               .mean();
          if (e < best) {
            best = e;
            best_p = p;
          }
        }
        if (best_p < 0) continue;
        ++matched_frames;
        if (id_of[g] == -2) id_of[g] = persons.track_ids[best_p];
        EXPECT_EQ(persons.track_ids[best_p], id_of[g]) << "person " << g << " frame " << f;
      }
    }
    EXPECT_GT(matched_frames, static_cast<int>(0.95 * scene.gt.size() * scene.gt[0].num_persons()));
    for (size_t a = 0; a < id_of.size(); ++a) {
      for (size_t b = a + 1; b < id_of.size(); ++b) EXPECT_NE(id_of[a], id_of[b]);
    }
  }
}

}  // namespace
}  // namespace rpt
