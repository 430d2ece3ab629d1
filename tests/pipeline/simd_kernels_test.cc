// SPDX-License-Identifier: MIT
// The SIMD kernels (core/pipeline/simd_kernels.h) against the scalar code they replace, on random
// pose pairs, for every instruction set this CPU runs: the results must be bit-identical (the
// kernels use the scalar operations in the scalar order, without fused multiply-add), and the
// whole triangulator with them must give the scalar steps' persons bit for bit.
#include "core/pipeline/simd_kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/fast_math.h"
#include "core/pipeline/median.h"
#include "core/pipeline/merge.h"
#include "core/pipeline/proposal_scoring.h"
#include "core/pipeline/triangulator.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/view_geometry.h"
#include "core/triangulation.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// Bitwise equality (NaN == NaN, -0 != +0): the kernels promise the scalar bits. A build for the
// host (-DRPT_MARCH_NATIVE=ON) lets the compiler fuse the scalar code's multiply-adds, which the
// kernels never do: there the two agree to rounding only.
#if defined(__FMA__)
constexpr bool kScalarCodeFused = true;
#else
constexpr bool kScalarCodeFused = false;
#endif
bool SameBits(double a, double b) {
  if (kScalarCodeFused && std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b))) return true;
  return std::memcmp(&a, &b, sizeof(a)) == 0;
}

ViewGeometry RandomView(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-3.1, 3.1), pos(-4, 4), focal(400, 1600);
  ViewGeometry g;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.3 * angle(rng), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  g.center = Eigen::Vector3d(pos(rng), pos(rng), 1.5 + 0.5 * pos(rng));
  g.fx = focal(rng);
  g.fy = g.fx * 1.01;
  g.cx = 640;
  g.cy = 360;
  g.focal = 0.5 * (g.fx + g.fy);
  Eigen::Matrix3d K;
  K << g.fx, 0, g.cx, 0, g.fy, g.cy, 0, 0, 1;
  g.Rt.leftCols<3>() = R;
  g.Rt.col(3) = -R * g.center;
  g.P = K * g.Rt;
  g.R_t = R.transpose();
  return g;
}

// A random keypoint of `view`: a noisy ray towards a point near the room's centre (sometimes
// missing, sometimes pointing away, sometimes a non-finite score).
Keypoint RandomKeypoint(std::mt19937& rng, const ViewGeometry& g) {
  std::uniform_real_distribution<double> pos(-2, 2), unit(0, 1), noise(-0.05, 0.05);
  Keypoint kp;
  const double kind = unit(rng);
  kp.score = kind < 0.15 ? 0.0 : (kind < 0.17 ? -0.5 : unit(rng));
  const Eigen::Vector3d X(pos(rng), pos(rng), 1 + 0.5 * pos(rng));
  kp.ray = X - g.center + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  if (unit(rng) < 0.05) kp.ray = -kp.ray;  // behind the camera
  if (unit(rng) < 0.02) kp.ray = Eigen::Vector3d(1e-300, 0, 0);  // degenerate
  const Eigen::Vector3d h = g.P.leftCols<3>() * X + g.P.col(3);
  kp.u = h.x() / h.z() + 20 * noise(rng);
  kp.v = h.y() / h.z() + 20 * noise(rng);
  kp.sqrt_score = std::sqrt(std::max(kp.score, 0.0));
  return kp;
}

struct PairCase {
  ViewGeometry ga, gb;
  std::vector<Keypoint> ka, kb;
  KeypointColumns columns;  // pose 0 = a, pose 1 = b
};

PairCase RandomPair(std::mt19937& rng, int n) {
  PairCase c;
  c.ga = RandomView(rng);
  c.gb = RandomView(rng);
  for (int i = 0; i < n; ++i) {
    c.ka.push_back(RandomKeypoint(rng, c.ga));
    c.kb.push_back(RandomKeypoint(rng, c.gb));
  }
  std::vector<Keypoint> both = c.ka;
  both.insert(both.end(), c.kb.begin(), c.kb.end());
  c.columns.Assign(both.data(), 2, n, nullptr, n);
  return c;
}

// Joint counts around every vector width (1, 2, 4, 8 doubles) and the whole-body skeleton.
const int kJointCounts[] = {1, 3, 4, 7, 8, 9, 17, 133};

std::set<std::string> PathsRun() {
  std::set<std::string> paths;
  simd::ForEachPathForTest([&] { paths.insert(simd::ActivePath()); });
  return paths;
}

TEST(SimdKernels, RunsEveryInstructionSetOfThisCpu) {
  const std::set<std::string> paths = PathsRun();
  EXPECT_TRUE(paths.count("scalar")) << "the portable fallback is always compiled and runnable";
  for (const std::string& path : paths) EXPECT_TRUE(path == "scalar" || path == "SSE4" || path == "AVX2" || path == "AVX-512") << path;
  // After the loop the automatic choice is back: the best of those.
  const std::string active = simd::ActivePath();
  EXPECT_TRUE(paths.count(active)) << active;
  if (paths.count("AVX-512")) {
    EXPECT_EQ(active, "AVX-512");
  } else if (paths.count("AVX2")) {
    EXPECT_EQ(active, "AVX2");
  }
  std::string all;
  for (const std::string& p : paths) all += p + " ";
  RecordProperty("paths", all);
}

TEST(SimdKernels, TriangulatePairEqualsTriangulateMidpointBitForBit) {
  int paths = 0;
  simd::ForEachPathForTest([&] {
    ++paths;
    std::mt19937 rng(7);
    int triangulated = 0, failed = 0;
    for (int round = 0; round < 40; ++round) {
      for (const int n : kJointCounts) {
        const PairCase c = RandomPair(rng, n);
        std::vector<Eigen::Vector3d> xyz(n, Eigen::Vector3d::Constant(7));
        std::vector<double> gap(n, 7), score(n, 7);
        simd::TriangulatePair(c.ga.center.data(), simd::ColumnsOf(c.columns, 0), c.gb.center.data(),
                              simd::ColumnsOf(c.columns, 1), n, xyz.data()->data(), gap.data(), score.data());
        for (int i = 0; i < n; ++i) {
          Eigen::Vector3d point;
          double g = -1;
          const bool ok = c.ka[i].score > 0 && c.kb[i].score > 0 &&
                          TriangulateMidpoint(c.ga.center, c.ka[i].ray, c.gb.center, c.kb[i].ray, &point, &g);
          ASSERT_EQ(score[i], ok ? 1.0 : 0.0) << simd::ActivePath() << " n=" << n << " joint " << i;
          if (!ok) {
            EXPECT_EQ(gap[i], -1.0);
            ++failed;
            continue;
          }
          ++triangulated;
          ASSERT_TRUE(SameBits(gap[i], g)) << simd::ActivePath() << " " << gap[i] << " vs " << g;
          for (int a = 0; a < 3; ++a) ASSERT_TRUE(SameBits(xyz[i][a], point[a])) << simd::ActivePath();
        }
      }
    }
    EXPECT_GT(triangulated, 1000);
    EXPECT_GT(failed, 300) << "missing joints, rays behind cameras and degenerate rays are exercised";
  });
  EXPECT_GE(paths, 1);
}

TEST(SimdKernels, ResidualsAndScoresEqualTheScalarKernelsBitForBit) {
  simd::ForEachPathForTest([&] {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    int scored = 0, kept = 0;
    for (int round = 0; round < 30; ++round) {
      for (const int n : kJointCounts) {
        for (const bool adaptive : {true, false}) {
          const PairCase c = RandomPair(rng, n);
          std::vector<Eigen::Vector3d> xyz(n);
          std::vector<double> gap(n), score(n), geometric(n);
          for (int i = 0; i < n; ++i) {
            xyz[i] = Eigen::Vector3d(4 * unit(rng) - 2, 4 * unit(rng) - 2, 2 * unit(rng));
            if (unit(rng) < 0.03) xyz[i] = c.ga.center - c.ga.R_t.col(2);  // behind view a
            gap[i] = unit(rng) < 0.1 ? -1 : 0.3 * unit(rng) * unit(rng);
            score[i] = unit(rng) < 0.15 ? 0.0 : 1.0;
            geometric[i] = unit(rng) < 0.2 ? unit(rng) : -1.0;
          }
          const double scale_a = adaptive ? 1.0 / c.ga.focal : 1.0 / 300, scale_b = adaptive ? 1.0 / c.gb.focal : 1.0 / 250;
          const simd::ResidualViews rv{.Pa = c.ga.P.data(), .Pb = c.gb.P.data(), .scale_a = scale_a, .scale_b = scale_b,
                                       .adaptive = adaptive};
          const double* xyzd = xyz.data()->data();
          // Pass 1 residuals.
          const double skip_gap = 0.12;
          std::vector<double> residual(n, 7);
          simd::PairResiduals(rv, simd::ColumnsOf(c.columns, 0), simd::ColumnsOf(c.columns, 1), n, xyzd, gap.data(),
                              score.data(), geometric.data(), true, skip_gap, residual.data());
          for (int i = 0; i < n; ++i) {
            double expected = -1;
            if (score[i] > 0 && geometric[i] < 0) {
              expected = gap[i] > skip_gap ? 1e6 : JointResidual(c.ga, c.gb, xyz[i], c.ka[i], c.kb[i], scale_a, scale_b, adaptive);
            }
            ASSERT_TRUE(SameBits(residual[i], expected)) << simd::ActivePath() << " " << residual[i] << " vs " << expected;
          }
          // Joint scores, with and without precomputed residuals, for each kernel mode.
          for (const int mode : {0, 1, 2}) {
            const ScoreKernel kernel{.use_reprojection = mode != 2, .use_ray_gap = mode != 1, .adaptive = adaptive,
                                     .inv_residual = adaptive ? 1.0 / 0.03 : 1.0 / 0.05, .inv_ray_gap = 1.0 / 0.06};
            for (const bool precomputed : {false, true}) {
              std::vector<double> s = score, geo = geometric;
              std::vector<double> res(n);
              for (int i = 0; i < n; ++i) res[i] = JointResidual(c.ga, c.gb, xyz[i], c.ka[i], c.kb[i], scale_a, scale_b, adaptive);
              simd::ScoreJoints({.use_reprojection = kernel.use_reprojection, .use_ray_gap = kernel.use_ray_gap,
                                 .inv_residual = kernel.inv_residual, .inv_ray_gap = kernel.inv_ray_gap},
                                rv, simd::ColumnsOf(c.columns, 0), simd::ColumnsOf(c.columns, 1), n, xyzd, gap.data(),
                                precomputed ? res.data() : nullptr, s.data(), geo.data());
              for (int i = 0; i < n; ++i) {
                // The scalar loop of ScoreJointsOfProposal.
                double es = score[i], eg = geometric[i];
                if (es > 0) {
                  if (eg >= 0) {
                    es = eg;
                  } else {
                    double exponent = 0;
                    bool negligible = false;
                    if (kernel.use_ray_gap) {
                      const double r = gap[i] * kernel.inv_ray_gap;
                      exponent = r * r;
                      negligible = exponent > 30.0;
                    }
                    if (!negligible && kernel.use_reprojection) {
                      const double r = res[i] * kernel.inv_residual;
                      exponent += r * r;
                    }
                    es = eg = negligible ? 0.0 : FastExpNeg(exponent);
                    ++scored;
                    kept += es > 0 ? 1 : 0;
                  }
                }
                ASSERT_TRUE(SameBits(s[i], es)) << simd::ActivePath() << " mode " << mode << " " << s[i] << " vs " << es;
                ASSERT_TRUE(SameBits(geo[i], eg)) << simd::ActivePath() << " mode " << mode;
              }
            }
          }
        }
      }
    }
    EXPECT_GT(scored, 10000);
    EXPECT_GT(kept, 1000) << "scores in (0, 1) are exercised, not only zeros";
  });
}

// Rows of 1..3 persons against one pose: each row's sum and count as the scalar loop has them.
TEST(SimdKernels, PixelDistanceSumsEqualThePrefiltersScalarLoopBitForBit) {
  simd::ForEachPathForTest([&] {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> px(0, 1000), unit(0, 1);
    int compared = 0;
    for (int round = 0; round < 200; ++round) {
      for (const int n : kJointCounts) {
        const int persons = 1 + round % 3;
        std::vector<Eigen::Vector2d> uv(static_cast<size_t>(persons) * n);
        for (Eigen::Vector2d& point : uv) {
          point = unit(rng) < 0.15 ? Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN())
                                   : Eigen::Vector2d(px(rng), px(rng));
        }
        std::vector<Keypoint> kps(n);
        for (int i = 0; i < n; ++i) {
          kps[i].u = px(rng);
          kps[i].v = px(rng);
          kps[i].score = unit(rng) < 0.2 ? 0.0 : unit(rng);
        }
        KeypointColumns columns;
        columns.Assign(kps.data(), 1, n, nullptr, n);
        std::vector<double> sums(persons, -1);
        std::vector<int> counts(persons, -1);
        simd::PixelDistanceSums(uv.data()->data(), persons, simd::ColumnsOf(columns, 0), n, sums.data(),
                                counts.data());
        for (int q = 0; q < persons; ++q) {
          double expected = 0;
          int expected_count = 0;
          for (int i = 0; i < n; ++i) {  // steps::Prefilter's loop
            const Eigen::Vector2d& point = uv[static_cast<size_t>(q) * n + i];
            if (kps[i].score <= 0 || std::isnan(point.x())) continue;
            const double du = point.x() - kps[i].u, dv = point.y() - kps[i].v;
            expected += std::sqrt(du * du + dv * dv);
            ++expected_count;
          }
          ASSERT_EQ(counts[q], expected_count) << simd::ActivePath() << " person " << q;
          ASSERT_TRUE(SameBits(sums[q], expected)) << simd::ActivePath() << " " << sums[q] << " vs " << expected;
          ++compared;
        }
      }
    }
    EXPECT_EQ(compared, 8 * (67 * 1 + 67 * 2 + 66 * 3));
  });
}

// Limb pruning's first pass (simd::ImplausibleLimbs) against the scalar test of each limb, on
// random limbs with lengths exactly at their bounds, non-finite points and unscored joints, for
// every chunk size up to 64 and every instruction set.
TEST(SimdKernels, ImplausibleLimbsEqualsTheScalarTestBitForBit) {
  simd::ForEachPathForTest([&] {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> pos(-1, 1), unit(0, 1);
    int compared = 0, implausible = 0, at_bound = 0;
    for (int round = 0; round < 100; ++round) {
      const int n = 133, num_limbs = 1 + round % 64;
      std::vector<Eigen::Vector3d> xyz(n);
      std::vector<double> score(n);
      for (int i = 0; i < n; ++i) {
        xyz[i] = Eigen::Vector3d(pos(rng), pos(rng), pos(rng));
        if (unit(rng) < 0.03) xyz[i].y() = std::numeric_limits<double>::quiet_NaN();
        const double kind = unit(rng);
        score[i] = kind < 0.1 ? 0.0 : (kind < 0.13 ? -0.5 : unit(rng));
      }
      std::vector<ResolvedLimb> limbs;
      std::uniform_int_distribution<int> joint(0, n - 1);
      for (int l = 0; l < num_limbs; ++l) {
        ResolvedLimb limb{joint(rng), joint(rng), 0.3 + 0.5 * unit(rng), 0.9 + 0.8 * unit(rng)};
        const double length = (xyz[limb.a] - xyz[limb.b]).norm();
        const double kind = unit(rng);  // a length exactly at a bound, both ways
        if (kind < 0.1) limb.min_length_m = length;
        if (kind > 0.9) limb.max_length_m = length;
        limbs.push_back(limb);
      }
      const LimbColumns columns = ToLimbColumns(limbs);
      for (const size_t begin : {size_t{0}, static_cast<size_t>(num_limbs / 3)}) {
        const size_t end = static_cast<size_t>(num_limbs);
        uint64_t expected = 0;
        for (size_t l = begin; l < end; ++l) {
          const ResolvedLimb& limb = limbs[l];
          const double length_sq = (xyz[limb.a] - xyz[limb.b]).squaredNorm();
          if (length_sq == limb.min_length_sq() || length_sq == limb.max_length_sq()) ++at_bound;
          if (score[limb.a] > 0 && score[limb.b] > 0 &&
              (length_sq < limb.min_length_sq() || length_sq > limb.max_length_sq()))
            expected |= uint64_t{1} << (l - begin);
        }
        const uint64_t bits = simd::ImplausibleLimbs(columns, begin, end, xyz.data()->data(), score.data());
        ASSERT_EQ(bits, expected) << simd::ActivePath() << " round " << round << " begin " << begin;
        implausible += std::popcount(bits);
        ++compared;
      }
    }
    EXPECT_EQ(compared, 200);
    EXPECT_GT(implausible, 200);  // the cases hold both outcomes
    EXPECT_GT(at_bound, 50);
  });
}

// The median of a pair's residuals (median.h): the kernel's ranks against the scalar ranking, on
// random sets with ties, infinities, NaN and signed zeros, for every size the kernel takes.
TEST(SimdKernels, RankMedianEqualsTheScalarRankingBitForBit) {
  simd::ForEachPathForTest([&] {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> unit(0, 1);
    const double specials[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(), 0.0, -0.0, 1e6};
    int compared = 0, with_nan = 0;
    for (int round = 0; round < 300; ++round) {
      for (int n = 1; n <= simd::kRankMedianMax; ++n) {
        std::vector<double> values(n);
        for (double& v : values) {
          const double kind = unit(rng);
          v = kind < 0.1 ? specials[rng() % std::size(specials)] : kind < 0.4 ? std::round(unit(rng) * 4) : unit(rng);
        }
        with_nan += std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); });
        const double expected = RankMedianScalar(values.data(), n);
        const double got = simd::RankMedian(values.data(), n);
        ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0)
            << simd::ActivePath() << " n " << n << ": " << got << " vs " << expected;
        ++compared;
      }
    }
    EXPECT_EQ(compared, 300 * simd::kRankMedianMax);
    EXPECT_GT(with_nan, 100);
  });
  // Known medians, so that a ranking both sides get wrong alike is caught.
  for (const bool on : {false, true}) {
    simd::SetEnabled(on);
    std::vector<double> odd = {5, 1, 4, 1, 3};
    EXPECT_EQ(Median(odd.data(), 5), 3.0);
    std::vector<double> even = {0.4, 0.1, 0.3, 0.2};
    EXPECT_EQ(Median(even.data(), 4), 0.25);
    std::vector<double> ties = {2, 2, 2, 7, 7, 7};
    EXPECT_EQ(Median(ties.data(), 6), 4.5);
  }
  simd::SetEnabled(true);
}

// steps::Merge with the kernel against its scalar code (simd::SetEnabled(false)) on random groups,
// with repeated points (ties in the top_k choice), scores below the threshold, and every option.
TEST(SimdKernels, MergeEqualsTheScalarMergeBitForBit) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  int joints_kept = 0, compared = 0;
  for (int round = 0; round < 60; ++round) {
    const int n = kJointCounts[round % 8];
    Proposals proposals;
    proposals.Clear(n);
    Groups groups;
    groups.begin = {0};
    const int num_groups = 1 + round % 3;
    for (int g = 0; g < num_groups; ++g) {
      const int members = 1 + static_cast<int>(9 * unit(rng));
      for (int m = 0; m < members; ++m) {
        proposals.Add(PosePair{m, m + 1});
        const size_t base = static_cast<size_t>(proposals.size() - 1) * n;
        for (int j = 0; j < n; ++j) {
          const double spread = unit(rng) < 0.3 ? 0.4 : 0.05;
          proposals.xyz[base + j] = Eigen::Vector3d(j + spread * unit(rng), g + spread * unit(rng), spread * unit(rng));
          if (m > 0 && unit(rng) < 0.2) proposals.xyz[base + j] = proposals.xyz[base - n + j];  // a tie
          proposals.score[base + j] = unit(rng) < 0.2 ? 0.0 : (unit(rng) < 0.1 ? 0.05 : unit(rng));
        }
      }
      groups.begin.push_back(proposals.size());
    }
    for (int m = 0; m < proposals.size(); ++m) groups.members.push_back(m);
    for (int variant = 0; variant < 6; ++variant) {
      MergeOptions options;
      options.min_joint_score = variant == 1 ? 0.1 : 0.0;
      options.max_distance_m = variant == 2 ? 0.0 : (variant == 3 ? 0.03 : 0.2);
      options.top_k = variant == 4 ? 0 : (variant == 5 ? 8 : 1 + round % 4);
      options.score_weighted = variant % 2 == 0;
      options.keep_best_when_all_far = variant != 3 || round % 2 == 0;
      MergeScratch scratch;
      Poses3D scalar, vectorised;
      scalar.Clear(n);
      simd::SetEnabled(false);
      steps::Merge(options, {.proposals = proposals, .groups = groups}, &scratch, &scalar);
      simd::SetEnabled(true);
      simd::ForEachPathForTest([&] {
        vectorised.Clear(n);
        steps::Merge(options, {.proposals = proposals, .groups = groups}, &scratch, &vectorised);
        ASSERT_EQ(vectorised.data.size(), scalar.data.size());
        for (size_t i = 0; i < scalar.data.size(); ++i) {
          ASSERT_TRUE(SameBits(vectorised.data[i], scalar.data[i]))
              << simd::ActivePath() << " variant " << variant << " value " << i << ": " << vectorised.data[i]
              << " vs " << scalar.data[i];
        }
        ++compared;
      });
      for (size_t i = 3; i < scalar.data.size(); i += 4) joints_kept += scalar.data[i] > 0 ? 1 : 0;
    }
  }
  EXPECT_GT(compared, 360);
  EXPECT_GT(joints_kept, 1000);
}

TEST(SimdKernels, ExpMatchesFastExpNegOverItsWholeRange) {
  // Through ScoreJoints with only the ray-gap kernel: score = FastExpNeg(gap^2), gap = sqrt(x).
  simd::ForEachPathForTest([&] {
    const int n = 4096;
    std::vector<double> gap(n), score(n, 1.0), geometric(n, -1.0), xyz(3 * n, 0.0), zeros(n, 0.0);
    for (int i = 0; i < n; ++i) gap[i] = std::sqrt(29.999 * i / (n - 1));
    const simd::PoseColumns none{zeros.data(), zeros.data(), zeros.data(), zeros.data(), zeros.data(), zeros.data()};
    simd::ScoreJoints({.use_reprojection = false, .use_ray_gap = true, .inv_residual = 1, .inv_ray_gap = 1},
                      {.Pa = nullptr, .Pb = nullptr, .scale_a = 1, .scale_b = 1, .adaptive = true}, none, none, n,
                      xyz.data(), gap.data(), nullptr, score.data(), geometric.data());
    for (int i = 0; i < n; ++i) {
      const double x = gap[i] * gap[i];
      ASSERT_TRUE(SameBits(score[i], FastExpNeg(x))) << simd::ActivePath() << " x=" << x;
      ASSERT_NEAR(score[i], std::exp(-x), 1e-8 * std::exp(-x));
    }
    // Beyond 30 through the reprojection kernel alone (residual given: score = FastExpNeg(residual^2)),
    // up to the cut-off at 700 and past it, and NaN.
    std::vector<double> residual(n);
    for (int i = 0; i < n; ++i) residual[i] = std::sqrt(750.0 * i / (n - 2));
    residual[n - 1] = std::numeric_limits<double>::quiet_NaN();
    std::fill(score.begin(), score.end(), 1.0);
    std::fill(geometric.begin(), geometric.end(), -1.0);
    simd::ScoreJoints({.use_reprojection = true, .use_ray_gap = false, .inv_residual = 1, .inv_ray_gap = 1},
                      {.Pa = nullptr, .Pb = nullptr, .scale_a = 1, .scale_b = 1, .adaptive = true}, none, none, n,
                      xyz.data(), gap.data(), residual.data(), score.data(), geometric.data());
    int nonzero = 0;
    for (int i = 0; i < n; ++i) {
      const double x = residual[i] * residual[i];
      ASSERT_TRUE(SameBits(score[i], FastExpNeg(x))) << simd::ActivePath() << " x=" << x;
      if (x < 700) ASSERT_NEAR(score[i], std::exp(-x), 1e-8 * std::exp(-x)) << " x=" << x;
      else ASSERT_EQ(score[i], 0.0) << " x=" << x;
      nonzero += score[i] > 0;
    }
    EXPECT_GT(nonzero, n * 9 / 10);  // the range up to 700 is covered
  });
}

// Every frame's persons (x y z score per joint, track ids) and frame statistics' counts of a
// synthetic scene with realistic detections (false positives, misses, noise).
struct SceneOutput {
  std::vector<double> data;
  std::vector<int> track_ids;
  std::vector<int> counts;
};

SceneOutput RunScene(bool whole_body, int cameras, int people, const std::function<void(TriangulatorOptions*)>& set) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = cameras;
  options.num_people = people;
  options.whole_body = whole_body;
  options.num_frames = 25;
  options.seed = 9;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 9);
  TriangulatorOptions tri_options;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  set(&tri_options);
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  SceneOutput out;
  std::vector<Poses2D> views;
  for (int f = 0; f < options.num_frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views);
    Poses3D persons;
    FrameStats stats;
    tri.Process(views, f / scene.fps, &persons, &stats);
    out.data.insert(out.data.end(), persons.data.begin(), persons.data.end());
    out.track_ids.insert(out.track_ids.end(), persons.track_ids.begin(), persons.track_ids.end());
    out.counts.insert(out.counts.end(), std::begin(stats.count), std::end(stats.count));
  }
  return out;
}

// The whole triangulator with the kernels (every instruction set) against the steps' scalar code
// (simd::SetEnabled(false)): the same persons, bit for bit, on scenes and options that take every
// branch of the kernels.
// The undistort step of pinhole cameras (one with skew) with the kernel and with its scalar loop, on
// random joints: in and out of the image, scores below the minimum, at it, above 1 and negative,
// non-finite coordinates and scores; 17 joints (short rows) and 133 (whole body).
TEST(SimdKernels, UndistortPinholeEqualsTheScalarUndistortBitForBit) {
  if (kScalarCodeFused) GTEST_SKIP() << "built with fused multiply-add in the scalar code (RPT_MARCH_NATIVE)";
  std::vector<Camera> cameras = test::RingCameras(3);
  cameras[1].K(0, 1) = 3.5;  // skew
  cameras[2].K << 1234.5, 0, 611.25, 0, 1190.75, 377.5, 0, 0, 1;
  // A roll about the optical axis: no row of R_t has a zero to hide the order of its sums.
  cameras[2].R = Eigen::AngleAxisd(0.37, Eigen::Vector3d::UnitZ()).toRotationMatrix() * cameras[2].R;
  std::vector<ViewGeometry> geometry;
  for (const Camera& c : cameras) geometry.push_back(MakeViewGeometry(c));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pixel(-200, 1200), unit(0, 1);
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()};
  const double scores[] = {-0.5, 0.0, 0.05, 0.1, 1.0, 1.03};
  for (int joints : {17, 133}) {
    std::vector<Poses2D> views(cameras.size());
    for (Poses2D& view : views) {
      view.Clear(joints);
      for (int p = 0; p < 4; ++p) {
        auto person = view.AddPerson();
        for (int j = 0; j < joints; ++j) {
          person(0, j) = pixel(rng);
          person(1, j) = pixel(rng);
          person(2, j) = unit(rng) < 0.3 ? scores[static_cast<int>(unit(rng) * 6)] : unit(rng);
          if (unit(rng) < 0.05) person(static_cast<int>(unit(rng) * 3), j) = special[static_cast<int>(unit(rng) * 3)];
        }
      }
    }
    std::vector<int> core;
    for (int j = 0; j < 12; ++j) core.push_back(j);
    const steps::UndistortInput input{
        .views = views, .cameras = cameras, .geometry = geometry, .derived = {}, .core_joints = core,
        .num_output_joints = joints};
    for (const double min_joint_score : {UndistortOptions{}.min_joint_score, 0.0}) {  // 0: score-0 joints kept
      UndistortOptions options;
      options.min_core_joints = 1;
      options.min_joint_score = min_joint_score;
      PreparedViews scalar;
      simd::SetEnabled(false);
      const int poses = steps::Undistort(options, input, &scalar);
      simd::SetEnabled(true);
      ASSERT_EQ(poses, 12) << "every pose kept";
      simd::ForEachPathForTest([&] {
        PreparedViews vectorised;
        ASSERT_EQ(steps::Undistort(options, input, &vectorised), poses);
        ASSERT_EQ(vectorised.keypoints.size(), scalar.keypoints.size());
        for (size_t k = 0; k < scalar.keypoints.size(); ++k) {
          const Keypoint &a = vectorised.keypoints[k], &b = scalar.keypoints[k];
          const double fa[] = {a.u, a.v, a.score, a.sqrt_score, a.ray.x(), a.ray.y(), a.ray.z(), a.x, a.y};
          const double fb[] = {b.u, b.v, b.score, b.sqrt_score, b.ray.x(), b.ray.y(), b.ray.z(), b.x, b.y};
          for (int f = 0; f < 9; ++f) {
            ASSERT_TRUE(SameBits(fa[f], fb[f])) << simd::ActivePath() << " " << joints << " joints, keypoint " << k
                                                << " field " << f << ": " << fa[f] << " vs " << fb[f];
          }
        }
        EXPECT_EQ(vectorised.bbox_diag, scalar.bbox_diag);
        for (const KeypointColumns PreparedViews::*columns :
             {&PreparedViews::all_columns, &PreparedViews::core_columns}) {
          const KeypointColumns &a = vectorised.*columns, &b = scalar.*columns;
          EXPECT_EQ(a.stride, b.stride);
          for (const std::vector<double> KeypointColumns::*field :
               {&KeypointColumns::u, &KeypointColumns::v, &KeypointColumns::score, &KeypointColumns::sqrt_score,
                &KeypointColumns::rx, &KeypointColumns::ry, &KeypointColumns::rz}) {
            ASSERT_EQ((a.*field).size(), (b.*field).size());
            EXPECT_EQ(std::memcmp((a.*field).data(), (b.*field).data(), (b.*field).size() * sizeof(double)), 0)
                << simd::ActivePath() << " " << joints << " joints: a column differs";
          }
        }
      });
    }
  }
}

TEST(SimdKernels, TriangulatorOutputIsBitIdenticalToTheScalarSteps) {
  if (kScalarCodeFused) GTEST_SKIP() << "built with fused multiply-add in the scalar code (RPT_MARCH_NATIVE)";
  struct Case {
    const char* name;
    bool whole_body;
    int cameras, people;
    std::function<void(TriangulatorOptions*)> set;
  };
  const std::vector<Case> cases = {
      {"body", false, 5, 4, [](TriangulatorOptions*) {}},
      {"whole body", true, 5, 2, [](TriangulatorOptions*) {}},
      {"12 cameras", false, 12, 8, [](TriangulatorOptions*) {}},
      {"fixed scale", false, 5, 4, [](TriangulatorOptions* o) { o->score.scale = ScoreScale::kFixed; }},
      {"reprojection only", false, 5, 4, [](TriangulatorOptions* o) { o->score.mode = ScoreMode::kReprojectionOnly; }},
      {"triangulation only", false, 5, 4,
       [](TriangulatorOptions* o) { o->score.mode = ScoreMode::kTriangulationOnly; }},
      {"merge variants", false, 6, 5,
       [](TriangulatorOptions* o) {
         o->merge.top_k = 1;
         o->merge.score_weighted = false;
         o->merge.max_distance_m = 0.05;
         o->merge.keep_best_when_all_far = false;
       }},
      {"merge keep all", false, 6, 5,
       [](TriangulatorOptions* o) {
         o->merge.top_k = 0;
         o->merge.max_distance_m = 0;
       }},
      {"dlt", false, 5, 4, [](TriangulatorOptions* o) { o->triangulate.method = TriangulationMethod::kDlt; }},
  };
  for (const Case& c : cases) {
    simd::SetEnabled(false);
    const SceneOutput scalar = RunScene(c.whole_body, c.cameras, c.people, c.set);
    simd::SetEnabled(true);
    ASSERT_GT(scalar.track_ids.size(), 20u) << c.name << ": persons are found";
    simd::ForEachPathForTest([&] {
      const SceneOutput vectorised = RunScene(c.whole_body, c.cameras, c.people, c.set);
      EXPECT_EQ(vectorised.track_ids, scalar.track_ids) << c.name << " " << simd::ActivePath();
      EXPECT_EQ(vectorised.counts, scalar.counts) << c.name << " " << simd::ActivePath();
      ASSERT_EQ(vectorised.data.size(), scalar.data.size()) << c.name << " " << simd::ActivePath();
      EXPECT_EQ(std::memcmp(vectorised.data.data(), scalar.data.data(), scalar.data.size() * sizeof(double)), 0)
          << c.name << " " << simd::ActivePath();
    });
  }
}

}  // namespace
}  // namespace rpt
