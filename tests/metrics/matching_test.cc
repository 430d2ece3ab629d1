// SPDX-License-Identifier: MIT
#include "metrics/matching.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace rpt::metrics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NearestGt, ArgminPerPredictionAndMinusOneWithoutFiniteCost) {
  Eigen::MatrixXd cost(3, 2);
  cost << 100, 150,  //
      40, 30,        //
      kInf, kInf;
  EXPECT_EQ(NearestGt(cost), (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(NearestPrediction(cost), (std::vector<int>{1, 1}));
  EXPECT_EQ(NearestGt(Eigen::MatrixXd(2, 0)), (std::vector<int>{-1, -1}));
}

TEST(GreedyMatch, HighestScoreWinsAndDuplicatesAreFalsePositives) {
  const std::vector<MatchRecord> records = {
      {0, 20.0, 0.9},   // TP: highest score
      {0, 10.0, 0.5},   // duplicate of GT 0 (better error, lower score): FP
      {1, 600.0, 0.8},  // beyond the 500 mm gate: FP
  };
  EXPECT_EQ(GreedyMatch(records, 500.0), (std::vector<bool>{true, false, false}));
  // At 15 mm the first record fails the threshold, so the duplicate becomes the TP.
  EXPECT_EQ(GreedyMatch(records, 15.0), (std::vector<bool>{false, true, false}));
  // Strict "<": an error equal to the threshold is not a match.
  EXPECT_EQ(GreedyMatch(records, 20.0), (std::vector<bool>{false, true, false}));
}

TEST(GreedyMatch, EqualScoresFallBackToAscendingError) {
  const std::vector<MatchRecord> records = {{0, 30.0, 1.0}, {0, 10.0, 1.0}, {-1, kInf, 1.0}};
  EXPECT_EQ(RankRecords(records), (std::vector<int>{1, 0, 2}));
  EXPECT_EQ(GreedyMatch(records, 500.0), (std::vector<bool>{false, true, false}));
}

TEST(HungarianMatch, MinimisesTotalErrorWhereGreedyDoesNot) {
  // Both predictions are nearest to GT 0; greedy keeps only pred 0 -> GT 0 (100 mm).
  // Hungarian: pred 0 -> GT 1 (150) + pred 1 -> GT 0 (40) = 190 < 100 + 290.
  Eigen::MatrixXd cost(2, 2);
  cost << 100, 150,  //
      40, 290;
  EXPECT_EQ(NearestGt(cost), (std::vector<int>{0, 0}));
  EXPECT_EQ(HungarianMatch(cost, 500.0), (std::vector<int>{1, 0}));
}

TEST(HungarianMatch, GatingDropsPairsAtOrAboveTheGate) {
  Eigen::MatrixXd cost(2, 2);
  cost << 100, 600,  //
      40, 500;       // 500 is not < 500
  EXPECT_EQ(HungarianMatch(cost, 500.0), (std::vector<int>{-1, 0}));
  EXPECT_EQ(HungarianMatch(cost, 50.0), (std::vector<int>{-1, 0}));
  EXPECT_EQ(HungarianMatch(cost, 30.0), (std::vector<int>{-1, -1}));
}

TEST(HungarianMatch, PrefersMorePairsOverASmallerTotal) {
  Eigen::MatrixXd cost(2, 2);
  cost << 10, 20,  //
      15, kInf;
  // {p0-g0} alone costs 10, but {p0-g1, p1-g0} matches two persons (35).
  EXPECT_EQ(HungarianMatch(cost, 500.0), (std::vector<int>{1, 0}));
  // Even when the two pairs cost far more (400 + 400) than the single best one (10).
  cost << 10, 400,  //
      400, 1000;
  EXPECT_EQ(HungarianMatch(cost, 500.0), (std::vector<int>{1, 0}));
}

TEST(HungarianMatch, RectangularInBothDirections) {
  Eigen::MatrixXd tall(3, 1);
  tall << 80, 20, 50;
  EXPECT_EQ(HungarianMatch(tall, 500.0), (std::vector<int>{-1, 0, -1}));
  Eigen::MatrixXd wide(1, 3);
  wide << 80, 20, 50;
  EXPECT_EQ(HungarianMatch(wide, 500.0), (std::vector<int>{1}));
  EXPECT_EQ(HungarianMatch(Eigen::MatrixXd(0, 2), 500.0), (std::vector<int>{}));
}

}  // namespace
}  // namespace rpt::metrics
