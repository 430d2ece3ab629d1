// SPDX-License-Identifier: MIT
// The adaptive score's noise estimate (noise_scale.h) and its effect on scoring.
#include <gtest/gtest.h>

#include "core/pipeline/noise_scale.h"

namespace rpt {
namespace {

TEST(NoiseScale, StartsAtThePriorAndFollowsTheVotes) {
  NoiseScale noise(0.02);
  EXPECT_NEAR(noise.Estimate(), 0.02, 0.02 * 0.06) << "within one histogram bin of the prior";
  // 100 frames of 5 votes at 5 cm: the median moves there and the prior no longer matters.
  for (int f = 0; f < 100; ++f) {
    noise.BeginFrame();
    for (int v = 0; v < 5; ++v) noise.Vote(0.05);
  }
  EXPECT_NEAR(noise.Estimate(), 0.05, 0.05 * 0.06);
  EXPECT_EQ(noise.votes(), 500);
  // Then the data changes to 1 cm: the estimate follows within a few hundred frames.
  for (int f = 0; f < 300; ++f) {
    noise.BeginFrame();
    for (int v = 0; v < 5; ++v) noise.Vote(0.01);
  }
  EXPECT_NEAR(noise.Estimate(), 0.01, 0.01 * 0.06);
}

TEST(NoiseScale, IgnoresImplausibleVotesAndClamps) {
  NoiseScale noise(0.02);
  for (int v = 0; v < 1000; ++v) noise.Vote(0.5);  // cross-person pairs: above the plausibility cap
  EXPECT_EQ(noise.votes(), 0);
  EXPECT_NEAR(noise.Estimate(), 0.02, 0.02 * 0.06);
  for (int v = 0; v < 1000; ++v) noise.Vote(0.0);  // exact data: clamped at the lower bound
  EXPECT_DOUBLE_EQ(noise.Estimate(), NoiseScale::kMinNoiseM);
  noise.Reset(0.03);
  EXPECT_NEAR(noise.Estimate(), 0.03, 0.03 * 0.06);
  EXPECT_EQ(noise.votes(), 0);
}

TEST(NoiseScale, MedianIsRobustToAMinorityOfOutliers) {
  NoiseScale noise(0.02);
  for (int v = 0; v < 300; ++v) noise.Vote(v % 10 < 3 ? 0.12 : 0.03);  // 30 % wrong pairs at 12 cm
  EXPECT_NEAR(noise.Estimate(), 0.03, 0.03 * 0.1);
}

}  // namespace
}  // namespace rpt
