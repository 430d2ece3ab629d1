// SPDX-License-Identifier: MIT
// metrics::IdentityAccumulator: identity switches counted by hand on a five-frame scene of two GT
// persons (ids 7 and 9, 2 m apart) and predictions on them with chosen track ids.
#include "metrics/identity_counts.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "metrics/accumulator.h"
#include "tests/metrics/metrics_test_util.h"

namespace rpt::metrics {
namespace {

using test::AddPerson;
using test::CocoBodyTemplate;
using test::EmptyPoses;
using test::Shifted;

// Adds one frame: GT persons 7 (at x = 0) and 9 (at x = 2 m), and per entry of `predictions` a
// person at GT `at` (0 or 1, 3 cm off) with track id `track`.
void AddFrame(MetricsAccumulator* metrics, IdentityAccumulator* identity, const std::string& id,
              const std::vector<std::pair<int, int>>& predictions) {
  Poses3D gt = EmptyPoses(17);
  AddPerson(&gt, CocoBodyTemplate(), 1.0, 7);
  AddPerson(&gt, Shifted(CocoBodyTemplate(), {2.0, 0, 0}), 1.0, 9);
  Poses3D pred = EmptyPoses(17);
  for (const auto& [at, track] : predictions) {
    AddPerson(&pred, Shifted(CocoBodyTemplate(), {2.0 * at + 0.03, 0, 0}), 0.9, track);
  }
  metrics->Add(id, gt, CocoBodyJoints(), pred, CocoBodyJoints());
  identity->Add(metrics->LastFrame(), gt, pred);
}

TEST(IdentityCounts, SwitchesBreaksAndReturnsCountedByHand) {
  MetricsAccumulator metrics;
  IdentityAccumulator identity;
  AddFrame(&metrics, &identity, "f0", {{0, 1}, {1, 2}});  // 7 -> 1, 9 -> 2
  AddFrame(&metrics, &identity, "f1", {{0, 1}, {1, 2}});  // as before
  AddFrame(&metrics, &identity, "f2", {{0, 2}, {1, 1}});  // swapped: 2 switches
  AddFrame(&metrics, &identity, "f3", {{0, 5}});          // 7 resumes as track 5: 1 switch; 9 missed
  AddFrame(&metrics, &identity, "f4", {{1, 1}, {0, -1}}); // 9 as its last (1): none; untracked: not counted
  const IdentityCounts c = identity.counts();
  EXPECT_EQ(c.tracked_matches, 8);
  EXPECT_EQ(c.id_switches, 3);
  EXPECT_EQ(c.gt_identities, 2);
  EXPECT_EQ(c.matched_identities, 2);
  EXPECT_EQ(c.track_ids, 3);  // 1, 2, 5
}

// GT persons without ids (-1) count nothing; one with an id 1 m from the prediction (no match at
// 500 mm) is a GT person, never matched.
TEST(IdentityCounts, UnmatchedOrAnonymousPersonsCountNothing) {
  MetricsAccumulator metrics;
  IdentityAccumulator identity;
  Poses3D gt = EmptyPoses(17);
  AddPerson(&gt, CocoBodyTemplate(), 1.0, -1);
  Poses3D pred = EmptyPoses(17);
  AddPerson(&pred, CocoBodyTemplate(), 0.9, 4);
  metrics.Add("a", gt, CocoBodyJoints(), pred, CocoBodyJoints());
  identity.Add(metrics.LastFrame(), gt, pred);
  gt = EmptyPoses(17);
  AddPerson(&gt, CocoBodyTemplate(), 1.0, 3);
  pred = EmptyPoses(17);
  AddPerson(&pred, Shifted(CocoBodyTemplate(), {1.0, 0, 0}), 0.9, 4);
  metrics.Add("b", gt, CocoBodyJoints(), pred, CocoBodyJoints());
  identity.Add(metrics.LastFrame(), gt, pred);
  const IdentityCounts c = identity.counts();
  EXPECT_EQ(c.tracked_matches, 0);
  EXPECT_EQ(c.id_switches, 0);
  EXPECT_EQ(c.gt_identities, 1) << "id 3 is labelled, never matched";
  EXPECT_EQ(c.matched_identities, 0);
  EXPECT_EQ(c.track_ids, 1);
  IdentityCounts sum = c;
  sum.Merge({2, 2, 5, 10, 3});
  EXPECT_EQ(sum.gt_identities, 3);
  EXPECT_EQ(sum.matched_identities, 2);
  EXPECT_EQ(sum.track_ids, 6);
  EXPECT_EQ(sum.tracked_matches, 10);
  EXPECT_EQ(sum.id_switches, 3);
}

}  // namespace
}  // namespace rpt::metrics
