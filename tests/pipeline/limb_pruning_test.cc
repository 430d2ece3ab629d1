// SPDX-License-Identifier: MIT
// Limb pruning (PruneImplausibleLimbs, proposal_scoring.h) on hand-made joints: a limb whose
// length lies outside its range invalidates its distal joint, in limb order, so a joint invalidated
// by an earlier limb no longer prunes through a later one; a length exactly at a bound is
// plausible; unscored joints are never tested. Run with the scalar first pass and with the SIMD
// kernel's on every instruction set of this CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/pipeline/proposal_scoring.h"
#include "core/pipeline/simd_kernels.h"

namespace rpt {
namespace {

// 70 joints 0.5 m apart on the x axis and the chain of 69 limbs (i, i + 1), each 0.4-0.6 m:
// two chunks of the 64-limb passes, long enough for the kernel (kMinLimbsForKernel).
struct Chain {
  Chain() {
    for (int i = 0; i < 70; ++i) {
      xyz.emplace_back(0.5 * i, 0, 0);
      score.push_back(0.8);
    }
    for (int i = 0; i + 1 < 70; ++i) limbs.push_back(ResolvedLimb{i, i + 1, 0.4, 0.6});
  }
  std::vector<Eigen::Vector3d> xyz;
  std::vector<double> score;
  std::vector<ResolvedLimb> limbs;
};

void ForScalarAndKernelFirstPass(const std::function<void(const std::string&, bool)>& body) {
  body("scalar first pass", false);
  simd::ForEachPathForTest([&] { body("SIMD " + simd::ActivePath(), true); });
}

TEST(LimbPruning, AnImplausibleLimbInvalidatesItsDistalJointInLimbOrder) {
  static_assert(kMinLimbsForKernel <= 69);
  ForScalarAndKernelFirstPass([](const std::string& path, bool kernel) {
    Chain c;
    c.xyz[10] += Eigen::Vector3d(0, 2, 0);  // limbs 9-10 and 10-11 both 2.06 m long
    c.xyz[64] += Eigen::Vector3d(0, 0, 3);  // limbs 63-64 (first chunk) and 64-65 (second)
    c.score[30] = 0;                        // unscored, with no point: limbs 29-30, 30-31 untested
    c.xyz[30].setConstant(std::numeric_limits<double>::quiet_NaN());
    c.limbs[40].min_length_m = 0.5;  // limb 40-41 exactly at its lower bound: plausible
    c.limbs[50].max_length_m = 0.5;  // and limb 50-51 at its upper bound
    const LimbColumns columns = ToLimbColumns(c.limbs);
    const int pruned = PruneImplausibleLimbs(c.limbs, kernel ? &columns : nullptr, c.xyz.data(), c.score.data());
    EXPECT_EQ(pruned, 2) << path;
    for (int i = 0; i < 70; ++i) {
      // 10 and 64 invalidated; 11 and 65 kept: their limbs start at an invalidated joint.
      const double expected = i == 10 || i == 64 ? 0.0 : (i == 30 ? 0.0 : 0.8);
      EXPECT_EQ(c.score[i], expected) << path << ", joint " << i;
    }
  });
}

TEST(LimbPruning, TooShortAndTooLongLimbsArePrunedWhereverTheyAre) {
  ForScalarAndKernelFirstPass([](const std::string& path, bool kernel) {
    Chain c;
    // Shift the tail from joint 21 on by -0.2 m: limb 20-21 is 0.3 m (too short). Then move joint
    // 68 out by 0.2 m: limb 67-68 is 0.7 m (too long), limb 68-69 0.3 m, but 68 is invalidated.
    for (int i = 21; i < 70; ++i) c.xyz[i].x() -= 0.2;
    c.xyz[68].x() += 0.2;
    const LimbColumns columns = ToLimbColumns(c.limbs);
    const int pruned = PruneImplausibleLimbs(c.limbs, kernel ? &columns : nullptr, c.xyz.data(), c.score.data());
    EXPECT_EQ(pruned, 2) << path;
    for (int i = 0; i < 70; ++i) EXPECT_EQ(c.score[i], i == 21 || i == 68 ? 0.0 : 0.8) << path << ", joint " << i;
    // The limbs given in the other order (distal chain first): limb 68-69 is tested while 68 is
    // still scored and invalidates 69 as well.
    Chain r;
    for (int i = 21; i < 70; ++i) r.xyz[i].x() -= 0.2;
    r.xyz[68].x() += 0.2;
    std::vector<ResolvedLimb> reversed(r.limbs.rbegin(), r.limbs.rend());
    const LimbColumns reversed_columns = ToLimbColumns(reversed);
    EXPECT_EQ(PruneImplausibleLimbs(reversed, kernel ? &reversed_columns : nullptr, r.xyz.data(), r.score.data()), 3)
        << path;
    EXPECT_EQ(r.score[69], 0.0) << path;
  });
}

}  // namespace
}  // namespace rpt
