// SPDX-License-Identifier: MIT
// MetricsAccumulator::Merge: frames evaluated in two accumulators and merged give the numbers of
// one accumulator fed all frames (counts and AP exactly, means up to rounding); repeated frame ids
// and different options are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.h"
#include "metrics/accumulator.h"
#include "tests/metrics/random_frames.h"

namespace rpt::metrics {
namespace {

void Add(MetricsAccumulator* accumulator, const test::RandomFrame& frame) {
  accumulator->Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
}

// Equal, both NaN, or within 1e-12 relative (sums merged as one term each).
void ExpectClose(double merged, double single, const std::string& what) {
  if (std::isnan(single)) {
    EXPECT_TRUE(std::isnan(merged)) << what;
  } else if (std::isinf(single)) {
    EXPECT_EQ(merged, single) << what;
  } else {
    EXPECT_NEAR(merged, single, 1e-12 * std::abs(single)) << what;
  }
}

void ExpectMergedEqualsSingle(const MetricsResult& merged, const MetricsResult& single) {
  // Counts and everything computed from counts only: exact.
  EXPECT_EQ(merged.num_frames, single.num_frames);
  EXPECT_EQ(merged.num_frames_with_gt, single.num_frames_with_gt);
  EXPECT_EQ(merged.num_gt_persons, single.num_gt_persons);
  EXPECT_EQ(merged.num_dropped_gt_persons, single.num_dropped_gt_persons);
  EXPECT_EQ(merged.num_predictions, single.num_predictions);
  EXPECT_EQ(merged.num_predictions_total, single.num_predictions_total);
  EXPECT_EQ(merged.num_matches, single.num_matches);
  EXPECT_EQ(merged.num_missing_pred_joints, single.num_missing_pred_joints);
  EXPECT_EQ(merged.num_unaligned_matches, single.num_unaligned_matches);
  EXPECT_EQ(merged.recall_100, single.recall_100);
  EXPECT_EQ(merged.recall_500, single.recall_500);
  EXPECT_EQ(merged.invalid, single.invalid);
  EXPECT_EQ(merged.invalid_causes.duplicate, single.invalid_causes.duplicate);
  EXPECT_EQ(merged.invalid_causes.near_matched_gt, single.invalid_causes.near_matched_gt);
  EXPECT_EQ(merged.invalid_causes.near_missed_gt, single.invalid_causes.near_missed_gt);
  EXPECT_EQ(merged.invalid_causes.far_from_gt, single.invalid_causes.far_from_gt);
  EXPECT_EQ(merged.invalid_causes.no_gt, single.invalid_causes.no_gt);
  const InvalidCauses& c = single.invalid_causes;
  EXPECT_EQ(c.Total(), single.num_predictions - single.num_matches);
  EXPECT_EQ(merged.f1, single.f1);
  EXPECT_EQ(merged.pck_100, single.pck_100);
  EXPECT_EQ(merged.pck_500, single.pck_500);
  EXPECT_EQ(merged.pcp, single.pcp);
  for (size_t k = 0; k < merged.ap.size(); ++k) EXPECT_EQ(merged.ap[k], single.ap[k]) << "ap[" << k << "]";
  // Means of sums: up to rounding.
  ExpectClose(merged.mpjpe_mm, single.mpjpe_mm, "mpjpe_mm");
  ASSERT_EQ(merged.joints.size(), single.joints.size());
  for (size_t j = 0; j < merged.joints.size(); ++j) {
    EXPECT_EQ(merged.joints[j].count, single.joints[j].count) << merged.joints[j].name;
    EXPECT_EQ(merged.joints[j].num_gt, single.joints[j].num_gt) << merged.joints[j].name;
    EXPECT_EQ(merged.joints[j].pck_100, single.joints[j].pck_100) << merged.joints[j].name;
    ExpectClose(merged.joints[j].mean_error_mm, single.joints[j].mean_error_mm, merged.joints[j].name);
  }
  ASSERT_EQ(merged.pcp_parts.size(), single.pcp_parts.size());
  for (size_t k = 0; k < merged.pcp_parts.size(); ++k) {
    EXPECT_EQ(merged.pcp_parts[k].correct, single.pcp_parts[k].correct) << merged.pcp_parts[k].name;
    EXPECT_EQ(merged.pcp_parts[k].total, single.pcp_parts[k].total) << merged.pcp_parts[k].name;
  }
  ASSERT_EQ(merged.wholebody.size(), single.wholebody.size());
  for (size_t k = 0; k < merged.wholebody.size(); ++k) {
    EXPECT_EQ(merged.wholebody[k].num_persons, single.wholebody[k].num_persons) << merged.wholebody[k].name;
    EXPECT_EQ(merged.wholebody[k].num_joints, single.wholebody[k].num_joints) << merged.wholebody[k].name;
    ExpectClose(merged.wholebody[k].mpjpe_mm, single.wholebody[k].mpjpe_mm, merged.wholebody[k].name);
  }
  ASSERT_EQ(merged.legacy_pcp.has_value(), single.legacy_pcp.has_value());
  if (!merged.legacy_pcp) return;
  EXPECT_EQ(merged.legacy_pcp->num_frames, single.legacy_pcp->num_frames);
  EXPECT_EQ(merged.legacy_pcp->num_skipped_frames, single.legacy_pcp->num_skipped_frames);
  EXPECT_EQ(merged.legacy_pcp->recall_500, single.legacy_pcp->recall_500);
  EXPECT_EQ(merged.legacy_pcp->average_pcp, single.legacy_pcp->average_pcp);
  ASSERT_EQ(merged.legacy_pcp->actors.size(), single.legacy_pcp->actors.size());
  for (size_t i = 0; i < merged.legacy_pcp->actors.size(); ++i) {
    EXPECT_EQ(merged.legacy_pcp->actors[i].actor_id, single.legacy_pcp->actors[i].actor_id);
    EXPECT_EQ(merged.legacy_pcp->actors[i].num_frames, single.legacy_pcp->actors[i].num_frames);
    EXPECT_EQ(merged.legacy_pcp->actors[i].pcp, single.legacy_pcp->actors[i].pcp);
  }
}

TEST(MetricsAccumulatorMerge, TwoHalvesMergedEqualOneAccumulatorOverAllFrames) {
  for (const MatchingMode matching : {MatchingMode::kGreedy, MatchingMode::kHungarian}) {
    for (const bool pelvis : {false, true}) {
      EvalOptions options;
      options.matching = matching;
      options.alignment = pelvis ? Alignment::kPelvis : Alignment::kNone;
      options.legacy_pcp = LegacyPcpLayout::kCampus;
      options.count_preds_without_gt = !pelvis;
      test::RandomFrames frames(31, /*wholebody=*/true, /*person_scores=*/pelvis);
      MetricsAccumulator single(options), first(options), second(options), third(options);
      for (int f = 0; f < 300; ++f) {
        const test::RandomFrame frame = frames.Next();
        Add(&single, frame);
        Add(f < 120 ? &first : f < 250 ? &second : &third, frame);
      }
      first.Merge(second);
      first.Merge(third);
      SCOPED_TRACE(std::string(matching == MatchingMode::kGreedy ? "greedy" : "hungarian") +
                   (pelvis ? ", pelvis" : ", absolute"));
      const MetricsResult merged = first.Finalize();
      ExpectMergedEqualsSingle(merged, single.Finalize());
      EXPECT_GT(merged.num_matches, 100);
    }
  }
}

TEST(MetricsAccumulatorMerge, MergingAnEmptyAccumulatorChangesNothingAndFramesContinueAfterIt) {
  test::RandomFrames frames(5, /*wholebody=*/false, /*person_scores=*/false);
  MetricsAccumulator single, merged;
  for (int f = 0; f < 40; ++f) {
    const test::RandomFrame frame = frames.Next();
    Add(&single, frame);
    Add(&merged, frame);
    if (f == 20) merged.Merge(MetricsAccumulator());
  }
  ExpectMergedEqualsSingle(merged.Finalize(), single.Finalize());
}

TEST(MetricsAccumulatorMerge, RepeatedFrameIdsAcrossTheTwoThrowInputErrorAndMergeNothing) {
  test::RandomFrames frames(9, /*wholebody=*/false, /*person_scores=*/false);
  MetricsAccumulator first, second;
  std::vector<test::RandomFrame> kept;
  for (int f = 0; f < 2000; ++f) {  // more frame ids than FrameIdSet keeps unsorted
    const test::RandomFrame frame = frames.Next();
    Add(f % 2 == 0 ? &first : &second, frame);
    if (f == 1500) kept.push_back(frame);
  }
  const MetricsResult before = first.Finalize();
  MetricsAccumulator repeats;
  Add(&repeats, kept[0]);  // frame_1500 is in `first` already
  try {
    first.Merge(repeats);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("1 frame id(s) were added to both"), std::string::npos) << error.what();
  }
  EXPECT_EQ(first.Finalize().num_frames, before.num_frames);
  first.Merge(second);  // disjoint ids
  EXPECT_EQ(first.Finalize().num_frames, 2000);
  EXPECT_THROW(Add(&first, kept[0]), InputError) << "the merged ids are known";
}

TEST(MetricsAccumulatorMerge, DifferentOptionsThrowConfigErrorNamingTheOption) {
  EvalOptions hungarian;
  hungarian.matching = MatchingMode::kHungarian;
  MetricsAccumulator greedy_accumulator, hungarian_accumulator(hungarian);
  try {
    greedy_accumulator.Merge(hungarian_accumulator);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("'matching'"), std::string::npos) << error.what();
  }
  EvalOptions joints;
  joints.evaluated_joints = {"nose", "hip_left"};
  EXPECT_THROW(MetricsAccumulator(joints).Merge(MetricsAccumulator()), ConfigError);
  EXPECT_EQ(FirstDifferentOption(EvalOptions(), EvalOptions()), "");
  EXPECT_EQ(FirstDifferentOption(joints, EvalOptions()), "evaluated_joints");
}

}  // namespace
}  // namespace rpt::metrics
