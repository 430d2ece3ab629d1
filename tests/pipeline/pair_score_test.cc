// SPDX-License-Identifier: MIT
// Steps 6-8 on simulated detections with known identities: which pose pairs pass the pair
// filter. Each proposal's two 2D poses carry the GT person they came from (false positives are
// left out), so every pair is either true (same person) or cross-person.
#include <gtest/gtest.h>

#include <vector>

#include "core/joints.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/score.h"
#include "core/pipeline/triangulate_core.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/view_geometry.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt {
namespace {

using synthetic::DetectorOptions;

struct PairTally {
  int true_pairs = 0, true_kept = 0, cross_pairs = 0, cross_kept = 0;
  double TrueKept() const { return static_cast<double>(true_kept) / true_pairs; }
  double CrossKept() const { return static_cast<double>(cross_kept) / cross_pairs; }
};

// 5 cameras, 4 people, 100 frames; pairs with pair score >= `min_match_score` are kept.
PairTally TallyPairs(const DetectorOptions& detector_options, const ScoreOptions& score, double min_match_score) {
  synthetic::SceneOptions scene_options;
  scene_options.rig.num_cameras = 5;
  scene_options.num_people = 4;
  scene_options.num_frames = 100;
  const synthetic::Scene scene = synthetic::GenerateScene(scene_options);
  const synthetic::DetectorSimulator detector(detector_options, scene.joint_names, 1);

  std::vector<ViewGeometry> geometry;
  for (const Camera& c : scene.cameras) geometry.push_back(MakeViewGeometry(c));
  const JointNames output = AddDerivedJoints(scene.joint_names);
  std::vector<DerivedJointRule> derived;
  for (int j = static_cast<int>(scene.joint_names.size()); j < static_cast<int>(output.size()); ++j) {
    DerivedJointRule rule{j, {}};
    for (const auto& alternative : DerivedJointSources(output[j])) {
      std::vector<int> sources;
      for (const auto& name : alternative) sources.push_back(FindJoint(scene.joint_names, name));
      rule.alternatives.push_back(sources);
    }
    derived.push_back(rule);
  }
  std::vector<int> core;
  for (const auto& name : DefaultCoreJoints()) core.push_back(FindJoint(output, name));

  NoiseScale noise(score.noise_prior_m);
  std::vector<Poses2D> views;
  std::vector<std::vector<synthetic::DetectionSource>> sources;
  PreparedViews prepared;
  std::vector<PosePair> pairs;
  Proposals proposals;
  ScoreScratch scratch;
  ScoreKernel kernel;
  FrameStats stats;
  const std::vector<ResolvedLimb> no_limbs;
  PairTally tally;
  for (int f = 0; f < scene_options.num_frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views, &sources);
    steps::Undistort(UndistortOptions{},
                     {.views = views,
                      .cameras = scene.cameras,
                      .geometry = geometry,
                      .derived = derived,
                      .core_joints = core,
                      .num_output_joints = static_cast<int>(output.size())},
                     &prepared);
    steps::MakePairs(prepared, PairListing::kAll, &pairs);
    steps::TriangulateCore(TriangulateOptions{},
                           {.views = prepared, .geometry = geometry, .pairs = pairs, .joints = core}, &proposals);
    steps::Score(score, {.views = prepared, .geometry = geometry, .core_joints = core, .core_limbs = no_limbs}, &noise,
                 &scratch, &proposals, &kernel, &stats);
    for (int k = 0; k < proposals.size(); ++k) {
      const PosePair& pair = proposals.pairs[k];
      const int a = sources[prepared.view_of[pair.a]][prepared.person_of[pair.a]].gt_person;
      const int b = sources[prepared.view_of[pair.b]][prepared.person_of[pair.b]].gt_person;
      if (a < 0 || b < 0) continue;  // a false positive
      const bool kept = proposals.pair_score[k] >= min_match_score;
      if (a == b) {
        ++tally.true_pairs;
        tally.true_kept += kept ? 1 : 0;
      } else {
        ++tally.cross_pairs;
        tally.cross_kept += kept ? 1 : 0;
      }
    }
  }
  return tally;
}

ScoreOptions FirstReleaseScore() {
  ScoreOptions options;
  options.scale = ScoreScale::kFixed;
  options.trim_fraction = 0;
  return options;
}

// The issue this design answers: with real-detector noise the fixed kernels of the first release
// let too few true pairs through the 0.9 threshold. The adaptive kernels (default options and
// threshold 0.7) keep at least 95 % of the true pairs on the realistic profile and on the
// clean one. Few cross-person pairs pass (grouping with exclusive poses and the verification
// step remove those). Observed: clean 98.0 % true / 0.2 % cross, realistic 95.5 % / 2.6 %.
TEST(PairScore, AdaptiveKernelsKeepTruePairsOnEveryDetectorProfile) {
  const double threshold = FilterOptions{}.min_match_score;
  struct Case {
    const char* profile;
    double max_cross_kept;
  };
  for (const Case& c : {Case{"clean", 0.005}, Case{"realistic", 0.035}}) {
    SCOPED_TRACE(c.profile);
    const PairTally t = TallyPairs(synthetic::DetectorProfile(c.profile), ScoreOptions{}, threshold);
    EXPECT_GT(t.true_pairs, 2000);
    EXPECT_GT(t.cross_pairs, 5000);
    EXPECT_GE(t.TrueKept(), 0.95) << t.true_kept << " of " << t.true_pairs;
    EXPECT_LE(t.CrossKept(), c.max_cross_kept) << t.cross_kept << " of " << t.cross_pairs;
  }
}

// Observed: first release keeps 97.5 % of the true pairs on the clean detector, 22.7 % on the
// realistic one.
TEST(PairScore, FirstReleaseKernelsLoseTruePairsOnRealisticNoise) {
  const PairTally clean = TallyPairs(DetectorOptions::Clean(), FirstReleaseScore(), 0.9);
  const PairTally realistic = TallyPairs(DetectorOptions::Realistic(), FirstReleaseScore(), 0.9);
  const PairTally adaptive = TallyPairs(DetectorOptions::Realistic(), ScoreOptions{}, FilterOptions{}.min_match_score);
  EXPECT_GE(clean.TrueKept(), 0.9) << "tuned on the clean detector";
  EXPECT_LT(realistic.TrueKept(), 0.35) << realistic.true_kept << " of " << realistic.true_pairs;
  EXPECT_GT(adaptive.TrueKept(), realistic.TrueKept() + 0.5);
}

}  // namespace
}  // namespace rpt
