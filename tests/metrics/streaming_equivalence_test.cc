// SPDX-License-Identifier: MIT
// MetricsAccumulator gives, bit for bit, the numbers of the pre-streaming accumulator (the frozen
// oracle in reference_metrics.cc) on randomised frames, for every combination of the options that
// change how records are matched or reduced; and each frame's matches (LastFrame()) are the
// frame's part of the whole run's matching.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "metrics/accumulator.h"
#include "tests/metrics/random_frames.h"
#include "tests/metrics/reference_metrics.h"

namespace rpt::metrics {
namespace {

// Same bits, or both NaN.
bool Identical(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) || (std::isnan(a) && std::isnan(b));
}

#define EXPECT_IDENTICAL(a, b) EXPECT_PRED2(Identical, a, b) << context

void ExpectIdentical(const MetricsResult& a, const MetricsResult& b, const std::string& context) {
  EXPECT_IDENTICAL(a.pcp, b.pcp);
  EXPECT_IDENTICAL(a.pck_100, b.pck_100);
  EXPECT_IDENTICAL(a.pck_500, b.pck_500);
  EXPECT_IDENTICAL(a.mpjpe_mm, b.mpjpe_mm);
  EXPECT_IDENTICAL(a.recall_100, b.recall_100);
  EXPECT_IDENTICAL(a.recall_500, b.recall_500);
  EXPECT_IDENTICAL(a.invalid, b.invalid);
  EXPECT_IDENTICAL(a.f1, b.f1);
  for (size_t k = 0; k < a.ap.size(); ++k) EXPECT_IDENTICAL(a.ap[k], b.ap[k]) << " ap[" << k << "]";
  EXPECT_EQ(a.num_frames, b.num_frames) << context;
  EXPECT_EQ(a.num_frames_with_gt, b.num_frames_with_gt) << context;
  EXPECT_EQ(a.num_gt_persons, b.num_gt_persons) << context;
  EXPECT_EQ(a.num_dropped_gt_persons, b.num_dropped_gt_persons) << context;
  EXPECT_EQ(a.num_predictions, b.num_predictions) << context;
  EXPECT_EQ(a.num_predictions_total, b.num_predictions_total) << context;
  EXPECT_EQ(a.num_matches, b.num_matches) << context;
  EXPECT_EQ(a.invalid_causes.duplicate, b.invalid_causes.duplicate) << context;
  EXPECT_EQ(a.invalid_causes.near_matched_gt, b.invalid_causes.near_matched_gt) << context;
  EXPECT_EQ(a.invalid_causes.near_missed_gt, b.invalid_causes.near_missed_gt) << context;
  EXPECT_EQ(a.invalid_causes.far_from_gt, b.invalid_causes.far_from_gt) << context;
  EXPECT_EQ(a.invalid_causes.no_gt, b.invalid_causes.no_gt) << context;
  EXPECT_EQ(a.num_missing_pred_joints, b.num_missing_pred_joints) << context;
  EXPECT_EQ(a.num_unaligned_matches, b.num_unaligned_matches) << context;
  ASSERT_EQ(a.joints.size(), b.joints.size()) << context;
  for (size_t j = 0; j < a.joints.size(); ++j) {
    EXPECT_EQ(a.joints[j].name, b.joints[j].name) << context;
    EXPECT_IDENTICAL(a.joints[j].mean_error_mm, b.joints[j].mean_error_mm) << " " << a.joints[j].name;
    EXPECT_IDENTICAL(a.joints[j].pck_100, b.joints[j].pck_100) << " " << a.joints[j].name;
    EXPECT_EQ(a.joints[j].count, b.joints[j].count) << context << " " << a.joints[j].name;
    EXPECT_EQ(a.joints[j].num_gt, b.joints[j].num_gt) << context << " " << a.joints[j].name;
  }
  ASSERT_EQ(a.pcp_parts.size(), b.pcp_parts.size()) << context;
  for (size_t k = 0; k < a.pcp_parts.size(); ++k) {
    EXPECT_EQ(a.pcp_parts[k].name, b.pcp_parts[k].name) << context;
    EXPECT_EQ(a.pcp_parts[k].correct, b.pcp_parts[k].correct) << context << " " << a.pcp_parts[k].name;
    EXPECT_EQ(a.pcp_parts[k].total, b.pcp_parts[k].total) << context << " " << a.pcp_parts[k].name;
    EXPECT_IDENTICAL(a.pcp_parts[k].pcp, b.pcp_parts[k].pcp) << " " << a.pcp_parts[k].name;
  }
  ASSERT_EQ(a.wholebody.size(), b.wholebody.size()) << context;
  for (size_t k = 0; k < a.wholebody.size(); ++k) {
    EXPECT_EQ(a.wholebody[k].name, b.wholebody[k].name) << context;
    EXPECT_IDENTICAL(a.wholebody[k].mpjpe_mm, b.wholebody[k].mpjpe_mm) << " " << a.wholebody[k].name;
    EXPECT_EQ(a.wholebody[k].num_persons, b.wholebody[k].num_persons) << context << " " << a.wholebody[k].name;
    EXPECT_EQ(a.wholebody[k].num_joints, b.wholebody[k].num_joints) << context << " " << a.wholebody[k].name;
  }
  ASSERT_EQ(a.legacy_pcp.has_value(), b.legacy_pcp.has_value()) << context;
  if (!a.legacy_pcp) return;
  const LegacyPcpResult& la = *a.legacy_pcp;
  const LegacyPcpResult& lb = *b.legacy_pcp;
  EXPECT_IDENTICAL(la.average_pcp, lb.average_pcp);
  for (int g = 0; g < kNumLegacyGroups; ++g) EXPECT_IDENTICAL(la.average_group_pcp[g], lb.average_group_pcp[g]);
  EXPECT_IDENTICAL(la.recall_500, lb.recall_500);
  EXPECT_EQ(la.num_frames, lb.num_frames) << context;
  EXPECT_EQ(la.num_skipped_frames, lb.num_skipped_frames) << context;
  ASSERT_EQ(la.actors.size(), lb.actors.size()) << context;
  for (size_t i = 0; i < la.actors.size(); ++i) {
    EXPECT_EQ(la.actors[i].actor_id, lb.actors[i].actor_id) << context;
    EXPECT_EQ(la.actors[i].num_frames, lb.actors[i].num_frames) << context;
    EXPECT_EQ(la.actors[i].averaged, lb.actors[i].averaged) << context;
    EXPECT_IDENTICAL(la.actors[i].pcp, lb.actors[i].pcp);
    for (int g = 0; g < kNumLegacyGroups; ++g) EXPECT_IDENTICAL(la.actors[i].group_pcp[g], lb.actors[i].group_pcp[g]);
  }
}

// Per prediction of the frame added last: matched at the gate (to which kept GT) and the error to
// its nearest GT, in the reference's terms.
reference::ReferenceAccumulator::FrameMatches Matches(const FrameRecords& frame) {
  reference::ReferenceAccumulator::FrameMatches matches;
  matches.pred_matched.assign(frame.num_predictions, false);
  matches.pred_matched_gt.assign(frame.num_predictions, -1);
  matches.pred_error_mm.assign(frame.num_predictions, std::numeric_limits<double>::infinity());
  for (const PairRecord& pair : frame.pairs) {
    if (pair.flags & kNearest) matches.pred_error_mm[pair.pred_idx] = pair.error_mm;
    if (!(pair.flags & kMatch)) continue;
    matches.pred_matched[pair.pred_idx] = true;
    matches.pred_matched_gt[pair.pred_idx] = pair.gt_idx;
  }
  return matches;
}

void ExpectSameMatches(const std::vector<reference::ReferenceAccumulator::FrameMatches>& frames,
                       const std::vector<reference::ReferenceAccumulator::FrameMatches>& expected,
                       const std::string& context) {
  ASSERT_EQ(frames.size(), expected.size()) << context;
  for (size_t f = 0; f < frames.size(); ++f) {
    EXPECT_EQ(frames[f].pred_matched, expected[f].pred_matched) << context << ", frame " << f;
    EXPECT_EQ(frames[f].pred_matched_gt, expected[f].pred_matched_gt) << context << ", frame " << f;
    EXPECT_EQ(frames[f].pred_error_mm, expected[f].pred_error_mm) << context << ", frame " << f;
  }
}

// Every combination of the switches that change matching or reduction, plus the kind of data.
struct Combination {
  EvalOptions options;
  bool wholebody_data = false;
  bool person_scores = false;
  std::string name;
};

std::vector<Combination> AllCombinations() {
  std::vector<Combination> all;
  for (int bits = 0; bits < (1 << 8) * 3; ++bits) {
    Combination c;
    EvalOptions& o = c.options;
    o.matching = bits & 1 ? MatchingMode::kHungarian : MatchingMode::kGreedy;
    o.pck_denominator = bits & 2 ? PckDenominator::kMatchedGt : PckDenominator::kAllGt;
    o.alignment = bits & 4 ? Alignment::kPelvis : Alignment::kNone;
    o.pcp_matching = bits & 8 ? PcpMatching::kMatched : PcpMatching::kNearest;
    o.wholebody_groups = (bits & 16) != 0;
    o.count_preds_without_gt = (bits & 32) != 0;
    c.person_scores = (bits & 64) != 0;
    c.wholebody_data = (bits & 128) != 0;
    o.legacy_pcp = std::array{LegacyPcpLayout::kNone, LegacyPcpLayout::kShelf, LegacyPcpLayout::kCampus}[bits >> 8];
    o.legacy_pcp_skip_empty_frames = (bits >> 8) == 2;
    o.match_threshold_mm = bits & 2 ? 150.0 : 500.0;
    std::ostringstream name;
    name << "matching " << (bits & 1 ? "hungarian" : "greedy") << ", pck " << (bits & 2 ? "matched" : "all_gt")
         << ", alignment " << (bits & 4 ? "pelvis" : "none") << ", pcp_matching "
         << (bits & 8 ? "matched" : "nearest") << ", wholebody_groups " << ((bits & 16) != 0)
         << ", count_preds_without_gt " << ((bits & 32) != 0) << ", person scores " << c.person_scores
         << ", whole-body data " << c.wholebody_data << ", legacy " << (bits >> 8);
    c.name = name.str();
    all.push_back(c);
  }
  return all;
}

TEST(StreamingEquivalence, EveryOptionCombinationMatchesThePreStreamingAccumulatorBitForBit) {
  int seed = 0;
  for (const Combination& c : AllCombinations()) {
    test::RandomFrames frames(1000 + seed++, c.wholebody_data, c.person_scores);
    MetricsAccumulator accumulator(c.options);
    reference::ReferenceAccumulator reference(c.options);
    std::vector<reference::ReferenceAccumulator::FrameMatches> last_frames;
    for (int f = 0; f < 24; ++f) {
      const test::RandomFrame frame = frames.Next();
      accumulator.Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
      reference.Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
      last_frames.push_back(Matches(accumulator.LastFrame()));
    }
    ExpectIdentical(accumulator.Finalize(), reference.Finalize(), c.name);
    // Each frame's matches as Add() resolved them are the frame's part of the run's matching.
    ExpectSameMatches(last_frames, reference.PerFrameMatches(), c.name);
    if (HasFailure()) return;  // one combination's diagnostics are enough
  }
}

TEST(StreamingEquivalence, ThousandsOfFramesWithTiedScoresMatchBitForBit) {
  // Long runs: score ties across many frames (the greedy ranking over the whole run), both matchings.
  for (const MatchingMode matching : {MatchingMode::kGreedy, MatchingMode::kHungarian}) {
    EvalOptions options;
    options.matching = matching;
    options.legacy_pcp = LegacyPcpLayout::kShelf;
    test::RandomFrames frames(7, /*wholebody=*/false, /*person_scores=*/true);
    MetricsAccumulator accumulator(options);
    reference::ReferenceAccumulator reference(options);
    std::vector<reference::ReferenceAccumulator::FrameMatches> last_frames;
    for (int f = 0; f < 3000; ++f) {
      const test::RandomFrame frame = frames.Next();
      accumulator.Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
      reference.Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
      last_frames.push_back(Matches(accumulator.LastFrame()));
      if (f == 100) ExpectIdentical(accumulator.Finalize(), reference.Finalize(), "after 101 frames");
    }
    const MetricsResult result = accumulator.Finalize();
    ExpectIdentical(result, reference.Finalize(), "3000 frames");
    ExpectSameMatches(last_frames, reference.PerFrameMatches(), "3000 frames");
    // The data exercise what they should: matches and misses, duplicates, frames without GT.
    EXPECT_GT(result.num_matches, 1000);
    EXPECT_GT(result.num_predictions, result.num_matches + 500);
    EXPECT_LT(result.num_frames_with_gt, 2700);
    EXPECT_GT(result.num_dropped_gt_persons, 50);
    EXPECT_GT(result.num_missing_pred_joints, 100);
    EXPECT_GT(result.ap[5], 1.0);
  }
}

}  // namespace
}  // namespace rpt::metrics
