// SPDX-License-Identifier: MIT
// Step 12b (single_view.h): a pose seen by one camera is lifted only when the other views do not
// contradict it; the ground prior stands it upright on the floor, kept only when its body size,
// posture and place are plausible. Hand-computed geometry first, then the step on a projected scene.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/single_view.h"
#include "core/pipeline/triangulator.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/view_geometry.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// COCO joints (CocoBodyJoints()).
enum : int {
  kNose = 0,
  kShoulderL = 5,
  kShoulderR = 6,
  kElbowL = 7,
  kElbowR = 8,
  kWristL = 9,
  kWristR = 10,
  kHipL = 11,
  kHipR = 12,
  kKneeL = 13,
  kKneeR = 14,
  kAnkleL = 15,
  kAnkleR = 16,
};

// A camera at (0, 0, 2) and a person in the vertical plane x = 4 facing it, joints given as
// (y, z): every joint's ray is its point minus the camera centre, so the ground prior must put it
// back exactly (t = 1 on every ray).
struct PlanePerson {
  std::vector<Keypoint> kps = std::vector<Keypoint>(17);
  void Set(int j, double y, double z) {
    kps[j].score = 0.9;
    kps[j].ray = Eigen::Vector3d(4.0, y, z - 2.0);
  }
};

// Typical adult sizes: shins 0.40, thighs 0.42, hips 0.24, shoulders 0.36, upper arms 0.29,
// forearms 0.26; the shoulder-to-hip limbs sqrt(0.06^2 + 0.5^2) = 0.503587 m (ratio 1.007174),
// the two largest ratios, so the body scale is 1.007174.
PlanePerson StandingPlanePerson(double size, bool ankles = true) {
  PlanePerson p;
  const auto set = [&](int j, double y, double z) { p.Set(j, size * y, 0.08 + size * (z - 0.08)); };
  if (ankles) {
    set(kAnkleL, 0.12, 0.08);
    set(kAnkleR, -0.12, 0.08);
  }
  set(kKneeL, 0.12, 0.48);
  set(kKneeR, -0.12, 0.48);
  set(kHipL, 0.12, 0.90);
  set(kHipR, -0.12, 0.90);
  set(kShoulderL, 0.18, 1.40);
  set(kShoulderR, -0.18, 1.40);
  set(kElbowL, 0.18, 1.11);
  set(kElbowR, -0.18, 1.11);
  set(kWristL, 0.18, 0.85);
  set(kWristR, -0.18, 0.85);
  set(kNose, 0.0, 1.60);
  return p;
}

ViewGeometry CameraAt2m() {
  ViewGeometry geo;
  geo.center = Eigen::Vector3d(0, 0, 2);
  return geo;
}

TEST(PlaceOnGround, StandsAPersonOnItsAnklesExactly) {
  const PlanePerson p = StandingPlanePerson(1.0);
  const std::vector<TypicalLimb> limbs = ResolveTypicalLimbs(CocoBodyJoints());
  const GroundJoints ground = ResolveGroundJoints(CocoBodyJoints());
  SingleViewOptions options;
  std::vector<double> ratios;
  Eigen::Matrix4Xd person(4, 17);
  double scale = 0;
  ASSERT_TRUE(PlaceOnGround(options, p.kps.data(), CameraAt2m(), limbs, ground, &ratios, &person, &scale));
  EXPECT_NEAR(scale, std::sqrt(0.06 * 0.06 + 0.5 * 0.5) / 0.5, 1e-12);
  EXPECT_NEAR(scale, 1.007174, 1e-6);
  for (int j : {kAnkleL, kHipR, kShoulderL, kWristR, kNose}) {
    const Eigen::Vector3d expected = CameraAt2m().center + p.kps[j].ray;
    EXPECT_LT((person.col(j).head<3>() - expected).norm(), 1e-12) << "joint " << j;
    EXPECT_DOUBLE_EQ(person(3, j), 0.9 * options.score_factor);
  }
  EXPECT_EQ(person.col(1).norm(), 0.0) << "a joint not detected stays zero";
}

TEST(PlaceOnGround, WithoutAnklesStandsTheHipsAtTheirHeight) {
  // Hips at 0.90 m = hip_height_m: the same exact placement from the hips.
  const PlanePerson p = StandingPlanePerson(1.0, /*ankles=*/false);
  SingleViewOptions options;
  std::vector<double> ratios;
  Eigen::Matrix4Xd person(4, 17);
  ASSERT_TRUE(PlaceOnGround(options, p.kps.data(), CameraAt2m(), ResolveTypicalLimbs(CocoBodyJoints()),
                            ResolveGroundJoints(CocoBodyJoints()), &ratios, &person, nullptr));
  EXPECT_LT((person.col(kShoulderR).head<3>() - Eigen::Vector3d(4, -0.18, 1.40)).norm(), 1e-12);
  // Every ray 0.1 m higher at x = 4: the hips' plane is met farther, at t = (0.9 - 2) / (-1.1 + 0.1) = 1.1.
  PlanePerson high = p;
  for (Keypoint& k : high.kps) k.ray.z() += 0.1;
  ASSERT_TRUE(PlaceOnGround(options, high.kps.data(), CameraAt2m(), ResolveTypicalLimbs(CocoBodyJoints()),
                            ResolveGroundJoints(CocoBodyJoints()), &ratios, &person, nullptr));
  EXPECT_NEAR(person(0, kHipL), 4.0 * 1.1, 1e-12);
}

TEST(PlaceOnGround, RejectsImplausibleSizesAndPostures) {
  const std::vector<TypicalLimb> limbs = ResolveTypicalLimbs(CocoBodyJoints());
  const GroundJoints ground = ResolveGroundJoints(CocoBodyJoints());
  SingleViewOptions options;  // body scale 0.75 .. 1.30, upright cosine >= 0.5
  std::vector<double> ratios;
  Eigen::Matrix4Xd person(4, 17);
  double scale = 0;
  // Twice a typical adult (3.5 m tall) standing on the floor: scale 2.014.
  EXPECT_FALSE(PlaceOnGround(options, StandingPlanePerson(2.0).kps.data(), CameraAt2m(), limbs, ground, &ratios,
                             &person, &scale));
  EXPECT_NEAR(scale, 2 * 1.007174, 1e-6);
  // A child-sized 0.6: scale 0.604, below 0.75.
  EXPECT_FALSE(PlaceOnGround(options, StandingPlanePerson(0.6).kps.data(), CameraAt2m(), limbs, ground, &ratios,
                             &person, &scale));
  EXPECT_NEAR(scale, 0.6 * 1.007174, 1e-6);
  // Just inside each bound: 0.75 / 1.007174 and 1.30 / 1.007174 of the typical size pass.
  EXPECT_TRUE(PlaceOnGround(options, StandingPlanePerson(0.7451).kps.data(), CameraAt2m(), limbs, ground, &ratios,
                            &person, &scale));
  EXPECT_TRUE(PlaceOnGround(options, StandingPlanePerson(1.2907).kps.data(), CameraAt2m(), limbs, ground, &ratios,
                            &person, &scale));
  EXPECT_FALSE(PlaceOnGround(options, StandingPlanePerson(1.2909).kps.data(), CameraAt2m(), limbs, ground, &ratios,
                             &person, &scale));
  // Lying on a table at hip height, head to the right: torso horizontal (cosine 0), typical size.
  PlanePerson lying;
  lying.Set(kHipL, 0.0, 0.90);
  lying.Set(kHipR, 0.0, 0.90);
  lying.Set(kShoulderL, 0.5, 0.90);
  lying.Set(kShoulderR, 0.5, 0.90);
  lying.Set(kKneeL, -0.42, 0.90);
  lying.Set(kKneeR, -0.42, 0.90);
  EXPECT_FALSE(PlaceOnGround(options, lying.kps.data(), CameraAt2m(), limbs, ground, &ratios, &person, &scale));
  EXPECT_NEAR(scale, 1.0, 1e-12) << "its size is plausible: the posture rejects it";
  options.min_upright = -1;
  EXPECT_TRUE(PlaceOnGround(options, lying.kps.data(), CameraAt2m(), limbs, ground, &ratios, &person, &scale));
  // Feet above the camera's height: the ankle ray goes up and never meets the floor.
  PlanePerson above = StandingPlanePerson(1.0);
  for (Keypoint& k : above.kps) k.ray.z() += 3.0;
  EXPECT_FALSE(PlaceOnGround(options, above.kps.data(), CameraAt2m(), limbs, ground, &ratios, &person, &scale));
}

struct OneViewScene {
  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;
  std::vector<int> core;
  PreparedViews prepared;
  std::vector<TypicalLimb> limbs = ResolveTypicalLimbs(CocoBodyJoints());
  GroundJoints ground = ResolveGroundJoints(CocoBodyJoints());
  Proposals no_proposals;
  Groups no_groups;
  ScoreKernel kernel;
  Poses3D found;

  // `person` detected by camera 0 of `num_cameras` ring cameras only; the others detect nobody.
  explicit OneViewScene(const Eigen::Matrix4Xd& person, int num_cameras = 5) : cameras(test::RingCameras(num_cameras)) {
    std::vector<Poses2D> views = test::ProjectPersons(cameras, {person});
    for (size_t v = 1; v < views.size(); ++v) views[v].Clear(17);
    test::UndistortCocoViews(cameras, views, &geometry, &core, &prepared);
    kernel.scale_m = 0.05;
    found.Clear(17);
  }
  int Run(const SingleViewOptions& options, const Room& room, Poses3D* lifted, FrameStats* stats,
          const Tracks* tracks = nullptr, double timestamp_s = 0) {
    return steps::SingleView(options,
                             {.views = prepared,
                              .geometry = geometry,
                              .core_joints = core,
                              .limbs = limbs,
                              .ground = ground,
                              .room = room,
                              .tracks = tracks,
                              .timestamp_s = timestamp_s,
                              .proposals = no_proposals,
                              .groups = no_groups,
                              .kernel = kernel,
                              .found = found},
                             &scratch, lifted, stats);
  }
  SingleViewScratch scratch;
};

SingleViewOptions GroundPriorOn() {
  SingleViewOptions options;
  options.enabled = true;
  options.ground_prior = true;
  options.min_empty_views = 5;  // the four other views see nobody and must not veto here
  return options;
}

TEST(SingleView, LiftsAPoseOnlyWhenTheOtherViewsDoNotSeeAnEmptySpot) {
  // The person stands in plain view of the four other cameras, which detect nobody: four empty
  // views contradict the pose. With single_view.min_empty_views above four they do not, and the
  // pose is lifted (limb-length depth) to about the person's place.
  const Eigen::Matrix4Xd person = test::StandingPerson(0.5, 0.2);
  OneViewScene scene(person);
  SingleViewOptions options;
  options.enabled = true;
  Poses3D lifted;
  FrameStats stats;
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats), 0) << "four empty views";
  options.min_empty_views = 5;
  ASSERT_EQ(scene.Run(options, Room{}, &lifted, &stats), 1);
  EXPECT_EQ(stats.single_view_persons, 1);
  const Eigen::Vector3d hips = 0.5 * (lifted.Person(0).col(kHipL) + lifted.Person(0).col(kHipR)).head<3>();
  EXPECT_LT((hips - 0.5 * (person.col(kHipL) + person.col(kHipR)).head<3>()).norm(), 0.5);
}

TEST(SingleView, MinEmptyViewsCountsTheEmptyViewsAlone) {
  // Two cameras: the one other view is empty. Under the default (two empty views) that does not
  // veto; with min_empty_views = 1 a single empty view does.
  OneViewScene scene(test::StandingPerson(0.5, 0.2), 2);
  SingleViewOptions options;
  options.enabled = true;
  Poses3D lifted;
  FrameStats stats;
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats), 1) << "one empty view, two needed";
  options.min_empty_views = 1;
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats), 0) << "one empty view, one needed";
}

TEST(SingleViewGroundPrior, PlacesAPersonSeenByOneCameraNearItsPlace) {
  // A 1.75 m person (test_scene.h, ankles 0.08 m above the floor) seen by camera 0 of the ring
  // only, from 3.9 m away and 2.5 m up. Noise-free: the mid-hip lands within 3 cm of the truth
  // (2.1 cm measured; the body is not flat, its joints lie up to 0.25 m off the plane the prior
  // assumes); the limb-length depth of the old placement puts it 6.6 cm off.
  const Eigen::Matrix4Xd truth = test::StandingPerson(0.5, 0.2);
  OneViewScene scene(truth);
  Poses3D lifted;
  FrameStats stats;
  ASSERT_EQ(scene.Run(GroundPriorOn(), Room{}, &lifted, &stats), 1);
  EXPECT_EQ(stats.single_view_persons, 1);
  EXPECT_EQ(stats.single_view_implausible, 0);
  const auto hips = [](const auto& p) { return Eigen::Vector3d(0.5 * (p.col(kHipL) + p.col(kHipR)).template head<3>()); };
  const auto ankles = [](const auto& p) {
    return Eigen::Vector3d(0.5 * (p.col(kAnkleL) + p.col(kAnkleR)).template head<3>());
  };
  const double hip_error = (hips(lifted.Person(0)) - hips(truth)).norm();
  EXPECT_LT(hip_error, 0.03);
  EXPECT_NEAR(ankles(lifted.Person(0)).z(), 0.08, 0.02) << "the feet stand on the floor";

  SingleViewOptions old_options = GroundPriorOn();
  old_options.ground_prior = false;
  ASSERT_EQ(scene.Run(old_options, Room{}, &lifted, &stats), 1);
  EXPECT_GT((hips(lifted.Person(0)) - hips(truth)).norm(), hip_error) << "the floor beats the limb lengths here";
}

TEST(SingleViewGroundPrior, CountsTheImplausibleAndThoseOutsideTheRoom) {
  // The same person 1.6 times larger (2.7 m): not lifted, counted.
  Eigen::Matrix4Xd giant = test::StandingPerson(0.0, 0.0);
  giant.topRows<3>() *= 1.6;
  giant.row(0).array() += 0.5;
  giant.row(1).array() += 0.2;
  OneViewScene scene(giant);
  Poses3D lifted;
  FrameStats stats;
  EXPECT_EQ(scene.Run(GroundPriorOn(), Room{}, &lifted, &stats), 0);
  EXPECT_EQ(stats.single_view_persons, 0);
  EXPECT_EQ(stats.single_view_implausible, 1);

  // A typical person, but the room ends 0.3 m short of it.
  OneViewScene typical(test::StandingPerson(0.5, 0.2));
  Room room;
  room.center_m = Eigen::Vector3d(-1.0, 0.0, 1.0);
  room.size_m = Eigen::Vector3d(2.4, 10.0, 4.0);  // x up to 0.2
  EXPECT_EQ(typical.Run(GroundPriorOn(), room, &lifted, &stats), 0);
  EXPECT_EQ(stats.single_view_implausible, 1);
  room.size_m.x() = 4.0;  // x up to 1.0
  EXPECT_EQ(typical.Run(GroundPriorOn(), room, &lifted, &stats), 1);
  EXPECT_EQ(stats.single_view_implausible, 0);
}

// One live track (id 7) whose last pose is `pose`, supported by two views at `supported_s`.
Tracks OneTrack(const Eigen::Matrix4Xd& pose, double supported_s) {
  Tracks tracks;
  tracks.slots.resize(1);
  tracks.slots[0].id = 7;
  tracks.slots[0].timestamp_s = supported_s;
  tracks.slots[0].supported_s = supported_s;
  tracks.slots[0].pose.assign(pose.data(), pose.data() + pose.size());
  return tracks;
}

TEST(SingleViewTrackAssist, PlacesAPoseAtItsTracksDepthWithAConfidenceThatFallsWithAge) {
  // Seen by camera 0 only, 0.5 s after two views last saw it where it stands: every joint lies on
  // its ray at the camera depth of the track's same joint, i.e. exactly in place; scores
  // 1 x score_factor 0.5 x exp(-0.5 s / 0.5 s).
  const Eigen::Matrix4Xd truth = test::StandingPerson(0.5, 0.2);
  OneViewScene scene(truth);
  SingleViewOptions options = GroundPriorOn();
  options.track_assist = true;
  options.floor_z_m = 10.0;  // the ground prior finds no floor: only the track can place the pose
  const Tracks tracks = OneTrack(truth, 1.0);
  Poses3D lifted;
  FrameStats stats;
  ASSERT_EQ(scene.Run(options, Room{}, &lifted, &stats, &tracks, 1.5), 1);
  EXPECT_EQ(stats.single_view_tracked, 1);
  EXPECT_EQ(stats.single_view_implausible, 0);
  for (int j = 0; j < 17; ++j) {
    EXPECT_LT((lifted.Person(0).col(j).head<3>() - truth.col(j).head<3>()).norm(), 1e-9) << "joint " << j;
    EXPECT_NEAR(lifted.Person(0)(3, j), 0.5 * std::exp(-1.0), 1e-12) << "joint " << j;
  }
  // A track that moved 0.3 m sideways still matches; the depth is the track's, not invented.
  Eigen::Matrix4Xd moved = truth;
  moved.row(1).array() += 0.3;
  const Tracks moved_tracks = OneTrack(moved, 1.0);
  ASSERT_EQ(scene.Run(options, Room{}, &lifted, &stats, &moved_tracks, 1.2), 1);
  EXPECT_EQ(stats.single_view_tracked, 1);
  EXPECT_NEAR(lifted.Person(0)(3, kHipL), 0.5 * std::exp(-0.4), 1e-12);
}

TEST(SingleViewTrackAssist, DropsThePersonWhenItsTrackIsStaleOrContinuedByAFoundPerson) {
  const Eigen::Matrix4Xd truth = test::StandingPerson(0.5, 0.2);
  OneViewScene scene(truth);
  SingleViewOptions options = GroundPriorOn();
  options.track_assist = true;
  options.floor_z_m = 10.0;  // the ground prior finds no floor
  const Tracks tracks = OneTrack(truth, 1.0);
  Poses3D lifted;
  FrameStats stats;
  // 1.0 s after the last multi-view support: still assisted (track_max_age_s = 1.0).
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats, &tracks, 2.0), 1);
  // 1.01 s: stale; the ground prior rejects the pose.
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats, &tracks, 2.01), 0);
  EXPECT_EQ(stats.single_view_tracked, 0);
  EXPECT_EQ(stats.single_view_implausible, 1);
  // Without track_assist the track is ignored.
  options.track_assist = false;
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats, &tracks, 1.5), 0);
  // A track that a person found this frame continues (centre within 0.5 m) assists nobody. The
  // track moved 0.3 m sideways (still matching the pose), the found person 0.4 m beyond it: 0.7 m
  // from the pose's place, so neither its projection nor the duplicate check takes the pose.
  options.track_assist = true;
  Eigen::Matrix4Xd moved = truth, found = truth;
  moved.row(1).array() += 0.3;
  found.row(1).array() += 0.7;
  const Tracks moved_tracks = OneTrack(moved, 1.0);
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats, &moved_tracks, 1.5), 1) << "nobody found yet";
  EXPECT_EQ(stats.single_view_tracked, 1);
  scene.found.AddPerson() = found;
  EXPECT_EQ(scene.Run(options, Room{}, &lifted, &stats, &moved_tracks, 1.5), 0);
  EXPECT_EQ(stats.single_view_tracked, 0);
}

TEST(SingleViewTrackAssist, KeepsAPersonWhoWalksOutOfAllButOneCameraUntilItsTrackIsStale) {
  // Five ring cameras, 10 frames/s; a person walks 5 cm per frame along x. Frames 0-4: all cameras
  // see it (triangulated). From frame 5 only camera 0 does (the others' detections removed, and
  // single_view.min_empty_views = 5 so that their empty views do not veto). The ground prior is
  // made to find no floor (floor_z_m = 10), so only the track can place it: frames 5-14 (up to
  // 1.0 s after the last multi-view support at 0.4 s) keep the person, lifted from one view, with
  // the track id it had and its confidence falling; from frame 15 it is no longer lifted (its
  // track coasts for track.max_missing_frames, then ends).
  const std::vector<Camera> cameras = test::RingCameras(5);
  TriangulatorOptions options;
  options.single_view.enabled = true;
  options.single_view.ground_prior = true;
  options.single_view.floor_z_m = 10.0;
  options.single_view.track_assist = true;
  options.single_view.min_empty_views = 5;
  Triangulator tri(cameras, CocoBodyJoints(), options);
  Poses3D persons;
  FrameStats stats;
  int track_id = -1;
  double last_score = 1.0;
  for (int f = 0; f < 20; ++f) {
    const Eigen::Matrix4Xd truth = test::StandingPerson(-0.5 + 0.05 * f, 0.2);
    std::vector<Poses2D> views = test::ProjectPersons(cameras, {truth});
    if (f >= 5) {
      for (size_t v = 1; v < views.size(); ++v) views[v].Clear(17);
    }
    tri.Process(views, 0.1 * f, &persons, &stats);
    int lifted = -1;
    for (int p = 0; p < persons.num_persons(); ++p) {
      if (persons.Provenance(p, kHipL) == JointProvenance::kLifted) lifted = p;
    }
    if (f < 5) {
      ASSERT_EQ(persons.num_persons(), 1) << "frame " << f;
      EXPECT_EQ(lifted, -1) << "frame " << f;
      track_id = persons.track_ids[0];
    } else if (f <= 14) {
      ASSERT_GE(lifted, 0) << "frame " << f;
      EXPECT_EQ(stats.single_view_tracked, 1) << "frame " << f;
      EXPECT_EQ(persons.track_ids[lifted], track_id) << "frame " << f;
      const Eigen::Vector3d hips = 0.5 * (persons.Person(lifted).col(kHipL) + persons.Person(lifted).col(kHipR)).head<3>();
      // The depth is the track's: off by at most the distance walked since the last multi-view
      // frame (here mostly along camera 0's rays: 0.045 m at frame 5, 0.448 m at frame 14).
      EXPECT_LT((hips - 0.5 * (truth.col(kHipL) + truth.col(kHipR)).head<3>()).norm(), 0.05 * (f - 4) + 0.01)
          << "frame " << f;
      EXPECT_LT(persons.Person(lifted)(3, kHipL), last_score) << "frame " << f;
      last_score = persons.Person(lifted)(3, kHipL);
    } else {
      EXPECT_EQ(lifted, -1) << "frame " << f;
      EXPECT_EQ(stats.single_view_tracked, 0) << "frame " << f;
    }
  }
}

TEST(TracksCommit, RecordsMultiViewSupportOnlyForPersonsWithoutLiftedJoints) {
  Poses3D persons;
  persons.Clear(17);
  persons.AddPerson(3) = test::StandingPerson(0, 0);
  Tracks tracks;
  tracks.slots.resize(1);
  tracks.slots[0].id = 3;
  tracks.Commit(persons, 1, 2.0);
  EXPECT_EQ(tracks.slots[0].supported_s, 2.0) << "triangulated joints";
  std::span<uint8_t> source = persons.PersonProvenance(0);
  ASSERT_EQ(source.size(), 17u);
  source[5] = static_cast<uint8_t>(JointProvenance::kLifted);
  tracks.Commit(persons, 1, 3.0);
  EXPECT_EQ(tracks.slots[0].timestamp_s, 3.0);
  EXPECT_EQ(tracks.slots[0].supported_s, 2.0) << "one lifted joint: no multi-view support";
}

}  // namespace
}  // namespace rpt
