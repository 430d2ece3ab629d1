// SPDX-License-Identifier: MIT
#include "metrics/average_precision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace rpt::metrics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Two GT persons. Ranked records: TP-candidate (20 mm), far FP, TP-candidate (60 mm).
const std::vector<MatchRecord> kRecords = {
    {0, 20.0, 0.9},
    {1, 7000.0, 0.8},
    {1, 60.0, 0.7},
};

TEST(AveragePrecision, TinyCaseByHand) {
  // t = 25: TP, FP, FP. recall = .5 .5 .5, precision = 1 .5 1/3 (already monotone).
  // AP = (.5 - 0) * 1 = 0.5.
  EXPECT_NEAR(AveragePrecision(kRecords, 2, 25.0), 0.5, 1e-12);
  EXPECT_NEAR(AveragePrecision(kRecords, 2, 50.0), 0.5, 1e-12);
  // t = 75: TP, FP, TP. recall = .5 .5 1, precision = 1 .5 2/3 -> monotone 1 2/3 2/3.
  // AP = .5 * 1 + .5 * 2/3 = 5/6.
  EXPECT_NEAR(AveragePrecision(kRecords, 2, 75.0), 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(AveragePrecision(kRecords, 2, 150.0), 5.0 / 6.0, 1e-12);
}

TEST(AveragePrecision, PrecisionIsMadeMonotoneFromTheRight) {
  // Three GT; ranked TP, FP, TP, TP. recall = 1/3 1/3 2/3 1, precision = 1 1/2 2/3 3/4
  // -> monotone 1 3/4 3/4 3/4. AP = 1/3 * 1 + 1/3 * 3/4 + 1/3 * 3/4 = 5/6
  // (without the monotone step it would be 1/3 * (1 + 2/3 + 3/4) = 29/36).
  const std::vector<MatchRecord> records = {{0, 10.0, 0.9}, {-1, kInf, 0.8}, {1, 10.0, 0.7}, {2, 10.0, 0.6}};
  EXPECT_NEAR(AveragePrecision(records, 3, 25.0), 5.0 / 6.0, 1e-12);
}

TEST(AveragePrecision, PerfectDetectionsGiveOne) {
  const std::vector<MatchRecord> records = {{0, 1.0, 0.9}, {1, 1.0, 0.8}};
  EXPECT_DOUBLE_EQ(AveragePrecision(records, 2, 25.0), 1.0);
  // A missed third GT caps recall at 2/3.
  EXPECT_NEAR(AveragePrecision(records, 3, 25.0), 2.0 / 3.0, 1e-12);
}

TEST(AveragePrecision, EmptyInputs) {
  EXPECT_DOUBLE_EQ(AveragePrecision({}, 2, 25.0), 0.0);
  EXPECT_TRUE(std::isnan(AveragePrecision(kRecords, 0, 25.0)));
}

}  // namespace
}  // namespace rpt::metrics
