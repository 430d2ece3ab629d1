// SPDX-License-Identifier: MIT
// Each of the paper's ablation options changes what it should (and only that).
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt {
namespace {

struct RunResult {
  std::vector<Poses3D> persons;
  std::vector<FrameStats> stats;
};

class AblationTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    synthetic::SceneOptions options;
    options.rig.num_cameras = 6;
    options.num_people = 5;
    options.num_frames = 60;
    options.seed = 7;
    scene_ = new synthetic::Scene(synthetic::GenerateScene(options));
    const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene_->joint_names, 7);
    frames_ = new std::vector<std::vector<Poses2D>>(options.num_frames);
    for (int f = 0; f < options.num_frames; ++f) {
      detector.Detect(scene_->cameras, scene_->gt[f], scene_->joint_names, f, &(*frames_)[f]);
    }
  }
  static void TearDownTestSuite() {
    delete scene_;
    delete frames_;
  }

  static RunResult Run(const std::function<void(TriangulatorOptions&)>& change) {
    TriangulatorOptions options;
    options.room_check.center_m = scene_->room_center_m;
    options.room_check.size_m = scene_->room_size_m;
    change(options);
    Triangulator tri(scene_->cameras, scene_->joint_names, options);
    RunResult result;
    for (size_t f = 0; f < frames_->size(); ++f) {
      Poses3D persons;
      FrameStats stats;
      tri.Process((*frames_)[f], f / scene_->fps, &persons, &stats);
      result.persons.push_back(persons);
      result.stats.push_back(stats);
    }
    return result;
  }
  static int Sum(const RunResult& r, Step step) {
    int total = 0;
    for (const auto& s : r.stats) total += s.count[static_cast<int>(step)];
    return total;
  }
  static bool SamePersons(const RunResult& a, const RunResult& b) {
    for (size_t f = 0; f < a.persons.size(); ++f) {
      if (a.persons[f].data != b.persons[f].data || a.persons[f].track_ids != b.persons[f].track_ids) return false;
    }
    return true;
  }

  static synthetic::Scene* scene_;
  static std::vector<std::vector<Poses2D>>* frames_;
};
synthetic::Scene* AblationTest::scene_ = nullptr;
std::vector<std::vector<Poses2D>>* AblationTest::frames_ = nullptr;

TEST_F(AblationTest, DefaultRunIsDeterministic) {
  EXPECT_TRUE(SamePersons(Run([](auto&) {}), Run([](auto&) {})));
}

TEST_F(AblationTest, NoPrefilterTriangulatesEveryPair) {
  const RunResult base = Run([](auto&) {});
  const RunResult off = Run([](auto& o) { o.prefilter.enabled = false; });
  EXPECT_EQ(Sum(off, Step::kPrefilter), Sum(off, Step::kMakePairs));
  EXPECT_LT(Sum(base, Step::kPrefilter), Sum(base, Step::kMakePairs) / 2) << "the pre-filter removes most pairs";
  EXPECT_GT(Sum(off, Step::kTriangulateCore), Sum(base, Step::kTriangulateCore));
}

TEST_F(AblationTest, ScoreWithoutConfidenceChangesScoresAndPositions) {
  const RunResult base = Run([](auto&) {});
  const RunResult off = Run([](auto& o) { o.score.use_confidence = false; });
  EXPECT_FALSE(SamePersons(base, off));
}

TEST_F(AblationTest, ScoreModesChangeScores) {
  const RunResult base = Run([](auto&) {});
  const RunResult tri = Run([](auto& o) { o.score.mode = ScoreMode::kTriangulationOnly; });
  const RunResult rep = Run([](auto& o) { o.score.mode = ScoreMode::kReprojectionOnly; });
  EXPECT_FALSE(SamePersons(base, tri));
  EXPECT_FALSE(SamePersons(base, rep));
  EXPECT_FALSE(SamePersons(tri, rep));
}

TEST_F(AblationTest, KeepingMergeOutliersChangesPositionsOnly) {
  const RunResult base = Run([](auto&) {});
  const RunResult topk = Run([](auto& o) { o.merge.top_k = 0; });
  const RunResult both = Run([](auto& o) {
    o.merge.top_k = 0;
    o.merge.max_distance_m = 0;
  });
  EXPECT_FALSE(SamePersons(base, topk));
  EXPECT_FALSE(SamePersons(topk, both));
  EXPECT_EQ(Sum(base, Step::kGroup), Sum(topk, Step::kGroup)) << "merge options do not change grouping";
}

TEST_F(AblationTest, HigherMinMatchScoreKeepsFewerProposals) {
  const RunResult base = Run([](auto&) {});
  const RunResult strict = Run([](auto& o) { o.filter.min_match_score = 0.97; });
  const RunResult loose = Run([](auto& o) { o.filter.min_match_score = 0.6; });
  EXPECT_LT(Sum(strict, Step::kFilter), Sum(base, Step::kFilter));
  EXPECT_GE(Sum(loose, Step::kFilter), Sum(base, Step::kFilter));
}

// Post-processing fills every missing joint whose chain of neighbours (an elbow's is its
// shoulder, a shoulder's the other shoulder, ...) reaches a joint the person has; a joint whose
// whole chain is missing (both shoulders and what hangs on them) has nothing to be placed from.
TEST_F(AblationTest, NoPostprocessingKeepsMissingJointsAndInvalidPersons) {
  const RunResult base = Run([](auto&) {});
  const RunResult off = Run([](auto& o) { o.postprocess.enabled = false; });
  const JointNames output = Triangulator(scene_->cameras, scene_->joint_names, TriangulatorOptions{}).output_joints();
  const std::vector<int> neighbour = NeighbourIndices(output);
  int filled = 0, missing_off = 0, fillable_missing = 0;
  for (const auto& s : base.stats) filled += s.filled_joints;
  for (const auto& s : off.stats) EXPECT_EQ(s.filled_joints + s.replaced_joints, 0);
  // Missing joints with a joint present down their chain of neighbours.
  const auto fillable = [&](const Poses3D& persons) {
    int count = 0;
    for (int p = 0; p < persons.num_persons(); ++p) {
      const auto person = persons.Person(p);
      for (int j = 0; j < persons.num_joints; ++j) {
        if (person(3, j) > 0) continue;
        bool present = false;
        for (int k = neighbour[j], steps = 0; k >= 0 && steps < persons.num_joints && !present; ++steps) {
          present = person(3, k) > 0;
          k = neighbour[k];
        }
        count += present ? 1 : 0;
      }
    }
    return count;
  };
  for (const auto& frame : off.persons) missing_off += fillable(frame);
  for (const auto& frame : base.persons) fillable_missing += fillable(frame);
  EXPECT_GT(filled, 0);
  EXPECT_GT(missing_off, 0);
  EXPECT_EQ(fillable_missing, 0) << "post-processing fills every joint it has a neighbour chain for";
  EXPECT_GE(Sum(off, Step::kPostprocess), Sum(base, Step::kPostprocess));
}

TEST_F(AblationTest, MinGroupSizeDropsSmallGroups) {
  const RunResult base = Run([](auto&) {});
  const RunResult strict = Run([](auto& o) { o.group.min_group_size = 4; });
  int small = 0;
  for (const auto& s : strict.stats) small += s.small_groups;
  EXPECT_GT(small, 0);
  EXPECT_LT(Sum(strict, Step::kGroup), Sum(base, Step::kGroup));
}

TEST_F(AblationTest, NoTrackingLeavesIdsUnsetAndNoCoasting) {
  const RunResult base = Run([](auto&) {});
  const RunResult off = Run([](auto& o) { o.track.enabled = false; });
  bool any_id = false;
  for (const auto& p : base.persons) {
    for (int id : p.track_ids) any_id |= id >= 0;
  }
  EXPECT_TRUE(any_id);
  for (const auto& p : off.persons) {
    for (int id : p.track_ids) EXPECT_EQ(id, -1);
  }
  for (const auto& s : off.stats) EXPECT_EQ(s.coasting_tracks + s.new_tracks, 0);
}

TEST_F(AblationTest, DltTriangulationIsCloseToMidpoint) {
  const RunResult base = Run([](auto&) {});
  const RunResult dlt = Run([](auto& o) { o.triangulate.method = TriangulationMethod::kDlt; });
  EXPECT_FALSE(SamePersons(base, dlt));
  double max_diff = 0;
  int compared = 0;
  for (size_t f = 0; f < base.persons.size(); ++f) {
    if (base.persons[f].num_persons() != dlt.persons[f].num_persons()) continue;
    for (int p = 0; p < base.persons[f].num_persons(); ++p) {
      double best = 1e9;
      for (int q = 0; q < dlt.persons[f].num_persons(); ++q) {
        best = std::min(best, (base.persons[f].Person(p).topRows(3) - dlt.persons[f].Person(q).topRows(3)).rowwise().norm().maxCoeff());
      }
      max_diff = std::max(max_diff, best);
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
  EXPECT_LT(max_diff, 0.5);
}

// Mean distance between two output persons over the joints both have.
double MeanJointDistance(const Poses3D& persons, int p, int q) {
  const auto a = persons.Person(p), b = persons.Person(q);
  double sum = 0;
  int common = 0;
  for (int j = 0; j < persons.num_joints; ++j) {
    if (a(3, j) <= 0 || b(3, j) <= 0) continue;
    sum += (a.col(j).head<3>() - b.col(j).head<3>()).norm();
    ++common;
  }
  return common > 0 ? sum / common : std::numeric_limits<double>::infinity();
}

// With 31 cameras the pair budget keeps one pair per pose first; some of a person's poses then pair
// only among themselves and make a copy of the person from views of their own. Verification drops
// it (verify.duplicate_distance_m); the scene's people never come that close (hips >= 0.8 m apart).
TEST(DuplicatePersons, VerificationDropsTheCopiesOfAPersonMadeFromViewsOfTheirOwn) {
  synthetic::SceneOptions scene_options;
  scene_options.rig.num_cameras = 31;
  scene_options.num_people = 8;
  scene_options.num_frames = 60;
  const synthetic::Scene scene = synthetic::GenerateScene(scene_options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 1);
  std::vector<std::vector<Poses2D>> frames(scene_options.num_frames);
  for (int f = 0; f < scene_options.num_frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &frames[f]);
  }
  // Frames with two persons closer than 0.25 m, and the persons verification dropped as copies.
  const auto run = [&](double duplicate_distance_m, int* dropped) {
    TriangulatorOptions options;
    options.room_check.center_m = scene.room_center_m;
    options.room_check.size_m = scene.room_size_m;
    options.verify.duplicate_distance_m = duplicate_distance_m;
    options.verify.part_distance_m = 0;  // parts off: a copy with fewer joints would be dropped as a part too
    Triangulator tri(scene.cameras, scene.joint_names, options);
    int close_frames = 0;
    *dropped = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
      Poses3D persons;
      FrameStats stats;
      tri.Process(frames[f], f / scene.fps, &persons, &stats);
      *dropped += stats.duplicate_persons;
      bool close = false;
      for (int p = 0; p < persons.num_persons(); ++p) {
        for (int q = p + 1; q < persons.num_persons(); ++q) close |= MeanJointDistance(persons, p, q) < 0.25;
      }
      close_frames += close ? 1 : 0;
    }
    return close_frames;
  };
  int dropped_off = 0, dropped_on = 0;
  EXPECT_GT(run(0.0, &dropped_off), 0) << "the scene makes copies (else this test shows nothing)";
  EXPECT_EQ(dropped_off, 0);
  EXPECT_EQ(run(0.25, &dropped_on), 0);
  EXPECT_GT(dropped_on, 0);
}

}  // namespace
}  // namespace rpt
