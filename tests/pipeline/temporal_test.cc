// SPDX-License-Identifier: MIT
// The optional temporal steps: causal smoothing (step 16), per-track bone-length consistency
// (step 15), and that both are off by default. Offline smoothing: offline_smoother_test.cc.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/model.h"
#include "core/pipeline/bone_lengths.h"
#include "core/pipeline/smooth.h"
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMaxGap = 1.0;  // TrackOptions default

// One frame of single-joint persons: positions and track ids (score 1).
Poses3D Points(const std::vector<Eigen::Vector3d>& xyz, const std::vector<int>& ids) {
  Poses3D persons;
  persons.Clear(1);
  for (size_t p = 0; p < xyz.size(); ++p) persons.AddPerson(ids[p]).col(0) << xyz[p], 1.0;
  return persons;
}

// Step 16 on `frame` at time `t`: the first `num_detected` persons are smoothed.
int Smooth(const SmoothOptions& options, double t, double unobserved_score, int num_detected, JointFilters* filters,
           Poses3D* frame) {
  const steps::SmoothInput input{
      .timestamp_s = t, .max_gap_s = kMaxGap, .unobserved_score = unobserved_score, .num_detected = num_detected};
  return steps::Smooth(options, input, filters, frame);
}

SmoothOptions Causal() {
  SmoothOptions options;
  options.mode = SmoothMode::kCausal;
  return options;
}

// Steady-state gains of the alpha-beta filter that a constant-velocity Kalman filter (white-noise
// acceleration held over each interval) settles to at a fixed frame interval (Kalata 1984), and
// the variance reduction of its position estimate for white measurement noise on a
// constant-velocity track (Benedict and Bordner 1962; Kalata 1984).
struct AlphaBeta {
  double alpha, beta, variance_ratio;
};
AlphaBeta SteadyState(double noise_m, double acceleration_m_s2, double dt) {
  const double lambda = acceleration_m_s2 * dt * dt / noise_m;
  const double root = std::sqrt(lambda * lambda + 8 * lambda);
  const double alpha = -(lambda * lambda + 8 * lambda - (lambda + 4) * root) / 8;
  const double beta = (lambda * lambda + 4 * lambda - lambda * root) / 4;
  const double ratio = (2 * alpha * alpha + 2 * beta - 3 * alpha * beta) / (alpha * (4 - 2 * alpha - beta));
  return {alpha, beta, ratio};
}

TEST(SmoothCausal, ReducesJitterOnAConstantVelocityTrackAsTheAlphaBetaTheoryPredicts) {
  // A joint walking at 1.1 m/s, observed at 25 fps with 2 cm noise per axis. The filter does not
  // lag behind constant velocity, so its RMS error is the noise times sqrt(variance ratio): with
  // the defaults (lambda = 10 * 0.04^2 / 0.02 = 0.8) 0.79 x the raw error; with a smaller assumed
  // acceleration (2 m/s^2, lambda = 0.16) 0.59 x.
  const double dt = 0.04, sigma = 0.02;
  const Eigen::Vector3d velocity(1.0, 0.45, 0.0);
  for (double acceleration : {10.0, 2.0}) {
    SCOPED_TRACE(testing::Message() << "acceleration_m_s2 " << acceleration);
    SmoothOptions options = Causal();
    options.measurement_noise_m = sigma;
    options.acceleration_m_s2 = acceleration;
    const AlphaBeta theory = SteadyState(sigma, acceleration, dt);
    JointFilters filters;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, sigma);
    double raw_sq = 0, smooth_sq = 0;
    Eigen::Vector3d bias = Eigen::Vector3d::Zero();
    int n = 0;
    for (int f = 0; f < 40000; ++f) {
      const Eigen::Vector3d truth = velocity * (f * dt);
      const Eigen::Vector3d observed = truth + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      Poses3D frame = Points({observed}, {0});
      Smooth(options, f * dt, 0.0, 1, &filters, &frame);
      if (f < 200) continue;  // let the gains settle
      raw_sq += (observed - truth).squaredNorm();
      smooth_sq += (frame.Person(0).col(0).head<3>() - truth).squaredNorm();
      bias += frame.Person(0).col(0).head<3>() - truth;
      ++n;
    }
    const double ratio = std::sqrt(smooth_sq / raw_sq);
    EXPECT_NEAR(ratio, std::sqrt(theory.variance_ratio), 0.02) << "RMS error ratio (theory "
                                                                << std::sqrt(theory.variance_ratio) << ")";
    EXPECT_LT((bias / n).norm(), 0.001) << "no lag on constant velocity";
  }
  EXPECT_NEAR(std::sqrt(SteadyState(0.02, 10.0, 0.04).variance_ratio), 0.791, 0.001);
  EXPECT_NEAR(std::sqrt(SteadyState(0.02, 2.0, 0.04).variance_ratio), 0.593, 0.001);
}

TEST(SmoothCausal, FollowsAStepWithBoundedLagAndOvershoot) {
  // A still joint jumps 30 cm. With the defaults the first output covers alpha = 71 % of the
  // step, the filter overshoots by less than 12 % (11.8 %) and is within 5 % of the new position from the
  // 5th frame on, within 1 % from the 10th.
  const SmoothOptions options = Causal();
  const double dt = 0.04, step = 0.3;
  JointFilters filters;
  std::vector<double> response;
  for (int f = 0; f < 130; ++f) {
    const double x = f < 100 ? 0.0 : step;
    Poses3D frame = Points({Eigen::Vector3d(x, 0, 1)}, {3});
    Smooth(options, f * dt, 0.0, 1, &filters, &frame);
    if (f >= 100) response.push_back(frame.Person(0)(0, 0) / step);
  }
  EXPECT_NEAR(response[0], SteadyState(options.measurement_noise_m, options.acceleration_m_s2, dt).alpha, 1e-6);
  for (size_t k = 1; k < response.size(); ++k) {
    EXPECT_LT(std::abs(response[k] - 1), 0.125) << "frame " << k;
    if (k >= 4) {
      EXPECT_LT(std::abs(response[k] - 1), 0.05) << "frame " << k;
    }
    if (k >= 9) {
      EXPECT_LT(std::abs(response[k] - 1), 0.01) << "frame " << k;
    }
  }
}

TEST(SmoothCausal, RestartsAfterGapsAndUnknownTimes) {
  const SmoothOptions options = Causal();
  JointFilters filters;
  auto feed = [&](double t, double x) {
    Poses3D frame = Points({Eigen::Vector3d(x, 0, 1)}, {0});
    Smooth(options, t, 0.0, 1, &filters, &frame);
    return frame.Person(0)(0, 0);
  };
  for (int f = 0; f < 10; ++f) feed(f * 0.04, 0.0);
  EXPECT_LT(feed(0.40, 0.5), 0.5) << "continuous: smoothed";
  EXPECT_EQ(feed(0.40 + 1.5, 2.0), 2.0) << "a gap over max_gap_s restarts the filter";
  EXPECT_LT(feed(1.94, 2.5), 2.5) << "continuous again";
  EXPECT_EQ(feed(kNaN, 3.0), 3.0) << "unknown time restarts the filter";
  EXPECT_EQ(feed(1.98, 3.5), 3.5) << "the frame after an unknown time too";
  EXPECT_LT(feed(2.02, 4.0), 4.0);
}

TEST(SmoothCausal, MissingFilledAndCoastingJointsAreLeftAloneAndTracksAreSeparate) {
  const SmoothOptions options = Causal();
  const double filled = 0.05;
  JointFilters filters;
  for (int f = 0; f < 10; ++f) {
    Poses3D frame = Points({Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(5, 0, 1)}, {0, 1});
    Smooth(options, f * 0.04, filled, 2, &filters, &frame);
  }
  // Track 0's joint is missing, track 1's is filled, and a coasting track 2 follows them: none
  // changes and none updates its filter.
  Poses3D frame = Points({Eigen::Vector3d(9, 9, 9), Eigen::Vector3d(7, 7, 7), Eigen::Vector3d(8, 8, 8)}, {0, 1, 2});
  frame.Person(0)(3, 0) = 0;
  frame.Person(1)(3, 0) = filled;
  const Poses3D before = frame;
  EXPECT_EQ(Smooth(options, 0.40, filled, 2, &filters, &frame), 0);
  EXPECT_EQ(frame.data, before.data);
  // Next frame: both tracks continue from where they were (not from the ignored values), and a
  // new track starts with its input.
  Poses3D next = Points({Eigen::Vector3d(5, 0, 1), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(2, 2, 2)}, {1, 0, 4});
  EXPECT_EQ(Smooth(options, 0.44, filled, 3, &filters, &next), 2);
  EXPECT_LT((next.Person(0).col(0).head<3>() - Eigen::Vector3d(5, 0, 1)).norm(), 1e-9) << "track 1 kept its own state";
  EXPECT_LT((next.Person(1).col(0).head<3>() - Eigen::Vector3d(0, 0, 1)).norm(), 1e-9) << "track 0 kept its own state";
  EXPECT_EQ(next.Person(2)(0, 0), 2.0) << "a new track starts with its input";
}

// --- Bone lengths -------------------------------------------------------------------------------

struct Skeleton {
  std::vector<ResolvedLimb> limbs;
  std::vector<int> neighbour;
};
Skeleton BodySkeleton() {
  const JointNames& names = CocoBodyJoints();
  Skeleton s;
  s.limbs = ResolveLimbs(LimbsFor(names), names);
  s.neighbour = NeighbourIndices(names);
  return s;
}

// Step 15 on `frame`: the first `num_detected` persons are checked.
int CheckBones(const BoneLengthOptions& options, const Skeleton& s, double unobserved_score, int num_detected,
               BoneLengthHistory* history, Poses3D* frame, FrameStats* stats) {
  BoneLengthsScratch scratch;
  return steps::BoneLengths(
      options,
      {.limbs = s.limbs, .neighbour = s.neighbour, .unobserved_score = unobserved_score, .num_detected = num_detected},
      history, &scratch, frame, stats);
}

// A person walking along x at 1 m/s with `noise_m` Gaussian noise per joint and axis.
Poses3D Walker(int f, double noise_m, std::mt19937_64* rng, int id = 0) {
  std::normal_distribution<double> noise(0.0, noise_m);
  Poses3D persons;
  persons.Clear(17);
  auto person = persons.AddPerson(id);
  person = test::StandingPerson(0.04 * f, 0.0);
  for (int j = 0; j < 17; ++j) person.col(j).head<3>() += Eigen::Vector3d(noise(*rng), noise(*rng), noise(*rng));
  return persons;
}

TEST(BoneLengths, MarksExactlyTheCorruptedJoint) {
  const Skeleton s = BodySkeleton();
  const int wrist = FindJoint(CocoBodyJoints(), "wrist_left");
  const int elbow = FindJoint(CocoBodyJoints(), "elbow_left");
  BoneLengthOptions options;
  options.enabled = true;
  for (double filled : {0.0, 0.05}) {
    SCOPED_TRACE(testing::Message() << "filled score " << filled);
    BoneLengthHistory history;
    std::mt19937_64 rng(5);
    FrameStats stats;
    for (int f = 0; f < 30; ++f) {
      Poses3D frame = Walker(f, 0.01, &rng);
      const Poses3D before = frame;
      const int checked = CheckBones(options, s, filled, 1, &history, &frame, &stats);
      EXPECT_EQ(checked, f < options.min_observations ? 0 : 12) << "12 joints have limbs, checked once known";
      EXPECT_EQ(frame.data, before.data) << "clean frame " << f;
    }
    EXPECT_EQ(stats.bone_length_corrections, 0);

    // The wrist moves 30 cm in one frame: only the wrist is marked (the elbow still agrees with
    // its upper arm).
    Poses3D frame = Walker(30, 0.01, &rng);
    frame.Person(0).col(wrist).head<3>() += Eigen::Vector3d(0, 0.3, 0);
    Poses3D before = frame;
    CheckBones(options, s, filled, 1, &history, &frame, &stats);
    EXPECT_EQ(stats.bone_length_corrections, 1);
    for (int j = 0; j < 17; ++j) {
      if (j == wrist) continue;
      EXPECT_EQ(Eigen::Vector4d(frame.Person(0).col(j)), Eigen::Vector4d(before.Person(0).col(j))) << "joint " << j;
    }
    if (filled > 0) {
      EXPECT_EQ(frame.Person(0)(3, wrist), filled) << "filled from its neighbour like in post-processing";
      EXPECT_EQ(Eigen::Vector3d(frame.Person(0).col(wrist).head<3>()), Eigen::Vector3d(frame.Person(0).col(elbow).head<3>()));
      EXPECT_EQ(stats.filled_joints, 1);
    } else {
      EXPECT_EQ(frame.Person(0)(3, wrist), 0.0) << "marked missing";
    }

    // The elbow moves 30 cm: both its limbs disagree; only the elbow is marked, not the wrist.
    frame = Walker(31, 0.01, &rng);
    frame.Person(0).col(elbow).head<3>() += Eigen::Vector3d(0, 0.3, 0);
    before = frame;
    stats.Reset();
    CheckBones(options, s, filled, 1, &history, &frame, &stats);
    EXPECT_EQ(stats.bone_length_corrections, 1);
    EXPECT_LE(frame.Person(0)(3, elbow), filled);
    EXPECT_EQ(Eigen::Vector4d(frame.Person(0).col(wrist)), Eigen::Vector4d(before.Person(0).col(wrist)));
  }
}

TEST(BoneLengths, AMarkedJointIsHeldAtItsTracksOffset) {
  // With the track's last output at hand (track.hold_missing_joints), the marked wrist goes to
  // the elbow plus the wrist's offset from it in that output, not onto the elbow.
  const Skeleton s = BodySkeleton();
  const int wrist = FindJoint(CocoBodyJoints(), "wrist_left");
  const int elbow = FindJoint(CocoBodyJoints(), "elbow_left");
  BoneLengthOptions options;
  options.enabled = true;
  BoneLengthHistory history;
  std::mt19937_64 rng(5);
  FrameStats stats;
  Poses3D last;
  for (int f = 0; f < 30; ++f) {
    last = Walker(f, 0.01, &rng);
    CheckBones(options, s, 0.05, 1, &history, &last, &stats);
  }
  Tracks tracks;
  tracks.slots.push_back(Tracks::Slot{.id = 0, .timestamp_s = 29 * 0.04,
                                      .pose = std::vector<double>(last.data.begin(), last.data.end())});
  Poses3D frame = Walker(30, 0.01, &rng);
  frame.Person(0).col(wrist).head<3>() += Eigen::Vector3d(0, 0.3, 0);
  BoneLengthsScratch scratch;
  steps::BoneLengths(options,
                     {.limbs = s.limbs, .neighbour = s.neighbour, .unobserved_score = 0.05, .num_detected = 1,
                      .tracks = &tracks},
                     &history, &scratch, &frame, &stats);
  EXPECT_EQ(stats.bone_length_corrections, 1);
  EXPECT_EQ(frame.Person(0)(3, wrist), 0.05);
  EXPECT_EQ(frame.Provenance(0, wrist), JointProvenance::kFilled);
  const Eigen::Vector3d offset = last.Person(0).col(wrist).head<3>() - last.Person(0).col(elbow).head<3>();
  EXPECT_LT((frame.Person(0).col(wrist).head<3>() - (frame.Person(0).col(elbow).head<3>() + offset)).norm(), 1e-12);
  EXPECT_GT(offset.norm(), 0.2) << "a forearm away from where the neighbour fill puts it";
}

TEST(BoneLengths, CleanTracksFilledJointsAndCoastingPersonsAreNeverCorrected) {
  const Skeleton s = BodySkeleton();
  const int wrist = FindJoint(CocoBodyJoints(), "wrist_right");
  const int elbow = FindJoint(CocoBodyJoints(), "elbow_right");
  BoneLengthOptions options;
  options.enabled = true;
  BoneLengthHistory history;
  std::mt19937_64 rng(11);
  FrameStats stats;
  for (int f = 0; f < 500; ++f) {
    // Two tracks with 1 cm noise per joint and axis.
    Poses3D frame = Walker(f, 0.01, &rng, 0);
    Poses3D other = Walker(f, 0.01, &rng, 1);
    other.Person(0).row(1).array() += 2.0;
    frame.AddPerson(1) = other.Person(0);
    if (f % 10 == 5) {
      // A filled wrist sits on its elbow (bone length 0): not an observation.
      frame.Person(0).col(wrist) = frame.Person(0).col(elbow);
      frame.Person(0)(3, wrist) = 0.05;
    }
    if (f >= 100 && f < 103) {
      // A coasting person (a third track) with a broken skeleton.
      auto coasting = frame.AddPerson(2);
      coasting = test::StandingPerson(-2, -2);
      coasting.col(wrist).head<3>() += Eigen::Vector3d(1, 0, 0);
    }
    const Poses3D before = frame;
    CheckBones(options, s, 0.05, 2, &history, &frame, &stats);
    EXPECT_EQ(frame.data, before.data) << "frame " << f;
  }
  EXPECT_EQ(stats.bone_length_corrections, 0);
}

// --- In the pipeline ----------------------------------------------------------------------------

struct SceneRun {
  std::vector<Poses3D> persons;
  std::vector<FrameStats> stats;
};

// A small synthetic scene through the triangulator.
SceneRun RunScene(const TriangulatorOptions& base, const std::vector<double>& times, int frames = 60) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = 4;
  options.num_people = 3;
  options.num_frames = frames;
  options.seed = 5;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 5);
  TriangulatorOptions tri_options = base;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  SceneRun run;
  run.persons.resize(frames);
  run.stats.resize(frames);
  std::vector<Poses2D> views;
  for (int f = 0; f < frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views);
    tri.Process(views, times.empty() ? f / scene.fps : times[f], &run.persons[f], &run.stats[f]);
  }
  return run;
}

TEST(TemporalSteps, AreOffByDefaultAndLeaveOutputsBitIdentical) {
  const TriangulatorOptions defaults;
  EXPECT_EQ(defaults.smooth.mode, SmoothMode::kOff);
  EXPECT_FALSE(defaults.bone_lengths.enabled);
  // Disabled steps ignore their parameters: outputs are bit-identical whatever they are set to.
  TriangulatorOptions disabled;
  disabled.smooth.measurement_noise_m = 1e-3;
  disabled.smooth.acceleration_m_s2 = 0.01;
  disabled.bone_lengths.tolerance_rel = 0.01;
  disabled.bone_lengths.min_tolerance_m = 0;
  disabled.bone_lengths.min_observations = 1;
  const SceneRun a = RunScene(defaults, {});
  const SceneRun b = RunScene(disabled, {});
  for (size_t f = 0; f < a.persons.size(); ++f) {
    ASSERT_EQ(a.persons[f].track_ids, b.persons[f].track_ids);
    ASSERT_EQ(0, std::memcmp(a.persons[f].data.data(), b.persons[f].data.data(), a.persons[f].data.size() * sizeof(double)))
        << "frame " << f;
    EXPECT_EQ(a.stats[f].count[static_cast<int>(Step::kBoneLengths)], 0);
    EXPECT_EQ(a.stats[f].count[static_cast<int>(Step::kSmooth)], 0);
    EXPECT_EQ(a.stats[f].bone_length_corrections, 0);
  }
  // Enabled, they do change the outputs (so the comparison above is not vacuous).
  TriangulatorOptions enabled = disabled;
  enabled.smooth.mode = SmoothMode::kCausal;
  enabled.bone_lengths.enabled = true;
  const SceneRun c = RunScene(enabled, {});
  int smoothed = 0, corrected = 0;
  for (const FrameStats& s : c.stats) {
    smoothed += s.count[static_cast<int>(Step::kSmooth)];
    corrected += s.bone_length_corrections;
  }
  EXPECT_GT(smoothed, 0);
  EXPECT_GT(corrected, 0) << "a 1 % tolerance flags noise";
  EXPECT_NE(c.persons.back().data, a.persons.back().data);
}

TEST(TemporalSteps, StartAfreshAfterAGapInThePipeline) {
  // Frames 0-29 continuous, then 1.5 s later frames 30-59, and frame 45 without a time. The first
  // frame after the gap, the frame with the unknown time and the one after it (its predecessor's
  // time is unknown) depend on nothing before them: with
  // the temporal steps on they equal the run with them off, bit for bit (fixed score scale: the
  // adaptive noise estimate carries over gaps and would differ between the runs).
  std::vector<double> times;
  for (int f = 0; f < 60; ++f) times.push_back(f < 30 ? f * 0.04 : 1.5 + f * 0.04);
  times[45] = kNaN;
  TriangulatorOptions off;
  off.score.scale = ScoreScale::kFixed;
  TriangulatorOptions on = off;
  on.smooth.mode = SmoothMode::kCausal;
  on.bone_lengths.enabled = true;
  on.bone_lengths.min_observations = 1;
  const SceneRun a = RunScene(off, times);
  const SceneRun b = RunScene(on, times);
  for (int f : {0, 30, 45, 46}) {
    SCOPED_TRACE(testing::Message() << "frame " << f);
    ASSERT_GT(a.persons[f].num_persons(), 0);
    EXPECT_EQ(a.persons[f].data, b.persons[f].data);
    EXPECT_EQ(b.stats[f].count[static_cast<int>(Step::kSmooth)], 0) << "nothing to smooth with";
    EXPECT_EQ(b.stats[f].count[static_cast<int>(Step::kBoneLengths)], 0) << "no lengths known yet";
  }
  EXPECT_GT(b.stats[31].count[static_cast<int>(Step::kSmooth)], 0);
  EXPECT_GT(b.stats[47].count[static_cast<int>(Step::kSmooth)], 0);
}

}  // namespace
}  // namespace rpt
