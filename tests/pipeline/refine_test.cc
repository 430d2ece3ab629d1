// SPDX-License-Identifier: MIT
// Step 11a (refine): each merged joint fitted to the rays of all its person's views, with
// confidence and robust (Cauchy) weights; hand-computed cases at the step, a noise-free scene
// through the Triangulator.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "core/pipeline/refine.h"
#include "core/pipeline/simd_kernels.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// One joint seen by several cameras: each view has one pose whose ray for the joint starts at the
// camera centre; the person was merged from the pairs listed.
struct OneJointScene {
  std::vector<ViewGeometry> geometry;
  PreparedViews views;
  Proposals proposals;
  Groups groups;
  ScoreKernel kernel;

  void AddView(const Eigen::Vector3d& center, const Eigen::Vector3d& ray, double confidence) {
    ViewGeometry g{};  // only the centre is read
    g.P.setZero();
    g.Rt.setZero();
    g.R_t.setZero();
    g.center = center;
    geometry.push_back(g);
    views.view_of.push_back(static_cast<int>(views.view_of.size()));
    views.all_columns.stride = 1;
    views.all_columns.rx.push_back(ray.x());
    views.all_columns.ry.push_back(ray.y());
    views.all_columns.rz.push_back(ray.z());
    views.all_columns.score.push_back(confidence);
  }
  void AddPair(int a, int b, double joint_score) {
    proposals.pairs.push_back({a, b});
    proposals.score.push_back(joint_score);
  }
  // Refines the person at `merged`; returns the refined joint and the step's count.
  Eigen::Vector3d Refine(const RefineOptions& options, const Eigen::Vector3d& merged, int* moved = nullptr,
                         double joint_score = 0.8) {
    proposals.num_joints = 1;
    views.num_joints = 1;
    views.all_columns.Resize(views.view_of.size());  // the slack the undistort step leaves
    groups.begin = {0, static_cast<int>(proposals.pairs.size())};
    Poses3D persons;
    persons.Clear(1);
    auto person = persons.AddPerson();
    person.col(0) << merged, joint_score;
    RefineScratch scratch;
    FrameStats stats;
    const int count = steps::Refine(options,
                                    steps::RefineInput{.views = views, .geometry = geometry, .proposals = proposals,
                                                       .groups = groups, .min_joint_score = 0.1, .kernel = kernel},
                                    &scratch, &persons, &stats);
    if (moved != nullptr) *moved = count;
    EXPECT_EQ(persons.Person(0)(3, 0), joint_score) << "the joint's score is not changed";
    return persons.Person(0).col(0).head<3>();
  }
};

RefineOptions On(int iterations) {
  RefineOptions options;
  options.enabled = true;
  options.iterations = iterations;
  return options;
}

// Two perpendicular rays 0.1 m apart along z: the x axis (confidence 0.9) and the line x = 0,
// z = 0.1 (confidence 0.3). The weighted least-squares point is on the common perpendicular at
// z = 0.1 w_b / (w_a + w_b).
OneJointScene SkewRays() {
  OneJointScene scene;
  scene.kernel.scale_m = 0.1;  // s = scale_factor (1) x 0.1 m
  scene.AddView({-5, 0, 0}, {2, 0, 0}, 0.9);  // an unnormalised ray, as undistort writes them
  scene.AddView({0, -5, 0.1}, {0, 1, 0}, 0.3);
  scene.AddPair(0, 1, 0.8);
  return scene;
}

TEST(Refine, WeighsEachViewByItsConfidenceAndItsDistance) {
  // From the midpoint z = 0.05 both rays are 0.05 m away: equal Cauchy factors 1 / (1 + 0.25), so
  // one pass weighs by confidence alone: z = 0.1 x 0.3 / (0.9 + 0.3) = 0.025.
  OneJointScene scene = SkewRays();
  int moved = 0;
  const Eigen::Vector3d once = scene.Refine(On(1), {0, 0, 0.05}, &moved);
  EXPECT_EQ(moved, 1);
  EXPECT_NEAR(once.x(), 0.0, 1e-12);
  EXPECT_NEAR(once.y(), 0.0, 1e-12);
  EXPECT_NEAR(once.z(), 0.025, 1e-12);
  // The second pass starts at z = 0.025: distances 0.025 and 0.075 m, weights 0.9 / 1.0625 and
  // 0.3 / 1.5625 = 0.192, z = 0.1 x 0.192 / (0.9 / 1.0625 + 0.192) = 0.0184782608...
  const Eigen::Vector3d twice = scene.Refine(On(2), {0, 0, 0.05});
  EXPECT_NEAR(twice.z(), 0.018478260869565215, 1e-12);
}

// Three rays through the origin and a fourth passing 0.5 m from it.
OneJointScene ThreeAgreeOneWrong(double wrong_pair_score) {
  OneJointScene scene;
  scene.kernel.scale_m = 0.1;
  scene.AddView({-4, 0, 1}, {4, 0, -1}, 0.8);
  scene.AddView({0, -4, 1.5}, {0, 4, -1.5}, 0.6);
  scene.AddView({3, 3, 2}, {-3, -3, -2}, 0.9);
  scene.AddView({0, 4, 1}, {0.5, -4, -1}, 0.7);  // through (0.5, 0, 0): passes about 0.49 m from the origin
  scene.AddPair(0, 1, 0.8);
  scene.AddPair(0, 2, 0.8);
  scene.AddPair(1, 2, 0.8);
  scene.AddPair(0, 3, wrong_pair_score);
  return scene;
}

TEST(Refine, AViewBeyondTheCutoffGetsNoWeight) {
  OneJointScene scene = ThreeAgreeOneWrong(0.5);
  const Eigen::Vector3d merged(0.02, -0.01, 0.03);
  // Cutoff 3 x 0.1 m: the wrong ray is out, the three others meet exactly at the origin.
  EXPECT_LT(scene.Refine(On(2), merged).norm(), 1e-12);
  // Without the cutoff the wrong ray pulls the point away.
  RefineOptions no_cutoff = On(2);
  no_cutoff.cutoff = 100;
  EXPECT_GT(scene.Refine(no_cutoff, merged).norm(), 0.01);
}

TEST(Refine, UsesOnlyViewsOfPairsTheMergeCouldUse) {
  RefineOptions options = On(2);
  options.cutoff = 100;
  const Eigen::Vector3d merged(0.02, -0.01, 0.03);
  // The wrong view's only pair scores the joint below merge.min_joint_score (0.1): not used.
  OneJointScene below = ThreeAgreeOneWrong(0.05);
  EXPECT_LT(below.Refine(options, merged).norm(), 1e-12);
  OneJointScene above = ThreeAgreeOneWrong(0.1);
  EXPECT_GT(above.Refine(options, merged).norm(), 0.01);
}

TEST(Refine, KeepsTheMergedJointWhenTheRaysDoNotFixIt) {
  const Eigen::Vector3d merged(0.3, 0.2, 0.1);
  // Two rays 0.05 degrees apart: depth is not fixed.
  OneJointScene parallel;
  parallel.kernel.scale_m = 10;  // both well inside the cutoff
  parallel.AddView({-5, 0, 0}, {1, 0, 0}, 0.9);
  parallel.AddView({-5, 0.01, 0}, {1, -0.01 / 5 + std::tan(0.05 * M_PI / 180), 0}, 0.9);
  parallel.AddPair(0, 1, 0.8);
  int moved = -1;
  EXPECT_EQ(parallel.Refine(On(2), merged, &moved), merged);
  EXPECT_EQ(moved, 0);
  // One ray only (the other beyond the cutoff), a missing joint, the step off: unchanged.
  OneJointScene skew = SkewRays();
  RefineOptions tight = On(2);
  tight.cutoff = 0.3;  // 0.03 m: from z = 0.005 only the first ray is near
  EXPECT_EQ(skew.Refine(tight, {0, 0, 0.005}, &moved), Eigen::Vector3d(0, 0, 0.005));
  EXPECT_EQ(moved, 0);
  EXPECT_EQ(skew.Refine(On(2), {0, 0, 0.05}, &moved, 0.0), Eigen::Vector3d(0, 0, 0.05));
  EXPECT_EQ(moved, 0);
  RefineOptions off = On(2);
  off.enabled = false;
  EXPECT_EQ(skew.Refine(off, {0, 0, 0.05}, &moved), Eigen::Vector3d(0, 0, 0.05));
  EXPECT_EQ(moved, 0);
}

// The SIMD kernels give the scalar code's result bit for bit on every instruction set: random
// persons of 13 joints (a partial last vector for every lane count) seen by 5 views, with missing
// joints, unusable pairs and a wrong view.
TEST(Refine, KernelsEqualTheScalarCodeBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  constexpr int kJoints = 13, kViews = 5;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<ViewGeometry> geometry(kViews);
    PreparedViews views;
    views.num_joints = kJoints;
    views.all_columns.stride = kJoints;
    Eigen::Matrix4Xd merged(4, kJoints);
    std::vector<Eigen::Vector3d> truth(kJoints);
    for (int j = 0; j < kJoints; ++j) {
      truth[j] = Eigen::Vector3d(uniform(rng), uniform(rng), 1 + uniform(rng));
      merged.col(j) << truth[j] + 0.05 * Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)),
          uniform(rng) < -0.8 ? 0.0 : 0.5 + 0.4 * uniform(rng);
    }
    for (int v = 0; v < kViews; ++v) {
      geometry[v].P.setZero();
      geometry[v].Rt.setZero();
      geometry[v].R_t.setZero();
      geometry[v].center = Eigen::Vector3d(4 * std::cos(v * 1.3), 4 * std::sin(v * 1.3), 2 + uniform(rng));
      views.view_of.push_back(v);
      for (int j = 0; j < kJoints; ++j) {
        const double off = v == 3 && j % 3 == 0 ? 0.4 : 0.03;  // view 3 gets some joints badly wrong
        const Eigen::Vector3d target = truth[j] + off * Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
        const Eigen::Vector3d ray = (target - geometry[v].center) * (0.5 + uniform(rng) * 0.2);
        views.all_columns.rx.push_back(ray.x());
        views.all_columns.ry.push_back(ray.y());
        views.all_columns.rz.push_back(ray.z());
        views.all_columns.score.push_back(uniform(rng) < -0.7 ? 0.0 : 0.6 + 0.3 * uniform(rng));
      }
    }
    views.all_columns.Resize(static_cast<size_t>(kViews) * kJoints);  // the slack the undistort step leaves
    Proposals proposals;
    proposals.num_joints = kJoints;
    for (int a = 0; a < kViews; ++a)
      for (int b = a + 1; b < kViews; ++b) {
        proposals.pairs.push_back({a, b});
        for (int j = 0; j < kJoints; ++j) proposals.score.push_back(uniform(rng) < -0.6 ? 0.05 : 0.5);
      }
    Groups groups;
    groups.begin = {0, static_cast<int>(proposals.pairs.size())};
    ScoreKernel kernel;
    kernel.scale_m = 0.1;
    auto run = [&](bool simd_on, int iterations) {
      Poses3D persons;
      persons.Clear(kJoints);
      persons.AddPerson() = merged;
      RefineScratch scratch;
      RefineOptions options = On(iterations);
      FrameStats stats;
      simd::SetEnabled(simd_on);
      const int moved = steps::Refine(options,
                                      steps::RefineInput{.views = views, .geometry = geometry, .proposals = proposals,
                                                         .groups = groups, .min_joint_score = 0.1, .kernel = kernel},
                                      &scratch, &persons, &stats);
      simd::SetEnabled(true);
      return std::make_pair(moved, persons.data);
    };
    for (const int iterations : {1, 2}) {
      const auto scalar = run(false, iterations);
      EXPECT_GT(scalar.first, 0);
      simd::ForEachPathForTest([&] {
        const auto lanes = run(true, iterations);
        EXPECT_EQ(lanes.first, scalar.first) << simd::ActivePath();
        ASSERT_EQ(lanes.second.size(), scalar.second.size());
        EXPECT_EQ(std::memcmp(lanes.second.data(), scalar.second.data(), scalar.second.size() * sizeof(double)), 0)
            << simd::ActivePath() << ", trial " << trial << ", " << iterations << " passes";
      });
    }
  }
}

// Through the whole pipeline, on noise-free projections: every joint stays exact and is counted.
// The left wrist seen by camera 0 only: on camera 0's ray through it, at the left elbow's depth.
TEST(Refine, AJointOneViewSawGoesOnItsRayAtItsNeighboursDepth) {
  constexpr int kElbow = 7, kWrist = 9, kShoulder = 5;
  const auto cameras = test::RingCameras(3);
  const Eigen::Matrix4Xd body = test::StandingPerson(0.2, -0.1, 0.7);
  auto views = test::ProjectPersons(cameras, {body});
  views[0].Person(0)(2, kWrist) = 0.8;
  views[1].Person(0)(2, kWrist) = 0;
  views[2].Person(0)(2, kWrist) = 0;
  TriangulatorOptions options;
  options.track.enabled = false;
  FrameStats stats;
  Poses3D persons = test::ProcessOneFrame(cameras, views, options, &stats);
  ASSERT_EQ(persons.num_persons(), 1);
  const Eigen::Vector3d center = cameras[0].Center();
  const Eigen::Vector3d ray = body.col(kWrist).head<3>() - center;
  const Eigen::Vector3d elbow = persons.Person(0).col(kElbow).head<3>();
  const Eigen::Vector3d expected = center + ray * (ray.dot(elbow - center) / ray.squaredNorm());
  EXPECT_LT((persons.Person(0).col(kWrist).head<3>() - expected).norm(), 1e-9);
  EXPECT_GT((expected - body.col(kWrist).head<3>()).norm(), 0.01) << "a guessed depth, not the truth";
  EXPECT_NEAR(persons.Person(0)(3, kWrist), 0.4, 1e-12) << "half its 2D confidence";
  EXPECT_EQ(persons.Provenance(0, kWrist), JointProvenance::kLifted);
  EXPECT_EQ(stats.one_view_joints, 1);

  // Off: the wrist is filled onto the elbow.
  options.refine.one_view_joints = false;
  persons = test::ProcessOneFrame(cameras, views, options, &stats);
  EXPECT_EQ(persons.Provenance(0, kWrist), JointProvenance::kFilled);
  EXPECT_EQ(stats.one_view_joints, 0);

  // The elbow seen by camera 0 only as well: the elbow goes on its ray (its neighbour, the
  // shoulder, was triangulated); the wrist, whose neighbour was not, is filled.
  views[1].Person(0)(2, kElbow) = 0;
  views[2].Person(0)(2, kElbow) = 0;
  options.refine.one_view_joints = true;
  persons = test::ProcessOneFrame(cameras, views, options, &stats);
  EXPECT_EQ(persons.Provenance(0, kElbow), JointProvenance::kLifted);
  EXPECT_EQ(persons.Provenance(0, kShoulder), JointProvenance::kTriangulated);
  EXPECT_EQ(persons.Provenance(0, kWrist), JointProvenance::kFilled);
  EXPECT_EQ(stats.one_view_joints, 1);

  // Two views saw the wrist, 200 px apart from agreeing: no pair kept it, and the views disagree,
  // so neither is taken (it is filled).
  views = test::ProjectPersons(cameras, {body});
  views[0].Person(0)(2, kWrist) = 0;
  views[2].Person(0)(0, kWrist) += 200;
  persons = test::ProcessOneFrame(cameras, views, options, &stats);
  EXPECT_EQ(persons.Provenance(0, kWrist), JointProvenance::kFilled);
  EXPECT_EQ(stats.one_view_joints, 0);
}

TEST(Refine, NoiseFreeSceneStaysExact) {
  const auto cameras = test::RingCameras(4);
  const Eigen::Matrix4Xd body = test::StandingPerson(0.2, -0.1, 0.7);
  const auto views = test::ProjectPersons(cameras, {body});
  TriangulatorOptions options;
  options.refine.enabled = true;
  options.track.enabled = false;
  options.clip_speed.enabled = false;
  FrameStats stats;
  const Poses3D persons = test::ProcessOneFrame(cameras, views, options, &stats);
  ASSERT_EQ(persons.num_persons(), 1);
  for (int j = 0; j < 17; ++j) EXPECT_LT((persons.Person(0).col(j).head<3>() - body.col(j).head<3>()).norm(), 1e-9) << j;
  EXPECT_EQ(stats.count[static_cast<int>(Step::kRefine)], persons.num_joints) << "every joint, derived ones included";
}

}  // namespace
}  // namespace rpt
