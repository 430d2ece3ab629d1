// SPDX-License-Identifier: MIT
// The score step (steps 6-7) on a scene small enough to compute by hand: what the statistical
// tests (pair_score_test.cc, synthetic suites) cannot see. With midpoint triangulation the two
// views' errors in metres come out nearly equal, so a residual that used one view's error twice
// passed every test; and a noise vote from one-sided best pairs moved the estimate too little for
// any test to notice. Here each proposal's 3D point is set by hand (the true point), so each
// view's reprojection error is exactly the pixel displacement put into its observations, and
// every expected number below follows from the comments. Both the scalar code and every SIMD
// instruction set of this CPU are run.
//
// The scene: camera A at (-4, 0, 1) looking along +x, camera B at (0, -4, 1) looking along +y
// (test::LookAtCamera: focal 800 px). A stick person stands on the vertical line x = y = 0
// (every joint at x = y = 0, at the heights of test::StandingPerson), so every joint is at depth
// 4 m in both views. A pose whose observations are displaced by d px then has, per joint,
// reprojection error d px, i.e. d * 4 / 800 = d / 200 m at the joint, and a pair of poses with
// displacements d_a, d_b has residual r = 0.5 * (d_a + d_b) / 200 = (d_a + d_b) / 400 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/noise_scale.h"
#include "core/pipeline/score.h"
#include "core/pipeline/simd_kernels.h"
#include "core/pipeline/triangulate_core.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/view_geometry.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// Runs `body` with the scalar code, then with the SIMD kernels on every instruction set of this
// CPU; restores the process's setting (RPT_SIMD) afterwards. Checks both kinds ran.
void ForScalarAndEveryKernel(const std::function<void(const std::string&)>& body) {
  const bool was_enabled = simd::Enabled();
  simd::SetEnabled(false);
  body("scalar code");
  simd::SetEnabled(true);
  int kernel_paths = 0;
  simd::ForEachPathForTest([&] {
    body("SIMD " + simd::ActivePath());
    ++kernel_paths;
  });
  simd::SetEnabled(was_enabled);
  EXPECT_GE(kernel_paths, 1);
}

// The two-camera scene of the file comment. displaced_a[p] / displaced_b[p]: the pixel
// displacement (du, dv) of every joint of pose p in view A / B.
struct HandScene {
  HandScene(const std::vector<Eigen::Vector2d>& displaced_a, const std::vector<Eigen::Vector2d>& displaced_b) {
    cameras = {test::LookAtCamera({-4, 0, 1}, {0, 0, 1}, "A"), test::LookAtCamera({0, -4, 1}, {0, 0, 1}, "B")};
    person = test::StandingPerson(0, 0);
    person.row(0).setZero();
    person.row(1).setZero();
    const std::vector<Eigen::Vector2d>* displaced[2] = {&displaced_a, &displaced_b};
    for (int v = 0; v < 2; ++v) {
      views.push_back(
          test::ProjectPersons({cameras[v]}, std::vector<Eigen::Matrix4Xd>(displaced[v]->size(), person))[0]);
      for (size_t p = 0; p < displaced[v]->size(); ++p) {
        views[v].Person(static_cast<int>(p)).topRows<2>().colwise() += (*displaced[v])[p];
      }
    }
    test::UndistortCocoViews(cameras, views, &geometry, &core, &prepared);
    steps::MakePairs(prepared, PairListing::kAll, &pairs);
  }

  // Triangulates every pair, then puts each proposal's joints at the true points with ray gap
  // `gap_m` (what the score step reads of a proposal), and scores them.
  Proposals Score(const ScoreOptions& options, double gap_m, NoiseScale* noise, ScoreScratch* scratch,
                  FrameStats* stats) const {
    Proposals proposals;
    steps::TriangulateCore(TriangulateOptions{},
                           {.views = prepared, .geometry = geometry, .pairs = pairs, .joints = core}, &proposals);
    for (int k = 0; k < proposals.size(); ++k) {
      for (int i = 0; i < proposals.num_joints; ++i) {
        const size_t at = static_cast<size_t>(k) * proposals.num_joints + i;
        if (proposals.score[at] <= 0) continue;
        proposals.xyz[at] = person.col(core[i]).head<3>();
        proposals.gap[at] = gap_m;
      }
    }
    ScoreKernel kernel;
    steps::Score(options, {.views = prepared, .geometry = geometry, .core_joints = core, .core_limbs = {}}, noise,
                 scratch, &proposals, &kernel, stats);
    return proposals;
  }

  // The pose of view v, person p.
  int Pose(int v, int p) const {
    for (int g = 0; g < prepared.num_poses(); ++g) {
      if (prepared.view_of[g] == v && prepared.person_of[g] == p) return g;
    }
    return -1;
  }

  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;
  Eigen::Matrix4Xd person;
  std::vector<int> core;
  std::vector<Poses2D> views;
  PreparedViews prepared;
  std::vector<PosePair> pairs;
};

// The noise histogram (noise_scale.cc) by hand: 64 bins over [1 mm, 300 mm) on a log scale,
// bin width w = ln(300) / 64; the estimate is 1 mm x exp((b + fraction) w) for the median's bin b.
double HistogramValue(double bin_position) { return 1e-3 * std::exp(bin_position * std::log(300.0) / 64); }

// Two views whose errors differ: view A is off by (3, 4) px = 5 px, view B by (5, -12) px = 13 px.
//   Per joint: e_A = 5 px -> 5 * 4 / 800 = 0.025 m;  e_B = 13 px -> 13 * 4 / 800 = 0.065 m;
//   r = 0.5 * (0.025 + 0.065) = 0.045 m (one view's error twice: 0.025 or 0.065 m).
// The pair (mutually best: the only one) votes 0.045 m. The prior 0.02 m sits in bin
// floor(ln(20) / w) = 33 with 10 votes, 9.9 after the frame's decay; the vote lands in bin
// floor(ln(45) / w) = 42. Of 10.9 counts the median (5.45) is in bin 33 at fraction
// 5.45 / 9.9 = 0.550505..., so the noise estimate is N = HistogramValue(33 + 5.45 / 9.9) = 19.887 mm
// and the kernel scale S = 5 N (scale_factor).
//   s_rep = exp(-(r / S)^2);  with the ray gap set to g = 0.03 m, s_tri = exp(-(g / 2S)^2);
//   every joint has confidence 1, so joint score = pair score = s_rep * s_tri (all 12 equal: the
//   trimmed quarter changes nothing).
TEST(ScoreHandValues, PairResidualAveragesTheErrorsOfBothViews) {
  const HandScene scene({{3, 4}}, {{5, -12}});
  ASSERT_EQ(scene.pairs.size(), 1u);
  const double r = 0.5 * (5 * 4 / 800.0 + 13 * 4 / 800.0);
  ASSERT_DOUBLE_EQ(r, 0.045);
  const double noise_m = HistogramValue(33 + 5.45 / 9.9);
  const double S = 5 * noise_m, g = 0.03;
  const double s_rep = std::exp(-(r / S) * (r / S)), s_tri = std::exp(-(g / (2 * S)) * (g / (2 * S)));
  EXPECT_NEAR(noise_m, 0.019887, 1e-6);
  EXPECT_NEAR(s_rep, 0.81481, 1e-5);  // the numbers, for the reader
  EXPECT_NEAR(s_tri, 0.97750, 1e-5);
  ForScalarAndEveryKernel([&](const std::string& path) {
    SCOPED_TRACE(path);
    NoiseScale noise(0.02);
    ScoreScratch scratch;
    FrameStats stats;
    const Proposals p = scene.Score(ScoreOptions{}, g, &noise, &scratch, &stats);
    ASSERT_EQ(p.size(), 1);
    for (int i = 0; i < p.num_joints; ++i) {
      EXPECT_NEAR(scratch.residual[i], r, 1e-12) << "joint slot " << i;
      EXPECT_NEAR(p.score[i], s_rep * s_tri, 1e-9) << "joint slot " << i;
    }
    EXPECT_NEAR(scratch.pair_residual[0], r, 1e-12);
    EXPECT_EQ(noise.votes(), 1);
    EXPECT_NEAR(stats.noise_m, noise_m, 1e-12);
    EXPECT_NEAR(p.pair_score[0], s_rep * s_tri, 1e-9);

    // Reprojection only: the pair score is s_rep alone.
    ScoreOptions rep_only;
    rep_only.mode = ScoreMode::kReprojectionOnly;
    NoiseScale fresh(0.02);
    EXPECT_NEAR(scene.Score(rep_only, g, &fresh, &scratch, &stats).pair_score[0], s_rep, 1e-9);
  });
}

// Only mutually best pairs vote. View A has poses A1 (off by 2 px) and A2 (6 px), view B has B1
// (2 px) and B2 (10 px); r = (d_a + d_b) / 400 m (file comment):
//   (A1, B1) 0.01 m   A1's best in B is B1 and B1's best in A is A1: mutually best, votes;
//   (A2, B1) 0.02 m   A2's best is B1, but B1's best is A1: one-sided (from A), must not vote;
//   (A1, B2) 0.03 m   B2's best is A1, but A1's best is B1: one-sided (from B), must not vote;
//   (A2, B2) 0.04 m   best of neither.
// One vote, 0.01 m, in bin floor(ln(10) / w) = 25, below the prior's bin 33 (9.9 counts after the
// decay). Of 10.9 counts the median 5.45 lies in bin 33 with 1 below it: fraction
// (5.45 - 1) / 9.9, so the estimate is HistogramValue(33 + 4.45 / 9.9) = 19.709 mm.
// Had the one-sided pairs voted: 0.02 m falls in bin 33, 0.03 m in bin 38, and the fraction would
// be (6.45 - 1) / 10.9 (both), (5.95 - 1) / 10.9 (A's side) or (5.95 - 1) / 9.9 (B's side).
TEST(ScoreHandValues, OnlyMutuallyBestPairsVoteForTheNoise) {
  const HandScene scene({{0, 2}, {6, 0}}, {{2, 0}, {6, 8}});
  ASSERT_EQ(scene.pairs.size(), 4u);
  const int a1 = scene.Pose(0, 0), a2 = scene.Pose(0, 1), b1 = scene.Pose(1, 0), b2 = scene.Pose(1, 1);
  ASSERT_GE(std::min({a1, a2, b1, b2}), 0);
  auto expected_residual = [&](const PosePair& pair) {
    const double d[4] = {2, 6, 2, 10};  // displacement (px) of A1, A2, B1, B2
    auto of = [&](int pose) { return pose == a1 ? d[0] : pose == a2 ? d[1] : pose == b1 ? d[2] : d[3]; };
    return (of(pair.a) + of(pair.b)) / 400.0;
  };
  const double noise_m = HistogramValue(33 + 4.45 / 9.9);
  EXPECT_NEAR(noise_m, 0.019709, 1e-6);
  // The one-sided votes would move it: both sides, A's side only, B's side only.
  EXPECT_GT(std::abs(HistogramValue(33 + 5.45 / 10.9) - noise_m), 5e-5);
  EXPECT_GT(std::abs(HistogramValue(33 + 4.95 / 10.9) - noise_m), 5e-6);
  EXPECT_GT(std::abs(HistogramValue(33 + 4.95 / 9.9) - noise_m), 5e-5);
  ForScalarAndEveryKernel([&](const std::string& path) {
    SCOPED_TRACE(path);
    NoiseScale noise(0.02);
    ScoreScratch scratch;
    FrameStats stats;
    const Proposals p = scene.Score(ScoreOptions{}, 0.0, &noise, &scratch, &stats);
    ASSERT_EQ(p.size(), 4);
    double residuals_seen = 0;
    for (int k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(scratch.pair_residual[k], expected_residual(p.pairs[k]), 1e-12) << "proposal " << k;
      residuals_seen += scratch.pair_residual[k];
    }
    EXPECT_NEAR(residuals_seen, 0.01 + 0.02 + 0.03 + 0.04, 1e-12) << "each of the four pairs once";
    EXPECT_EQ(noise.votes(), 1) << "only (A1, B1) is mutually best";
    EXPECT_NEAR(stats.noise_m, noise_m, 1e-12);
  });
}

}  // namespace
}  // namespace rpt
