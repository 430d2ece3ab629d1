// SPDX-License-Identifier: MIT
// Each pipeline step on hand-made geometry. Over 500 lines on purpose: the steps share one
// hand-made scene (the fixture at the top), so their tests stay together.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/model.h"
#include "core/pipeline/filter.h"
#include "core/pipeline/group.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/merge.h"
#include "core/pipeline/postprocess.h"
#include "core/pipeline/prefilter.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/score.h"
#include "core/pipeline/triangulate_core.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/view_geometry.h"
#include "core/triangulation.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

std::vector<int> CoreIndices(const JointNames& names) {
  std::vector<int> out;
  for (const auto& n : DefaultCoreJoints()) out.push_back(FindJoint(names, n));
  return out;
}

// Prepared views of `persons` seen by `num_cameras` ring cameras (17 joints + 3 derived).
struct StepFixture {
  explicit StepFixture(int num_cameras, std::vector<Eigen::Matrix4Xd> persons_in)
      : cameras(test::RingCameras(num_cameras)), persons(std::move(persons_in)) {
    for (const Camera& c : cameras) geometry.push_back(MakeViewGeometry(c));
    output = AddDerivedJoints(CocoBodyJoints());
    for (int j = 17; j < static_cast<int>(output.size()); ++j) {
      DerivedJointRule rule{j, {}};
      for (const auto& alt : DerivedJointSources(output[j])) {
        std::vector<int> idx;
        for (const auto& n : alt) idx.push_back(FindJoint(CocoBodyJoints(), n));
        rule.alternatives.push_back(idx);
      }
      derived.push_back(rule);
    }
    core = CoreIndices(output);
    for (int j = 0; j < static_cast<int>(output.size()); ++j) all.push_back(j);
    views = test::ProjectPersons(cameras, persons);
  }
  void Prepare(const UndistortOptions& options = {}) {
    steps::Undistort(options,
                     steps::UndistortInput{.views = views,
                                           .cameras = cameras,
                                           .geometry = geometry,
                                           .derived = derived,
                                           .core_joints = core,
                                           .num_output_joints = static_cast<int>(output.size())},
                     &prepared);
  }
  std::vector<Camera> cameras;
  std::vector<Eigen::Matrix4Xd> persons;
  std::vector<ViewGeometry> geometry;
  JointNames output;
  std::vector<DerivedJointRule> derived;
  std::vector<int> core, all;
  std::vector<Poses2D> views;
  PreparedViews prepared;
};

steps::TriangulateCoreInput CoreInput(const StepFixture& f, const std::vector<PosePair>& pairs,
                                      const std::vector<int>& joints) {
  return {.views = f.prepared, .geometry = f.geometry, .pairs = pairs, .joints = joints};
}

// Steps 6-7 on `proposals`, with a fresh noise estimate (at the prior until the frame's votes).
void Score(const StepFixture& f, const ScoreOptions& options, const std::vector<ResolvedLimb>& limbs,
           Proposals* proposals) {
  NoiseScale noise(options.noise_prior_m);
  ScoreScratch scratch;
  ScoreKernel kernel;
  FrameStats stats;
  steps::Score(options, {.views = f.prepared, .geometry = f.geometry, .core_joints = f.core, .core_limbs = limbs},
               &noise, &scratch, proposals, &kernel, &stats);
}

TEST(TriangulateMidpoint, RecoversPointFromExactRays) {
  const Eigen::Vector3d X(0.3, -0.2, 1.1), c1(4, 0, 2), c2(0, 4, 2);
  Eigen::Vector3d point;
  double gap = -1;
  ASSERT_TRUE(TriangulateMidpoint(c1, X - c1, c2, 2.0 * (X - c2), &point, &gap));
  EXPECT_LT((point - X).norm(), 1e-12);
  EXPECT_LT(gap, 1e-12);
}

TEST(TriangulateMidpoint, GapOfSkewRaysAndDegenerateCases) {
  Eigen::Vector3d point;
  double gap = 0;
  // Rays along x at z=0 and along y at z=1 (both starting "behind" the crossing point).
  ASSERT_TRUE(TriangulateMidpoint(Eigen::Vector3d(-5, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, -5, 1),
                                  Eigen::Vector3d(0, 1, 0), &point, &gap));
  EXPECT_NEAR(gap, 1.0, 1e-12);
  EXPECT_LT((point - Eigen::Vector3d(0, 0, 0.5)).norm(), 1e-12);
  EXPECT_FALSE(TriangulateMidpoint(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(2, 0, 0), &point, &gap))
      << "parallel rays";
  EXPECT_FALSE(TriangulateMidpoint(Eigen::Vector3d(-5, 0, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, -5, 0),
                                   Eigen::Vector3d(0, 1, 0), &point, &gap))
      << "crossing behind the first camera";
}

TEST(Undistort, RaysPassThroughTheJointsAndDerivedJointsAreAdded) {
  StepFixture f(3, {test::StandingPerson(0.2, -0.1, 0.4)});
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 3);
  ASSERT_EQ(f.prepared.num_joints, 20);
  for (int g = 0; g < 3; ++g) {
    const int v = f.prepared.view_of[g];
    const Keypoint* kps = f.prepared.Pose(g);
    for (int j = 0; j < 17; ++j) {
      const Eigen::Vector3d X = f.persons[0].col(j).head<3>();
      const Eigen::Vector3d to_point = (X - f.geometry[v].center).normalized();
      EXPECT_LT((kps[j].ray.normalized() - to_point).norm(), 1e-9) << "view " << v << " joint " << j;
    }
    // hip_middle is the mean of the hips in normalised coordinates.
    const int hip_middle = FindJoint(f.output, "hip_middle");
    EXPECT_NEAR(kps[hip_middle].x, 0.5 * (kps[11].x + kps[12].x), 1e-12);
    EXPECT_NEAR(kps[FindJoint(f.output, "head")].y, 0.5 * (kps[3].y + kps[4].y), 1e-12);
    EXPECT_GT(f.prepared.bbox_diag[g], 100.0);
  }
}

TEST(Undistort, LowScoresNaNsAndPosesWithoutCoreJointsAreMissing) {
  StepFixture f(2, {test::StandingPerson(0, 0)});
  f.views[0].Person(0)(2, 5) = 0.05;        // below min_joint_score
  f.views[0].Person(0)(0, 6) = std::nan("");  // NaN coordinate
  f.views[1].Person(0).row(2).setZero();     // nothing visible in view 1
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 1);
  EXPECT_EQ(f.prepared.Pose(0)[5].score, 0.0);
  EXPECT_EQ(f.prepared.Pose(0)[6].score, 0.0);
  EXPECT_EQ(f.prepared.Pose(0)[FindJoint(f.output, "shoulder_middle")].score, 0.0);
  EXPECT_EQ(f.prepared.view_begin, (std::vector<int>{0, 1, 1}));
}

TEST(Undistort, DropsPosesWithFewerValidCoreJointsThanItsMinimum) {
  StepFixture f(2, {test::StandingPerson(0, 0)});
  for (int j = 0; j < 17; ++j) {
    if (j != 5 && j != 6 && j != 11 && j != 12) f.views[1].Person(0)(2, j) = 0;  // 4 core joints in view 1
  }
  UndistortOptions options;
  options.min_core_joints = 4;
  f.Prepare(options);
  EXPECT_EQ(f.prepared.num_poses(), 2);
  options.min_core_joints = 5;
  f.Prepare(options);
  EXPECT_EQ(f.prepared.num_poses(), 1);
  EXPECT_EQ(f.prepared.view_of[0], 0);
}

// The keypoints of a frame are written into the last frame's slots: a frame with fewer poses,
// missing joints and a dropped pose after a frame where everything was seen gives exactly what
// a first frame would (no joint, derived joint or column keeps a value of the frame before).
TEST(Undistort, AFrameAfterAnotherEqualsAFirstFrame) {
  StepFixture f(3, {test::StandingPerson(-1, 0), test::StandingPerson(1, 0.5)});
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 6);
  f.views[0].Person(0)(2, 11) = 0;              // a hip missing: hip_middle cannot be derived
  f.views[0].Person(1)(0, 6) = std::nan("");    // a NaN coordinate
  f.views[1].Person(0).row(2).setZero();        // nobody in view 1 for person 0: pose dropped
  f.views[2].Clear(17);                         // view 2 sees nobody
  StepFixture first = f;
  first.prepared = PreparedViews{};
  first.Prepare();
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 3);
  EXPECT_EQ(f.prepared.view_of, first.prepared.view_of);
  EXPECT_EQ(f.prepared.bbox_diag, first.prepared.bbox_diag);
  ASSERT_EQ(f.prepared.keypoints.size(), first.prepared.keypoints.size());
  for (size_t k = 0; k < f.prepared.keypoints.size(); ++k) {
    const Keypoint& a = f.prepared.keypoints[k];
    const Keypoint& b = first.prepared.keypoints[k];
    EXPECT_TRUE(a.u == b.u && a.v == b.v && a.score == b.score && a.sqrt_score == b.sqrt_score && a.ray == b.ray &&
                a.x == b.x && a.y == b.y)
        << "keypoint " << k;
  }
  EXPECT_EQ(f.prepared.all_columns.score, first.prepared.all_columns.score);
  EXPECT_EQ(f.prepared.all_columns.rx, first.prepared.all_columns.rx);
  EXPECT_EQ(f.prepared.Pose(0)[FindJoint(f.output, "hip_middle")].score, 0.0);
}

TEST(MakePairs, EveryCrossViewPairOnce) {
  StepFixture f(3, {test::StandingPerson(-1, 0), test::StandingPerson(1, 0)});
  f.views[2].Clear(17);  // view 2 sees nobody
  auto extra = f.views[1].AddPerson();
  extra = test::ProjectPersons({f.cameras[1]}, {test::StandingPerson(0, 1.5)})[0].Person(0);
  f.Prepare();
  std::vector<PosePair> pairs;
  EXPECT_EQ(steps::MakePairs(f.prepared, PairListing::kAll, &pairs), 2 * 3);
  ASSERT_EQ(pairs.size(), 6u);
  for (const PosePair& p : pairs) EXPECT_LT(f.prepared.view_of[p.a], f.prepared.view_of[p.b]);
  // Counted, not listed (the pre-filter lists what it keeps): the same count, no pair.
  EXPECT_EQ(steps::MakePairs(f.prepared, PairListing::kCountOnly, &pairs), 2 * 3);
  EXPECT_TRUE(pairs.empty());
}

TEST(Prefilter, KeepsBothOrNeitherMatchedDropsOneSided) {
  const auto a = test::StandingPerson(-1, 0), b = test::StandingPerson(1, 0), c = test::StandingPerson(0, 1.5);
  StepFixture f(2, {a, b, c});
  f.Prepare();
  std::vector<PosePair> pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  ASSERT_EQ(pairs.size(), 9u);
  // Previous frame knew a and b (slightly moved), not c.
  PreviousPersons previous;
  previous.Clear(static_cast<int>(f.core.size()));
  for (const auto* person : {&a, &b}) {
    for (int c_idx : f.core) {
      previous.xyz.push_back(person->col(c_idx).head<3>() + Eigen::Vector3d(0.03, 0, 0));
      previous.score.push_back(1.0);
    }
  }
  PrefilterScratch scratch;
  const std::vector<int>& match = scratch.match;
  const steps::PrefilterInput input{
      .views = f.prepared, .geometry = f.geometry, .core_joints = f.core, .previous = previous, .timestamp_s = 0.0};
  const int kept = steps::Prefilter(PrefilterOptions{}, input, &scratch, &pairs);
  // Kept: a-a, b-b (same match), c-c (neither). Dropped: mixed ones and one-sided c-x / x-c.
  EXPECT_EQ(kept, 3);
  for (const PosePair& p : pairs) {
    EXPECT_EQ(f.prepared.person_of[p.a], f.prepared.person_of[p.b]);
  }
  EXPECT_EQ(match[f.prepared.view_begin[0] + 2], kPoseFree);
  // Disabled: everything stays.
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  PrefilterOptions off;
  off.enabled = false;
  EXPECT_EQ(steps::Prefilter(off, input, &scratch, &pairs), 9);
}

// The pair budget (prefilter.h): of the pairs matched to one person only max_pairs_per_person are
// kept, first the two best of every pose, then the best others; best = sin of the angle between
// the two cameras' directions from the person's last centre x the 2D confidence the two poses
// share on the core joints. Five cameras around one person whose views see it with different
// confidences; the expected pairs follow that rule, worked out here from the cameras and the
// confidences.
TEST(Prefilter, PairBudgetKeepsEveryPosesTwoBestPairsThenTheBestOthers) {
  const auto person = test::StandingPerson(0, 0);
  StepFixture f(5, {person});
  const double confidence[5] = {0.2, 0.9, 1.0, 0.8, 0.3};
  for (int v = 0; v < 5; ++v) f.views[v].Person(0).row(2).setConstant(confidence[v]);
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 5);
  PreviousPersons previous;
  previous.Clear(static_cast<int>(f.core.size()));
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int c : f.core) {
    previous.xyz.push_back(person.col(c).head<3>());
    previous.score.push_back(1.0);
    centre += person.col(c).head<3>() / static_cast<double>(f.core.size());
  }
  std::vector<PosePair> all;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  ASSERT_EQ(all.size(), 10u);
  // The rule by hand: quality of every pair, best first (ties: the earlier pair).
  std::vector<std::pair<double, int>> order;
  for (int k = 0; k < 10; ++k) {
    const int va = f.prepared.view_of[all[k].a], vb = f.prepared.view_of[all[k].b];
    const Eigen::Vector3d da = (f.geometry[va].center - centre).normalized();
    const Eigen::Vector3d db = (f.geometry[vb].center - centre).normalized();
    const double evidence = static_cast<double>(f.core.size()) * std::sqrt(confidence[va] * confidence[vb]);
    order.emplace_back(-da.cross(db).norm() * evidence, k);
  }
  std::sort(order.begin(), order.end());
  for (const int budget : {3, 7, 8}) {
    std::vector<bool> expected(10, false);
    int covered[5] = {0, 0, 0, 0, 0}, used = 0;
    for (const auto& [quality, k] : order) {  // every pose's two best
      const int va = f.prepared.view_of[all[k].a], vb = f.prepared.view_of[all[k].b];
      if (covered[va] >= 2 && covered[vb] >= 2) continue;
      ++covered[va];
      ++covered[vb];
      expected[k] = true;
      ++used;
    }
    for (const auto& [quality, k] : order) {  // then the best others, up to the budget
      if (used >= budget) break;
      if (!expected[k]) {
        expected[k] = true;
        ++used;
      }
    }
    std::vector<PosePair> pairs = all;
    PrefilterScratch scratch;
    PrefilterOptions options;
    options.max_pairs_per_person = budget;
    options.best_pairs_per_pose = 2;  // the rule above
    const int kept = steps::Prefilter(
        options, {.views = f.prepared, .geometry = f.geometry, .core_joints = f.core, .previous = previous, .timestamp_s = 0},
        &scratch, &pairs);
    ASSERT_EQ(kept, used) << "budget " << budget;
    ASSERT_EQ(pairs.size(), static_cast<size_t>(used));
    for (int k = 0, i = 0; k < 10; ++k) {
      if (!expected[k]) continue;
      EXPECT_EQ(pairs[i].a, all[k].a) << "budget " << budget << ", kept pair " << i;
      EXPECT_EQ(pairs[i].b, all[k].b) << "budget " << budget << ", kept pair " << i;
      ++i;
    }
    if (budget == 3) {
      EXPECT_GT(kept, 3) << "every pose keeps two pairs, even above the budget";
    } else {
      EXPECT_EQ(kept, budget);
    }
  }
}

// The last frame's persons for the pre-filter: the core joints of `persons`, each with score 1.
PreviousPersons PreviousOf(const StepFixture& f, const std::vector<Eigen::Matrix4Xd>& persons) {
  PreviousPersons previous;
  previous.Clear(static_cast<int>(f.core.size()));
  for (const Eigen::Matrix4Xd& person : persons) {
    for (int c : f.core) {
      previous.xyz.push_back(person.col(c).head<3>());
      previous.score.push_back(1.0);
    }
  }
  return previous;
}

// The pre-filter with `options` on a fresh copy of `all` (make_pairs' output) at time 0: returns
// how many it kept, which are then the first entries of *pairs.
int RunPrefilter(const StepFixture& f, const PreviousPersons& previous, const PrefilterOptions& options,
                 const std::vector<PosePair>& all, std::vector<PosePair>* pairs, PrefilterScratch* scratch) {
  *pairs = all;
  return steps::Prefilter(
      options, {.views = f.prepared, .geometry = f.geometry, .core_joints = f.core, .previous = previous, .timestamp_s = 0},
      scratch, pairs);
}

// The pair budget worked out the slow way the header states it, for the pairs `bucket` (indices
// into `pairs`) of one person whose last core joints have the mean `centre`: sorted best first
// (quality as in the test above, from the prepared views' sqrt scores; ties: the earlier pair),
// kept while one of the two poses has fewer than `per_pose` kept pairs, then the best others up
// to `budget`. Sets keep[k] for the kept ones.
void BudgetByHand(const StepFixture& f, const std::vector<PosePair>& pairs, const std::vector<int>& bucket,
                  const Eigen::Vector3d& centre, int budget, int per_pose, std::vector<bool>* keep) {
  std::vector<std::pair<double, int>> order;
  for (int k : bucket) {
    const PosePair& pair = pairs[k];
    const Eigen::Vector3d da = (f.geometry[f.prepared.view_of[pair.a]].center - centre).normalized();
    const Eigen::Vector3d db = (f.geometry[f.prepared.view_of[pair.b]].center - centre).normalized();
    double evidence = 0;
    for (int c : f.core) evidence += f.prepared.Pose(pair.a)[c].sqrt_score * f.prepared.Pose(pair.b)[c].sqrt_score;
    order.emplace_back(-da.cross(db).norm() * evidence, k);
  }
  std::sort(order.begin(), order.end());
  std::vector<int> covered(f.prepared.num_poses(), 0);
  int used = 0;
  for (const auto& [quality, k] : order) {
    if (covered[pairs[k].a] >= per_pose && covered[pairs[k].b] >= per_pose) continue;
    ++covered[pairs[k].a];
    ++covered[pairs[k].b];
    (*keep)[k] = true;
    ++used;
  }
  for (const auto& [quality, k] : order) {
    if (used >= budget) break;
    if (!(*keep)[k]) {
      (*keep)[k] = true;
      ++used;
    }
  }
}

// The mean of a previous person's core joints, summed then divided as the pre-filter does.
Eigen::Vector3d CoreCentre(const Eigen::Matrix4Xd& person, const std::vector<int>& core) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int c : core) sum += person.col(c).head<3>();
  return sum / static_cast<double>(core.size());
}

// Every joint of every view its own confidence in [0.3, 1) (a fixed pseudo-random pattern per seed).
void VaryConfidences(StepFixture* f, uint32_t seed = 12345) {
  uint32_t state = seed;
  for (Poses2D& view : f->views) {
    for (int p = 0; p < view.num_persons(); ++p) {
      for (int j = 0; j < view.num_joints; ++j) {
        state = state * 1664525u + 1013904223u;
        view.Person(p)(2, j) = 0.3 + 0.7 * static_cast<double>(state >> 8) / 16777216.0;
      }
    }
  }
}

// Twelve cameras, two persons, a confidence per joint: every person has 66 pairs, and each
// budget (and count of each pose's best pairs) keeps exactly the pairs of the rule, in make_pairs'
// order; also when the pre-filter's core joints are not the undistort step's (their sqrt scores
// are then gathered, not read from its columns).
TEST(Prefilter, PairBudgetOnTwelveViewsKeepsThePairsOfTheRule) {
  const std::vector<Eigen::Matrix4Xd> persons = {test::StandingPerson(-0.6, 0), test::StandingPerson(0.6, 0.3, 1.0)};
  StepFixture f(12, persons);
  VaryConfidences(&f);
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 24);
  const PreviousPersons previous = PreviousOf(f, persons);
  std::vector<PosePair> all;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  std::vector<std::vector<int>> bucket(2);  // each person's own pairs; the mixed ones are dropped
  for (int k = 0; k < static_cast<int>(all.size()); ++k) {
    const int pa = f.prepared.person_of[all[k].a], pb = f.prepared.person_of[all[k].b];
    if (pa == pb) bucket[pa].push_back(k);
  }
  ASSERT_EQ(bucket[0].size(), 66u);
  ASSERT_EQ(bucket[1].size(), 66u);
  for (const auto& [budget, per_pose] : std::vector<std::pair<int, int>>{
           {1, 2}, {13, 2}, {30, 2}, {50, 2}, {65, 2}, {66, 2}, {0, 2}, {1, 1}, {13, 1}, {30, 1}, {13, 3}, {30, 4}}) {
    std::vector<bool> expected(all.size(), false);
    for (int p = 0; p < 2; ++p) {
      if (budget == 0 || budget >= 66) {  // off, or not over the budget: all kept
        for (int k : bucket[p]) expected[k] = true;
      } else {
        BudgetByHand(f, all, bucket[p], CoreCentre(persons[p], f.core), budget, per_pose, &expected);
      }
    }
    std::vector<PosePair> want;
    for (size_t k = 0; k < all.size(); ++k) {
      if (expected[k]) want.push_back(all[k]);
    }
    StepFixture other_core = f;  // the undistort step's core joints in another order
    std::reverse(other_core.prepared.core_joints.begin(), other_core.prepared.core_joints.end());
    for (const StepFixture* fixture : {&f, &other_core}) {
      const std::string where = "budget " + std::to_string(budget) + ", " + std::to_string(per_pose) + " per pose" +
                                (fixture == &f ? "" : ", gathered");
      std::vector<PosePair> pairs;
      PrefilterScratch scratch;
      PrefilterOptions options;
      options.max_pairs_per_person = budget;
      options.best_pairs_per_pose = per_pose;
      const int kept = RunPrefilter(*fixture, previous, options, all, &pairs, &scratch);
      ASSERT_EQ(kept, static_cast<int>(want.size())) << where;
      ASSERT_EQ(pairs.size(), want.size()) << where;
      for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_TRUE(pairs[i].a == want[i].a && pairs[i].b == want[i].b) << where << ", kept pair " << i;
      }
      if (budget == 30 && per_pose <= 2) {
        EXPECT_EQ(kept, 60);  // two persons, each exactly at the budget
      }
      if (budget == 1) {  // the poses' best pairs alone: at least 6 (1 per pose) or 12 (2) per person
        EXPECT_GE(kept, 2 * 6 * per_pose);
      }
    }
  }
}

// Ties in the budget go to the earlier pair. Cameras 0, 1 and 2 stand at one place, 3 and 4 at
// another: the six pairs across the two places have exactly the same quality, the four within a
// place quality 0 (their rays meet at angle 0). Each pose's best is then its earliest pair across,
// and of the others the earliest come first, also when a later equal one would push it out.
TEST(Prefilter, PairBudgetTiesGoToTheEarlierPair) {
  const std::vector<Eigen::Matrix4Xd> persons = {test::StandingPerson(0, 0)};
  StepFixture f(5, persons);
  for (const auto& [copy, of] : {std::pair{1, 0}, {2, 0}, {4, 3}}) {
    const std::string name = f.cameras[copy].name;
    f.cameras[copy] = f.cameras[of];
    f.cameras[copy].name = name;
  }
  for (int v = 0; v < 5; ++v) f.geometry[v] = MakeViewGeometry(f.cameras[v]);
  f.views = test::ProjectPersons(f.cameras, f.persons);
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 5);
  std::vector<PosePair> all;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  ASSERT_EQ(all.size(), 10u);  // pose = view
  const auto kept_pairs = [&](int budget) {
    std::vector<PosePair> pairs;
    PrefilterScratch scratch;
    PrefilterOptions options;
    options.max_pairs_per_person = budget;
    options.best_pairs_per_pose = 1;
    RunPrefilter(f, PreviousOf(f, persons), options, all, &pairs, &scratch);
    std::vector<std::pair<int, int>> kept;
    for (const PosePair& pair : pairs) kept.emplace_back(pair.a, pair.b);
    return kept;
  };
  using Kept = std::vector<std::pair<int, int>>;
  // Poses 0 and 3 take (0,3), 1 (1,3), 2 (2,3), 4 (0,4).
  EXPECT_EQ(kept_pairs(1), (Kept{{0, 3}, {0, 4}, {1, 3}, {2, 3}}));
  // The best others: (1,4) and (2,4), then (0,1) of the pairs of quality 0.
  EXPECT_EQ(kept_pairs(6), (Kept{{0, 3}, {0, 4}, {1, 3}, {1, 4}, {2, 3}, {2, 4}}));
  EXPECT_EQ(kept_pairs(7), (Kept{{0, 1}, {0, 3}, {0, 4}, {1, 3}, {1, 4}, {2, 3}, {2, 4}}));
}

// Each pose's best pairs alone (budget 1), over many confidence patterns: whatever order a pose's
// pairs come in (its best after its second best, ...), the kept pairs are the rule's.
TEST(Prefilter, EveryPosesBestPairsWhateverTheOrderTheyComeIn) {
  const std::vector<Eigen::Matrix4Xd> persons = {test::StandingPerson(0, 0)};
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    StepFixture f(9, persons);
    VaryConfidences(&f, seed);
    f.Prepare();
    const PreviousPersons previous = PreviousOf(f, persons);
    std::vector<PosePair> all;
    steps::MakePairs(f.prepared, PairListing::kAll, &all);
    std::vector<int> bucket(all.size());
    for (size_t k = 0; k < all.size(); ++k) bucket[k] = static_cast<int>(k);
    for (const int per_pose : {2, 3, 4}) {
      std::vector<bool> expected(all.size(), false);
      BudgetByHand(f, all, bucket, CoreCentre(persons[0], f.core), 1, per_pose, &expected);
      std::vector<PosePair> pairs;
      PrefilterScratch scratch;
      PrefilterOptions options;
      options.max_pairs_per_person = 1;
      options.best_pairs_per_pose = per_pose;
      RunPrefilter(f, previous, options, all, &pairs, &scratch);
      std::vector<bool> got(all.size(), false);
      for (const PosePair& pair : pairs) {
        for (size_t k = 0; k < all.size(); ++k) got[k] = got[k] || (all[k].a == pair.a && all[k].b == pair.b);
      }
      ASSERT_EQ(got, expected) << "seed " << seed << ", " << per_pose << " per pose";
    }
  }
}

// A pose between two previous persons is ambiguous. It pairs with the poses matched to either of
// them (within twice the match radius of it) and with free poses, but not with the poses of a
// person standing elsewhere: that pair is the paper's one-sided case.
TEST(Prefilter, AnAmbiguousPosePairsOnlyWithThePersonsItIsAmbiguousBetween) {
  const Eigen::Matrix4Xd person = test::StandingPerson(0, 0);
  Eigen::Matrix4Xd beside = person;
  beside.row(1).array() += 0.3;  // a previous person 30 cm to the side
  const Eigen::Matrix4Xd elsewhere = test::StandingPerson(0.5, -1.6);  // beside person, seen from view 0
  const Eigen::Matrix4Xd newcomer = test::StandingPerson(-1.59, 0.85);  // not in the last frame: free
  StepFixture f(4, {person, elsewhere, newcomer});
  // View 0 sees `person` halfway between where `person` and `beside` project.
  const Poses2D there = test::ProjectPersons({f.cameras[0]}, {beside})[0];
  f.views[0].Person(0).topRows(2) = 0.5 * (f.views[0].Person(0).topRows(2) + there.Person(0).topRows(2));
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 12);
  const PreviousPersons previous = PreviousOf(f, {person, beside, elsewhere});
  std::vector<PosePair> all, pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  ASSERT_EQ(all.size(), 54u);  // 6 view pairs x 3 x 3
  PrefilterScratch scratch;
  const int kept = RunPrefilter(f, previous, PrefilterOptions{}, all, &pairs, &scratch);
  // Poses: view v holds person (3v), elsewhere (3v + 1) and newcomer (3v + 2).
  ASSERT_EQ(scratch.match[0], kPoseAmbiguous);
  for (int v = 0; v < 4; ++v) {
    if (v > 0) {
      ASSERT_EQ(scratch.match[3 * v], 0) << "view " << v;
    }
    ASSERT_EQ(scratch.match[3 * v + 1], 2) << "view " << v;
    ASSERT_EQ(scratch.match[3 * v + 2], kPoseFree) << "view " << v;
  }
  // Kept: the 6 pairs of each person (3 of person's with the ambiguous pose), and the ambiguous
  // pose with the 3 free poses of the newcomer in the other views.
  EXPECT_EQ(kept, 21);
  int with_newcomer = 0;
  for (const PosePair& pair : pairs) {
    const int pa = f.prepared.person_of[pair.a], pb = f.prepared.person_of[pair.b];
    if (pair.a == 0 && pb == 2) {
      ++with_newcomer;
      continue;
    }
    EXPECT_EQ(pa, pb) << pair.a << "-" << pair.b;
  }
  EXPECT_EQ(with_newcomer, 3);
  // The bound: `elsewhere` is a person the ambiguous pose is ambiguous between once twice the
  // radius exceeds its distance in view 0 (mean core-joint distance to pose 1, `elsewhere` itself).
  double sum = 0;
  for (int c : f.core) {
    const Keypoint &p0 = f.prepared.Pose(0)[c], &p1 = f.prepared.Pose(1)[c];
    sum += std::hypot(p0.u - p1.u, p0.v - p1.v);
  }
  const double distance_rel = sum / static_cast<double>(f.core.size()) / f.prepared.bbox_diag[0];
  for (const double factor : {0.98, 1.02}) {
    PrefilterOptions options;
    options.max_distance_rel = factor * distance_rel / 2;  // twice the radius: factor x the distance
    RunPrefilter(f, previous, options, all, &pairs, &scratch);
    ASSERT_EQ(scratch.match[0], kPoseAmbiguous) << "factor " << factor;
    int with_elsewhere = 0;
    for (const PosePair& pair : pairs) with_elsewhere += pair.a == 0 && f.prepared.person_of[pair.b] == 1 ? 1 : 0;
    EXPECT_EQ(with_elsewhere, factor > 1 ? 3 : 0) << "factor " << factor;
  }
}

// The pairs the pre-filter lists are those of its rule, in make_pairs' order, whatever the mix
// of matched, free and ambiguous poses (budgets off): both matched to one person, both free, or
// an ambiguous pose with a free or ambiguous one or with a pose matched to a person near it
// (scratch.near). A crowd of five known from the last frame, two of them moved, a newcomer, and
// a known person far from the crowd.
TEST(Prefilter, ListsThePairsOfItsRuleInMakePairsOrder) {
  std::vector<Eigen::Matrix4Xd> persons;
  for (int i = 0; i < 5; ++i) persons.push_back(test::StandingPerson(0.55 * (i % 3) - 0.5, 0.6 * (i / 3) - 0.3, i));
  persons.push_back(test::StandingPerson(2.0, 1.5));    // a newcomer, away from the crowd
  persons.push_back(test::StandingPerson(-2.0, -1.5));  // known, far from the crowd's ambiguous poses
  StepFixture f(6, persons);
  f.Prepare();
  std::vector<Eigen::Matrix4Xd> last(persons.begin(), persons.begin() + 5);
  last.push_back(persons[6]);
  last[1].row(0).array() += 0.27;  // halfway to person 2: person 1 is ambiguous between the two
  last[3].row(1).array() -= 0.2;
  const PreviousPersons previous = PreviousOf(f, last);
  std::vector<PosePair> all, pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  PrefilterOptions options;
  options.max_pairs_per_person = 0;
  options.max_pairs_per_ambiguous_pose = 0;
  PrefilterScratch scratch;
  const int kept = RunPrefilter(f, previous, options, all, &pairs, &scratch);
  const std::vector<int>& match = scratch.match;
  const int words = (previous.size() + 63) / 64;
  const auto near = [&](int pose, int person) {
    return ((scratch.near[static_cast<size_t>(pose) * words + person / 64] >> (person % 64)) & 1) != 0;
  };
  std::vector<PosePair> want;
  int ambiguous_second = 0, ambiguous_before_partner = 0, far_from_ambiguous = 0;
  for (const PosePair& pair : all) {
    const int a = match[pair.a], b = match[pair.b];
    far_from_ambiguous += b == kPoseAmbiguous && a >= 0 && !near(pair.b, a) ? 1 : 0;
    bool keep = a == b;
    if (a == kPoseAmbiguous) keep = b < 0 || near(pair.a, b);
    if (b == kPoseAmbiguous) keep = a < 0 || near(pair.b, a);
    if (!keep) continue;
    want.push_back(pair);
    ambiguous_second += b == kPoseAmbiguous && a >= 0 ? 1 : 0;
    // a kept ambiguous b listed before the pose of b's view matched to a's person
    for (int g = pair.b + 1; b == kPoseAmbiguous && a >= 0 && g < f.prepared.num_poses() &&
                             f.prepared.view_of[g] == f.prepared.view_of[pair.b];
         ++g) {
      ambiguous_before_partner += match[g] == a ? 1 : 0;
    }
  }
  ASSERT_EQ(kept, static_cast<int>(want.size()));
  ASSERT_EQ(pairs.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_TRUE(pairs[i].a == want[i].a && pairs[i].b == want[i].b) << "kept pair " << i;
  }
  // The scene has every case the listing handles.
  const auto count = [&](int m) { return std::count(match.begin(), match.end(), m); };
  EXPECT_GT(count(kPoseFree), 1);
  EXPECT_GT(count(kPoseAmbiguous), 1);
  EXPECT_GT(ambiguous_second, 0);
  EXPECT_GT(ambiguous_before_partner, 0);
  EXPECT_GT(far_from_ambiguous, 0);
  EXPECT_LT(kept, static_cast<int>(all.size()) / 2);
}

// Of the pairs of an ambiguous pose with the poses matched to one person, only the
// max_pairs_per_ambiguous_pose best are kept (prefilter.h), best = sin of the angle between the
// two cameras' directions from that person's last centre x the 2D confidence the poses share on
// the core joints, worked out here; its pairs with free poses are not limited. The scene of the
// test above: ambiguous pose 0 in view 0, `person` matched in views 1-3, the newcomer free.
TEST(Prefilter, AnAmbiguousPoseKeepsOnlyItsBestPairsWithEachPerson) {
  const Eigen::Matrix4Xd person = test::StandingPerson(0, 0);
  Eigen::Matrix4Xd beside = person;
  beside.row(1).array() += 0.3;
  const Eigen::Matrix4Xd elsewhere = test::StandingPerson(0.5, -1.6);
  const Eigen::Matrix4Xd newcomer = test::StandingPerson(-1.59, 0.85);
  StepFixture f(4, {person, elsewhere, newcomer});
  const Poses2D there = test::ProjectPersons({f.cameras[0]}, {beside})[0];
  f.views[0].Person(0).topRows(2) = 0.5 * (f.views[0].Person(0).topRows(2) + there.Person(0).topRows(2));
  // Confidences differ per view, so the evidence counts in the ranking too: view 2's ray angle
  // with view 0 has the smallest sine, but view 2 beats view 1 on confidence.
  const double confidence[4] = {0.9, 0.3, 0.95, 0.7};
  for (int v = 0; v < 4; ++v) f.views[v].Person(0).row(2).setConstant(confidence[v]);
  f.Prepare();
  ASSERT_EQ(f.prepared.num_poses(), 12);
  const PreviousPersons previous = PreviousOf(f, {person, beside, elsewhere});
  std::vector<PosePair> all, pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &all);
  // The quality of the ambiguous pose's pair with `person` in view v, at person's last centre.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int c : f.core) centre += person.col(c).head<3>();
  centre /= static_cast<double>(f.core.size());
  auto quality = [&](int v) {
    const Eigen::Vector3d d0 = (f.geometry[0].center - centre).normalized();
    const Eigen::Vector3d dv = (f.geometry[v].center - centre).normalized();
    double evidence = 0;
    for (int c : f.core) evidence += f.prepared.Pose(0)[c].sqrt_score * f.prepared.Pose(3 * v)[c].sqrt_score;
    return d0.cross(dv).norm() * evidence;
  };
  std::vector<int> ranked = {1, 2, 3};  // best first
  std::sort(ranked.begin(), ranked.end(), [&](int x, int y) { return quality(x) > quality(y); });
  ASSERT_GT(quality(ranked[0]), quality(ranked[1]) * 1.05);  // a clear ranking
  ASSERT_GT(quality(ranked[1]), quality(ranked[2]) * 1.05);
  for (const int limit : {1, 2, 3, 0}) {
    PrefilterScratch scratch;
    PrefilterOptions options;
    options.max_pairs_per_ambiguous_pose = limit;
    const int kept = RunPrefilter(f, previous, options, all, &pairs, &scratch);
    ASSERT_EQ(scratch.match[0], kPoseAmbiguous);
    std::vector<int> with_person;  // views of person's poses kept with the ambiguous pose
    int with_newcomer = 0;
    for (int k = 0; k < kept; ++k) {
      if (pairs[k].a != 0) continue;
      const int other = f.prepared.person_of[pairs[k].b];
      if (other == 0) with_person.push_back(f.prepared.view_of[pairs[k].b]);
      if (other == 2) ++with_newcomer;
    }
    std::vector<int> expected(ranked.begin(), ranked.begin() + (limit == 0 ? 3 : limit));
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(with_person, expected) << "limit " << limit;
    EXPECT_EQ(with_newcomer, 3) << "limit " << limit;
    // The other pairs are untouched: 6 of `elsewhere`, 6 of the newcomer, 3 of person's without pose 0.
    EXPECT_EQ(kept, 15 + static_cast<int>(expected.size()) + 3) << "limit " << limit;
  }
  // Near two persons, each has its own limit: with twice the radius just past `elsewhere` (see the
  // test above) pose 0 pairs with `elsewhere` too, and keeps its best pair with each of the two.
  double sum = 0;
  for (int c : f.core) {
    const Keypoint &p0 = f.prepared.Pose(0)[c], &p1 = f.prepared.Pose(1)[c];
    sum += std::hypot(p0.u - p1.u, p0.v - p1.v);
  }
  PrefilterOptions options;
  options.max_distance_rel = 1.02 * sum / static_cast<double>(f.core.size()) / f.prepared.bbox_diag[0] / 2;
  for (const int limit : {0, 1}) {
    options.max_pairs_per_ambiguous_pose = limit;
    PrefilterScratch scratch;
    const int kept = RunPrefilter(f, previous, options, all, &pairs, &scratch);
    ASSERT_EQ(scratch.match[0], kPoseAmbiguous);
    int with[3] = {0, 0, 0};
    for (int k = 0; k < kept; ++k) {
      if (pairs[k].a == 0) ++with[f.prepared.person_of[pairs[k].b]];
    }
    EXPECT_EQ(with[0], limit == 0 ? 3 : 1) << "limit " << limit;
    EXPECT_EQ(with[1], limit == 0 ? 3 : 1) << "limit " << limit;
    EXPECT_EQ(with[2], 3) << "limit " << limit;
  }
}

TEST(TriangulateCore, ExactRecoveryWithMidpointAndDlt) {
  StepFixture f(4, {test::StandingPerson(0.5, 0.3, 1.0)});
  f.Prepare();
  std::vector<PosePair> pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  for (TriangulationMethod method : {TriangulationMethod::kMidpoint, TriangulationMethod::kDlt}) {
    Proposals proposals;
    TriangulateOptions options;
    options.method = method;
    ASSERT_EQ(steps::TriangulateCore(options, CoreInput(f, pairs, f.all), &proposals), 6);
    for (int k = 0; k < proposals.size(); ++k) {
      for (int j = 0; j < 17; ++j) {
        EXPECT_LT((proposals.xyz[k * 20 + j] - f.persons[0].col(j).head<3>()).norm(), 1e-9);
        EXPECT_EQ(proposals.score[k * 20 + j], 1.0);
        EXPECT_LT(proposals.gap[k * 20 + j], 1e-9);
      }
    }
  }
}

TEST(TriangulateCore, PairsWithTooFewCommonJointsYieldNoProposal) {
  StepFixture f(2, {test::StandingPerson(0, 0)});
  for (int j = 0; j < 17; ++j) {
    if (j != 5 && j != 6 && j != 11 && j != 12) f.views[1].Person(0)(2, j) = 0;  // only 4 joints in view 1
  }
  f.Prepare();
  std::vector<PosePair> pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  Proposals proposals;
  TriangulateOptions options;
  options.min_core_joints = 4;
  EXPECT_EQ(steps::TriangulateCore(options, CoreInput(f, pairs, f.core), &proposals), 1);
  options.min_core_joints = 5;
  EXPECT_EQ(steps::TriangulateCore(options, CoreInput(f, pairs, f.core), &proposals), 0);
}

Proposals OneJointProposals(const std::vector<Eigen::Vector3d>& points) {
  Proposals p;
  p.Clear(1);
  for (const auto& x : points) {
    p.Add(PosePair{});
    p.xyz.back() = x;
    p.score.back() = 1.0;
  }
  return p;
}

TEST(RoomCheck, DropsProposalsOutsideTheBoxPlusMargin) {
  Proposals p = OneJointProposals({{0, 0, 1}, {2.9, 0, 1}, {3.2, 0, 1}, {0, 50, 1}});
  const Room room{.center_m = Eigen::Vector3d(0, 0, 1), .size_m = Eigen::Vector3d(5, 0, 3)};  // y unbounded
  RoomCheckOptions options;
  options.margin_m = 0.5;
  EXPECT_EQ(steps::RoomCheck(options, room, &p), 3);
  EXPECT_NEAR(p.xyz[1].x(), 2.9, 1e-12);
  EXPECT_NEAR(p.xyz[2].y(), 50, 1e-12);
  Proposals q = OneJointProposals({{1e6, 0, 0}});
  EXPECT_EQ(steps::RoomCheck(options, Room{}, &q), 1) << "no room: nothing dropped";
  Proposals r = OneJointProposals({{3.2, 0, 1}});
  options.margin_m = 0.8;
  EXPECT_EQ(steps::RoomCheck(options, room, &r), 1) << "the margin is room_check's own";
}

TEST(ScoreProposals, CorrectPairsScoreOneMismatchedPairsScoreLow) {
  StepFixture f(2, {test::StandingPerson(-1.2, 0), test::StandingPerson(1.2, 0.3, 2.0)});
  f.Prepare();
  std::vector<PosePair> pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  Proposals proposals;
  steps::TriangulateCore(TriangulateOptions{}, CoreInput(f, pairs, f.core), &proposals);
  Score(f, ScoreOptions{}, {}, &proposals);
  int correct = 0;
  for (int k = 0; k < proposals.size(); ++k) {
    const bool same = f.prepared.person_of[proposals.pairs[k].a] == f.prepared.person_of[proposals.pairs[k].b];
    if (same) {
      EXPECT_NEAR(proposals.pair_score[k], 1.0, 1e-9);
      ++correct;
    } else {
      EXPECT_LT(proposals.pair_score[k], 0.5);
    }
  }
  EXPECT_EQ(correct, 2);
}

TEST(ScoreProposals, ModesConfidenceAndLimbPruning) {
  StepFixture f(2, {test::StandingPerson(0, 0)});
  // A 20 px error on the left wrist in view 0, and half confidence on the right wrist.
  f.views[0].Person(0)(0, 9) += 20;
  f.views[0].Person(0)(2, 10) = 0.5;
  f.views[1].Person(0)(2, 10) = 0.5;
  f.Prepare();
  std::vector<PosePair> pairs;
  steps::MakePairs(f.prepared, PairListing::kAll, &pairs);
  const int wrist_left_slot = 6, wrist_right_slot = 7;  // order of DefaultCoreJoints()
  auto run = [&](ScoreOptions options, std::vector<ResolvedLimb> limbs = {}) {
    Proposals p;
    steps::TriangulateCore(TriangulateOptions{}, CoreInput(f, pairs, f.core), &p);
    Score(f, options, limbs, &p);
    return p;
  };
  ScoreOptions combined;
  const Proposals c = run(combined);
  EXPECT_LT(c.score[wrist_left_slot], 0.99);
  EXPECT_NEAR(c.score[wrist_right_slot], 0.5, 1e-9) << "joint score carries the 2D confidence";
  ScoreOptions no_conf;
  no_conf.use_confidence = false;
  EXPECT_NEAR(run(no_conf).score[wrist_right_slot], 1.0, 1e-9);
  ScoreOptions rep_only;
  rep_only.mode = ScoreMode::kReprojectionOnly;
  ScoreOptions tri_only;
  tri_only.mode = ScoreMode::kTriangulationOnly;
  const double s_rep = run(rep_only).score[wrist_left_slot], s_tri = run(tri_only).score[wrist_left_slot];
  EXPECT_LT(s_rep, 1.0);
  EXPECT_LT(s_tri, 1.0);
  EXPECT_NEAR(c.score[wrist_left_slot], s_rep * s_tri, 1e-8);  // FastExpNeg precision
  // The pair score leaves out the worst quarter of the joints: one bad wrist out of 12 does not count.
  EXPECT_NEAR(c.pair_score[0], 1.0, 1e-9);
  ScoreOptions untrimmed = combined;
  untrimmed.trim_fraction = 0;
  const Proposals u = run(untrimmed);
  EXPECT_LT(u.pair_score[0], 1.0);
  // Weights: ten joints with confidence 1, the right wrist 0.5, the left wrist 1.
  EXPECT_NEAR(u.pair_score[0], (10.5 + c.score[wrist_left_slot]) / 11.5, 1e-9);
  // A limb (elbow_left -> wrist_left) whose allowed range excludes the true length prunes the wrist.
  const Proposals pruned = run(untrimmed, {ResolvedLimb{4, wrist_left_slot, 0.0, 0.05}});
  EXPECT_EQ(pruned.score[wrist_left_slot], 0.0);
  EXPECT_LT(pruned.pair_score[0], u.pair_score[0]);
}

TEST(Filter, KeepsPairsAtOrAboveTheThreshold) {
  Proposals p = OneJointProposals({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  p.pair_score = {0.95, 0.5, 0.9};
  FilterOptions options;
  options.min_match_score = 0.9;
  EXPECT_EQ(steps::Filter(options, &p), 2);
  EXPECT_NEAR(p.xyz[1].x(), 2.0, 1e-12);
}

TEST(Group, ClustersByPersonAndDropsSmallGroups) {
  Proposals p;
  p.Clear(3);
  auto add = [&](Eigen::Vector3d base, double score) {
    const int k = p.size();
    p.Add(PosePair{2 * k, 2 * k + 1});  // distinct 2D poses per proposal
    for (int i = 0; i < 3; ++i) {
      p.xyz[p.xyz.size() - 3 + i] = base + Eigen::Vector3d(0, 0, 0.5 * i);
      p.score[p.score.size() - 3 + i] = 1.0;
    }
    p.pair_score.back() = score;
  };
  add({0, 0, 0}, 0.95);
  add({2, 0, 0}, 0.99);
  add({0.05, 0, 0}, 0.97);
  add({2.04, 0.02, 0}, 0.93);
  add({0, 0.03, 0.01}, 0.92);
  add({5, 5, 0}, 0.91);  // a lone proposal
  Groups groups;
  GroupScratch scratch;
  FrameStats counters;
  GroupOptions options;
  const std::vector<int> no_mirror = {0, 1, 2};
  EXPECT_EQ(steps::Group(options, {.num_poses = 12, .mirror = no_mirror}, &scratch, &p, &groups, &counters), 3);
  EXPECT_EQ(counters.small_groups, 0);
  EXPECT_EQ(counters.conflicting_proposals, 0);
  EXPECT_EQ(p.group[0], p.group[2]);
  EXPECT_EQ(p.group[0], p.group[4]);
  EXPECT_EQ(p.group[1], p.group[3]);
  EXPECT_NE(p.group[0], p.group[1]);
  options.min_group_size = 2;
  EXPECT_EQ(steps::Group(options, {.num_poses = 12, .mirror = no_mirror}, &scratch, &p, &groups, &counters), 2);
  EXPECT_EQ(counters.small_groups, 1);
  EXPECT_EQ(p.group[5], -1);
  EXPECT_EQ(groups.members.size(), 5u);
}

// Adds a two-joint proposal of poses a and b, its joints at `first` and `second` (both scored 1),
// with pair score `score` (the group tests' proposals).
void AddTwoJointProposal(Proposals* p, int a, int b, const Eigen::Vector3d& first, const Eigen::Vector3d& second,
                         double score) {
  p->Add(PosePair{a, b});
  p->xyz[p->xyz.size() - 2] = first;
  p->xyz[p->xyz.size() - 1] = second;
  p->score[p->score.size() - 2] = p->score[p->score.size() - 1] = 1.0;
  p->pair_score.back() = score;
}

TEST(Group, EqualPairScoresAreVisitedInIndexOrder) {
  // Groups are numbered in creation order, and proposals are visited by decreasing pair score,
  // ties by index: of two far-apart proposals with equal scores the first makes group 0; a third,
  // stronger one, is visited first.
  Proposals p;
  p.Clear(2);
  auto add = [&](Eigen::Vector3d x, double score) {
    AddTwoJointProposal(&p, 2 * p.size(), 2 * p.size() + 1, x, x + Eigen::Vector3d(0, 0, 0.5), score);
  };
  add({0, 0, 0}, 0.8);
  add({2, 0, 0}, 0.8);
  add({4, 0, 0}, 0.9);
  Groups groups;
  GroupScratch scratch;
  FrameStats counters;
  const std::vector<int> no_mirror = {0, 1};
  ASSERT_EQ(steps::Group(GroupOptions{}, {.num_poses = 6, .mirror = no_mirror}, &scratch, &p, &groups, &counters), 3);
  EXPECT_EQ(p.group[2], 0);
  EXPECT_EQ(p.group[0], 1);
  EXPECT_EQ(p.group[1], 2);
}

TEST(Group, ExclusivePosesRemovePhantomsThatReuseAPersonsPoses) {
  // Person A: poses 0,1,2 (three views) -> proposals (0,1), (0,2), (1,2) near the origin.
  // Phantom: pair (2, 3) -- pose 2 belongs to A -- triangulated 1.5 m away.
  Proposals p;
  p.Clear(2);
  auto add = [&](int a, int b, Eigen::Vector3d x, double score) {
    AddTwoJointProposal(&p, a, b, x, x + Eigen::Vector3d(0, 0, 0.5), score);
  };
  add(0, 1, {0, 0, 0}, 0.95);
  add(0, 2, {0.02, 0, 0}, 0.94);
  add(1, 2, {0, 0.02, 0}, 0.93);
  add(2, 3, {1.5, 0, 0}, 0.99);  // stronger pair score, but a weaker group
  Groups groups;
  GroupScratch scratch;
  FrameStats counters;
  GroupOptions options;
  const std::vector<int> no_mirror = {0, 1};
  EXPECT_EQ(steps::Group(options, {.num_poses = 4, .mirror = no_mirror}, &scratch, &p, &groups, &counters), 1);
  EXPECT_EQ(counters.conflicting_proposals, 1);
  EXPECT_EQ(p.group[3], -1);
  options.exclusive_poses = false;
  EXPECT_EQ(steps::Group(options, {.num_poses = 4, .mirror = no_mirror}, &scratch, &p, &groups, &counters), 2);
  EXPECT_EQ(counters.conflicting_proposals, 0);
}

TEST(Group, MirroredDuplicateOfAPersonIsDropped) {
  // Joints: 0 = left, 1 = right. Person: left at y=+0.2, right at y=-0.2 (three proposals).
  // A left/right-swapped detection pair gives the same person mirrored (one proposal).
  Proposals p;
  p.Clear(2);
  auto add = [&](int a, int b, double left_y, double score) {
    AddTwoJointProposal(&p, a, b, Eigen::Vector3d(0, left_y, 1), Eigen::Vector3d(0, -left_y, 1), score);
  };
  add(0, 1, 0.2, 0.95);
  add(0, 2, 0.21, 0.94);
  add(1, 2, 0.19, 0.93);
  add(3, 4, -0.2, 0.99);  // mirrored: its "left" joint sits on the person's right
  Groups groups;
  GroupScratch scratch;
  FrameStats counters;
  GroupOptions options;
  const std::vector<int> mirror = {1, 0};
  EXPECT_EQ(steps::Group(options, {.num_poses = 5, .mirror = mirror}, &scratch, &p, &groups, &counters), 1);
  EXPECT_EQ(counters.mirrored_groups, 1);
  EXPECT_EQ(p.group[3], -1);
  EXPECT_EQ(p.group[0], 0);
  options.drop_mirrored = false;
  EXPECT_EQ(steps::Group(options, {.num_poses = 5, .mirror = mirror}, &scratch, &p, &groups, &counters), 2);
}

TEST(Group, MirrorCheckUsesTheProposalsExclusivePosesLeft) {
  // Joints: 0 = left, 1 = right. The person (poses 0, 1, 2) as in the test above; a mirrored
  // duplicate (3, 4) that four weak phantoms reusing the person's pose 2 join, each pulling the
  // group's running mean along x (to 0.274 m). exclusive_poses gives pose 2 to the person and
  // removes the phantoms: over what is left the duplicate is the mirrored person (distance 0),
  // while the mean with the phantoms would be 0.274 m away, above max_distance_m (0.25).
  Proposals p;
  p.Clear(2);
  auto add = [&](int a, int b, double x, double left_y, double score) {
    AddTwoJointProposal(&p, a, b, Eigen::Vector3d(x, left_y, 1), Eigen::Vector3d(x, -left_y, 1), score);
  };
  add(0, 1, 0, 0.2, 0.95);
  add(0, 2, 0, 0.21, 0.94);
  add(1, 2, 0, 0.19, 0.93);
  add(3, 4, 0, -0.2, 0.99);
  for (int i = 0; i < 4; ++i) add(2, 5 + i, std::vector<double>{0.2, 0.3, 0.4, 0.47}[i], -0.2, 0.3 - 0.01 * i);
  Groups groups;
  GroupScratch scratch;
  FrameStats counters;
  GroupOptions options;
  const std::vector<int> mirror = {1, 0};
  EXPECT_EQ(steps::Group(options, {.num_poses = 9, .mirror = mirror}, &scratch, &p, &groups, &counters), 1);
  EXPECT_EQ(counters.conflicting_proposals, 4);
  EXPECT_EQ(counters.mirrored_groups, 1);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(p.group[k], 0) << k;
  for (int k = 3; k < 8; ++k) EXPECT_EQ(p.group[k], -1) << k;
  // Without exclusive_poses the phantoms stay, and the mean they pull keeps the duplicate apart.
  options.exclusive_poses = false;
  EXPECT_EQ(steps::Group(options, {.num_poses = 9, .mirror = mirror}, &scratch, &p, &groups, &counters), 2);
  EXPECT_EQ(counters.mirrored_groups, 0);
}

TEST(JointSide, ReadsTheSideToken) {
  EXPECT_EQ(JointSide("wrist_left"), 1);
  EXPECT_EQ(JointSide("hand_thumb_1_right"), -1);
  EXPECT_EQ(JointSide("nose"), 0);
  EXPECT_EQ(JointSide("leftover_joint"), 0) << "tokens, not substrings";
}

TEST(MirrorJointName, SwapsSideTokens) {
  EXPECT_EQ(MirrorJointName("wrist_left"), "wrist_right");
  EXPECT_EQ(MirrorJointName("hand_thumb_1_right"), "hand_thumb_1_left");
  EXPECT_EQ(MirrorJointName("nose"), "nose");
  EXPECT_EQ(MirrorJointName("face_07"), "face_07");
  const std::vector<int> mirror = MirrorIndices(CocoBodyJoints());
  EXPECT_EQ(mirror[0], 0);
  EXPECT_EQ(mirror[5], 6);
  EXPECT_EQ(mirror[16], 15);
}

TEST(Merge, DistanceFilterTopKAndWeighting) {
  // One group, one joint, five proposals: four near (0,0,0), one outlier at 1 m.
  Proposals p = OneJointProposals({{0.01, 0, 0}, {-0.01, 0, 0}, {0.03, 0, 0}, {0, 0.02, 0}, {1, 0, 0}});
  p.score = {1.0, 1.0, 0.5, 1.0, 1.0};
  Groups groups;
  groups.begin = {0, 5};
  groups.members = {0, 1, 2, 3, 4};
  MergeScratch scratch;
  auto merge = [&](MergeOptions options) {
    Poses3D persons;
    persons.Clear(1);
    steps::Merge(options, {.proposals = p, .groups = groups}, &scratch, &persons);
    return Eigen::Vector4d(persons.Person(0).col(0));
  };
  MergeOptions plain;
  plain.score_weighted = false;
  plain.top_k = 0;
  plain.max_distance_m = 0;
  EXPECT_NEAR(merge(plain).x(), (0.01 - 0.01 + 0.03 + 0 + 1) / 5, 1e-12) << "keep all: plain mean";
  MergeOptions distance = plain;
  distance.max_distance_m = 0.3;  // mean x = 0.206: the outlier is 0.79 away
  EXPECT_NEAR(merge(distance).x(), 0.03 / 4, 1e-12);
  MergeOptions topk = distance;
  topk.top_k = 2;  // distances to the first mean (0.206, 0.004, 0): x=0.03 and x=0.01 are closest
  EXPECT_NEAR(merge(topk).x(), 0.02, 1e-12);
  MergeOptions weighted = distance;
  weighted.score_weighted = true;
  EXPECT_NEAR(merge(weighted).x(), (0.01 - 0.01 + 0.5 * 0.03 + 0) / 3.5, 1e-12);
  EXPECT_NEAR(merge(weighted)(3), (1 + 1 + 0.5 + 1) / 4.0, 1e-12) << "score = mean of kept scores";
  // Two candidates 1 m apart: the distance filter drops both; the fallback keeps the better one.
  Proposals two = OneJointProposals({{0, 0, 0}, {1, 0, 0}});
  two.score = {0.3, 0.8};
  Groups pair_group;
  pair_group.begin = {0, 2};
  pair_group.members = {0, 1};
  Poses3D out;
  out.Clear(1);
  steps::Merge(distance, {.proposals = two, .groups = pair_group}, &scratch, &out);
  EXPECT_NEAR(out.Person(0)(0, 0), 1.0, 1e-12);
  EXPECT_NEAR(out.Person(0)(3, 0), 0.8, 1e-12);
  MergeOptions no_fallback = distance;
  no_fallback.keep_best_when_all_far = false;
  out.Clear(1);
  steps::Merge(no_fallback, {.proposals = two, .groups = pair_group}, &scratch, &out);
  EXPECT_EQ(out.Person(0)(3, 0), 0.0);
  MergeOptions strict = plain;
  strict.min_joint_score = 1.1;
  EXPECT_EQ(merge(strict)(3), 0.0) << "no candidate: missing";
}

TEST(Postprocess, DropsInvalidPersonsAndFillsMissingJoints) {
  const JointNames names = AddDerivedJoints(CocoBodyJoints());
  const std::vector<int> neighbour = NeighbourIndices(names);
  const std::vector<ResolvedLimb> limbs = ResolveLimbs(LimbsFor(names), names);
  Poses3D persons;
  persons.Clear(static_cast<int>(names.size()));
  auto add = [&](const Eigen::Matrix4Xd& body) {
    auto person = persons.AddPerson();
    person.leftCols(17) = body;
  };
  Eigen::Matrix4Xd good = test::StandingPerson(0, 0);
  good(3, 9) = 0;  // wrist_left missing -> filled from elbow_left
  add(good);
  Eigen::Matrix4Xd wrong = test::StandingPerson(1.5, 0);
  wrong.col(10).head<3>() += Eigen::Vector3d(0, 0, 1.5);  // wrist_right 1.5 m off -> replaced
  add(wrong);
  Eigen::Matrix4Xd tiny = test::StandingPerson(-1.5, 0);
  tiny.topRows(3) = tiny.topRows(3) * 0.05;  // 9 cm tall
  add(tiny);
  Eigen::Matrix4Xd few = test::StandingPerson(0, 1.5);
  few.row(3).tail(12).setZero();  // 5 joints only
  add(few);
  add(test::StandingPerson(40, 0));  // outside the room
  const Room room{.size_m = Eigen::Vector3d(10, 10, 0)};
  const steps::PostprocessInput input{.neighbour = neighbour, .limbs = limbs, .room = room};
  FrameStats stats;
  EXPECT_EQ(steps::Postprocess(PostprocessOptions{}, input, &persons, &stats), 2);
  EXPECT_EQ(persons.num_persons(), 2);
  EXPECT_GE(stats.filled_joints, 2);
  EXPECT_EQ(stats.replaced_joints, 1);
  EXPECT_LT((persons.Person(0).col(9).head<3>() - good.col(7).head<3>()).norm(), 1e-12);
  EXPECT_NEAR(persons.Person(0)(3, 9), PostprocessOptions{}.filled_joint_score, 1e-12);
  EXPECT_LT((persons.Person(1).col(10).head<3>() - wrong.col(8).head<3>()).norm(), 1e-12);
  // Filled joints say so (the replaced wrist too); the others stay triangulated.
  EXPECT_EQ(persons.Provenance(0, 9), JointProvenance::kFilled);
  EXPECT_EQ(persons.Provenance(0, 7), JointProvenance::kTriangulated);
  EXPECT_EQ(persons.Provenance(1, 10), JointProvenance::kFilled);
  EXPECT_EQ(persons.Provenance(1, 8), JointProvenance::kTriangulated);
  EXPECT_EQ(persons.provenance.size(), 2 * names.size());

  // A kept person after a dropped one moves down with its provenance.
  Poses3D moved;
  moved.Clear(static_cast<int>(names.size()));
  moved.AddPerson().leftCols(17) = tiny;
  moved.AddPerson().leftCols(17) = good;
  EXPECT_EQ(steps::Postprocess(PostprocessOptions{}, input, &moved, &stats), 1);
  EXPECT_EQ(moved.Provenance(0, 9), JointProvenance::kFilled);
  EXPECT_EQ(moved.Provenance(0, 7), JointProvenance::kTriangulated);
  EXPECT_EQ(moved.provenance.size(), names.size());

  PostprocessOptions off;
  off.enabled = false;
  add(tiny);
  EXPECT_EQ(steps::Postprocess(off, input, &persons, &stats), 3);
}

// A joint whose proximal joint was never triangulated is measured from the nearest joint up the
// chain that was, allowing the limb's maximum once per limb (a whole-body user's junk hand points:
// a finger joint 1.5 m from its wrist, its parents missing, was kept, and pushed whole persons past
// max_extent_m). A joint whose proximal joint this rule removed is not measured, as before.
TEST(Postprocess, AJointWithoutItsParentIsMeasuredFromTheNearestJointUpItsChain) {
  const JointNames names = AddDerivedJoints(CocoBodyJoints());
  const std::vector<int> neighbour = NeighbourIndices(names);
  const std::vector<ResolvedLimb> limbs = ResolveLimbs(LimbsFor(names), names);
  const int shoulder = FindJoint(names, "shoulder_left"), elbow = FindJoint(names, "elbow_left"),
            wrist = FindJoint(names, "wrist_left");
  ASSERT_EQ(neighbour[wrist], elbow);
  ASSERT_EQ(neighbour[elbow], shoulder);
  const Room room{.size_m = Eigen::Vector3d(10, 10, 0)};
  const steps::PostprocessInput input{.neighbour = neighbour, .limbs = limbs, .room = room};
  // The forearm allows 0.55 m, the upper arm 0.60: a wrist without its elbow may lie up to 2 x 0.55
  // = 1.10 m from the shoulder (the forearm's limb, counted twice).
  const auto run = [&](double wrist_from_shoulder_m, double elbow_score, double elbow_from_shoulder_m) {
    Poses3D persons;
    persons.Clear(static_cast<int>(names.size()));
    Eigen::Matrix4Xd body = test::StandingPerson(0, 0);
    const Eigen::Vector3d out(1, 0, 0);  // the arm held out sideways
    body.col(elbow).head<3>() = body.col(shoulder).head<3>() + elbow_from_shoulder_m * out;
    body(3, elbow) = elbow_score;
    body.col(wrist).head<3>() = body.col(shoulder).head<3>() + wrist_from_shoulder_m * out;
    persons.AddPerson().leftCols(17) = body;
    FrameStats stats;
    EXPECT_EQ(steps::Postprocess(PostprocessOptions{}, input, &persons, &stats), 1);
    return std::pair(persons.Provenance(0, wrist), stats.replaced_joints);
  };
  EXPECT_EQ(run(1.09, 0, 0.3), std::pair(JointProvenance::kTriangulated, 0)) << "within 1.10 m of the shoulder";
  EXPECT_EQ(run(1.11, 0, 0.3), std::pair(JointProvenance::kFilled, 1)) << "beyond: replaced, filled";
  // The elbow 0.7 m out (over 0.60): removed (filled onto the shoulder); the wrist beyond it is not
  // measured from the shoulder, however far (walking past removed joints took right hand joints
  // with a wrong wrist on the whole-body scene).
  EXPECT_EQ(run(1.0, 0.9, 0.7), std::pair(JointProvenance::kTriangulated, 1));
  EXPECT_EQ(run(2.0, 0.9, 0.7), std::pair(JointProvenance::kTriangulated, 1));
}

TEST(Postprocess, JointsPlacedFromOneViewNeitherDecideNorOutweigh) {
  const JointNames names = AddDerivedJoints(CocoBodyJoints());
  const std::vector<int> neighbour = NeighbourIndices(names);
  const std::vector<ResolvedLimb> limbs = ResolveLimbs(LimbsFor(names), names);
  const int elbow = FindJoint(names, "elbow_left"), wrist = FindJoint(names, "wrist_left");
  const Room room{.size_m = Eigen::Vector3d(10, 10, 0)};
  const steps::PostprocessInput input{.neighbour = neighbour, .limbs = limbs, .room = room};
  const auto lifted = static_cast<uint8_t>(JointProvenance::kLifted);
  // A lifted elbow mirrored about the shoulder: the upper arm keeps its length, the forearm is
  // implausible. The elbow (the forearm's proximal end) is dropped and filled onto the shoulder;
  // the triangulated wrist (its distal end) stays where it is.
  const int shoulder = FindJoint(names, "shoulder_left");
  Poses3D persons;
  persons.Clear(static_cast<int>(names.size()));
  const Eigen::Matrix4Xd body = test::StandingPerson(0, 0);
  persons.AddPerson().leftCols(17) = body;
  const Eigen::Vector3d moved = 2 * body.col(shoulder).head<3>() - body.col(elbow).head<3>();
  persons.Person(0).col(elbow).head<3>() = moved;
  persons.PersonProvenance(0)[elbow] = lifted;
  for (const ResolvedLimb& limb : limbs) {
    if (limb.a == elbow && limb.b == wrist) {
      ASSERT_GT((moved - body.col(wrist).head<3>()).squaredNorm(), limb.max_length_sq()) << "forearm implausible";
    }
    if (limb.a == shoulder && limb.b == elbow) {
      const double length_sq = (moved - body.col(shoulder).head<3>()).squaredNorm();
      ASSERT_TRUE(length_sq >= limb.min_length_sq() && length_sq <= limb.max_length_sq()) << "upper arm plausible";
    }
  }
  FrameStats stats;
  ASSERT_EQ(steps::Postprocess(PostprocessOptions{}, input, &persons, &stats), 1);
  EXPECT_EQ(persons.Provenance(0, elbow), JointProvenance::kFilled);
  EXPECT_EQ(persons.Provenance(0, wrist), JointProvenance::kTriangulated);
  EXPECT_EQ(Eigen::Vector4d(persons.Person(0).col(wrist)), Eigen::Vector4d(body.col(wrist)));
  // Three triangulated joints from head to feet (nose, both ankles: an extent the extent check
  // keeps) and lifted ones: too few to make a person (min_valid_joints 4); four are enough.
  ASSERT_EQ(PostprocessOptions{}.min_valid_joints, 4);
  for (const int triangulated : {3, 4}) {
    Poses3D few;
    few.Clear(static_cast<int>(names.size()));
    few.AddPerson().leftCols(17) = body;
    for (int j = 0; j < 17; ++j) few.PersonProvenance(0)[j] = lifted;
    for (const int j : {0, 15, 16, 11}) {
      if (j == 11 && triangulated == 3) continue;
      few.PersonProvenance(0)[j] = static_cast<uint8_t>(JointProvenance::kTriangulated);
    }
    EXPECT_EQ(steps::Postprocess(PostprocessOptions{}, input, &few, &stats), triangulated == 4 ? 1 : 0)
        << triangulated << " triangulated joints";
  }
}

TEST(Postprocess, DropsPersonsOutsideTheRoomPlusItsOwnMargin) {
  // The room reaches x = 5; the person's centre is at x = 5.3.
  const Room room{.size_m = Eigen::Vector3d(10, 10, 0)};
  const std::vector<int> no_neighbour(17, -1);
  Poses3D persons;
  persons.Clear(17);
  persons.AddPerson() = test::StandingPerson(5.3, 0);
  const steps::PostprocessInput input{.neighbour = no_neighbour, .limbs = {}, .room = room};
  PostprocessOptions options;
  FrameStats stats;
  EXPECT_EQ(steps::Postprocess(options, input, &persons, &stats), 1) << "inside with the default 0.5 m";
  options.room_margin_m = 0.2;
  EXPECT_EQ(steps::Postprocess(options, input, &persons, &stats), 0);
}

}  // namespace
}  // namespace rpt

#include "core/fast_math.h"

namespace rpt {
namespace {

TEST(FastExpNeg, MatchesExpWithinTenBillionths) {
  double worst = 0;
  for (double x = 0; x < 60; x += 1e-3) worst = std::max(worst, std::abs(FastExpNeg(x) - std::exp(-x)) / std::exp(-x));
  EXPECT_LT(worst, 1e-8);
  EXPECT_EQ(FastExpNeg(0.0), 1.0);
  EXPECT_EQ(FastExpNeg(1e6), 0.0);
  EXPECT_EQ(FastExpNeg(std::nan("")), 0.0);
}

}  // namespace
}  // namespace rpt
