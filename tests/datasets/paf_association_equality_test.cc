// SPDX-License-Identifier: MIT
// PafAssociator (issue 22: the PAF grouping made fast and allocation-free) finds exactly the
// persons the previous implementation found (kept as bench/baseline_paf_association.h): on every
// view of the real 4D-Association Shelf bundle (skipped without ../shared/data) under several
// options, on random hand-built candidate sets with ties, empty joints, zero scores and negative
// links, and with every instruction set of the CPU. A warm PafAssociator allocates nothing
// (counting operator new, which is why this is its own test executable).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <random>
#include <vector>

#include "bench/baseline_paf_association.h"
#include "core/pipeline/simd_kernels.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/openpose_paf_association.h"
#include "tests/allocation_counting.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

std::vector<PafPerson> Unflatten(const PafPersons& persons) {
  std::vector<PafPerson> out;
  for (int p = 0; p < persons.size(); ++p) out.emplace_back(persons.Person(p), persons.Person(p) + persons.num_joints);
  return out;
}

std::vector<PafAssociationOptions> OptionVariants() {
  std::vector<PafAssociationOptions> variants;
  for (const double min_paf_score : {0.05, 0.3, 0.6}) {
    for (const int min_joints : {1, 3, 5}) variants.push_back({min_paf_score, min_joints});
  }
  return variants;
}

// Random candidates: up to `max_candidates` per joint, scores and PAF values drawn from a few
// levels (so equal scores, and ties between limbs, are common), some links negative, and (unless
// `positive_scores`) some candidate scores 0. With every candidate score > 0 PafAssociator takes
// its sparse way through limbs of up to 64 PAF entries (paf_limb_connections.cc), else the dense.
PafCandidates RandomCandidates(const PafSkeleton& skeleton, int max_candidates, std::mt19937* rng,
                               bool positive_scores = false) {
  std::uniform_int_distribution<int> count(0, max_candidates);
  std::uniform_int_distribution<int> level(-2, 8);
  PafCandidates c;
  for (int j = 0; j < skeleton.num_joints; ++j) {
    Eigen::Matrix3Xd m(3, count(*rng));
    for (Eigen::Index i = 0; i < m.cols(); ++i) m.col(i) << i, j, level(*rng) < 0 && !positive_scores ? 0.0 : 0.9;
    c.joints.push_back(m);
  }
  for (const auto& [a, b] : skeleton.limbs) {
    Eigen::MatrixXd paf(c.joints[static_cast<size_t>(a)].cols(), c.joints[static_cast<size_t>(b)].cols());
    for (Eigen::Index i = 0; i < paf.size(); ++i) paf(i) = 0.1 * level(*rng);
    c.pafs.push_back(paf);
  }
  return c;
}

TEST(PafAssociatorEquality, RandomCandidateSetsGiveTheBaselinePersons) {
  std::mt19937 rng(22);
  PafAssociator associator;  // one associator for all: nothing may leak from one call to the next
  PafPersons persons;
  long compared = 0, nonempty = 0;
  const std::vector<PafSkeleton> skeletons = {
      Body25PafSkeleton(), PafSkeleton{3, {{0, 1}, {1, 2}, {0, 2}}}, PafSkeleton{4, {{0, 1}, {2, 3}, {1, 2}, {0, 3}}}};
  for (int round = 0; round < 400; ++round) {
    const PafSkeleton& skeleton = skeletons[static_cast<size_t>(round) % skeletons.size()];
    const PafCandidates c = RandomCandidates(skeleton, 1 + round % 9, &rng);
    ASSERT_EQ(CheckPafCandidates(skeleton, c), "");
    for (const PafAssociationOptions& options : OptionVariants()) {
      associator.Run(skeleton, c, options, &persons);
      const std::vector<PafPerson> expected = bench::AssociatePafsBaseline(skeleton, c, options);
      ASSERT_EQ(Unflatten(persons), expected) << "round " << round << ", min_paf_score " << options.min_paf_score
                                              << ", min_joints " << options.min_joints;
      ++compared;
      nonempty += !expected.empty();
    }
  }
  EXPECT_EQ(compared, 400 * 9);
  EXPECT_GT(nonempty, compared / 2);  // the cases exercise the association, not only empty outputs
}

// As above with every candidate score > 0 (the sparse way, as on real images), and up to 12
// candidates per joint so that some limbs have more than 64 PAF entries (the dense way again) and
// many images more than 8 connections to sort (Highway's vqsort).
TEST(PafAssociatorEquality, RandomCandidateSetsWithPositiveScoresGiveTheBaselinePersons) {
  std::mt19937 rng(29);
  PafAssociator associator;
  PafPersons persons;
  long compared = 0, nonempty = 0;
  const std::vector<PafSkeleton> skeletons = {Body25PafSkeleton(), PafSkeleton{3, {{0, 1}, {1, 2}, {0, 2}}},
                                              PafSkeleton{4, {{0, 1}, {2, 3}, {1, 2}, {0, 3}}}};
  for (int round = 0; round < 400; ++round) {
    const PafSkeleton& skeleton = skeletons[static_cast<size_t>(round) % skeletons.size()];
    const PafCandidates c = RandomCandidates(skeleton, 1 + round % 12, &rng, /*positive_scores=*/true);
    ASSERT_EQ(CheckPafCandidates(skeleton, c), "");
    for (const PafAssociationOptions& options : OptionVariants()) {
      associator.Run(skeleton, c, options, &persons);
      const std::vector<PafPerson> expected = bench::AssociatePafsBaseline(skeleton, c, options);
      ASSERT_EQ(Unflatten(persons), expected)
          << "round " << round << ", min_paf_score " << options.min_paf_score << ", min_joints " << options.min_joints;
      ++compared;
      nonempty += !expected.empty();
    }
  }
  EXPECT_EQ(compared, 400 * 9);
  EXPECT_GT(nonempty, compared / 2);
}

// Every instruction set the CPU has (Highway's runtime dispatch: the PAF score mask and vqsort)
// gives the same persons, on random and real candidates.
TEST(PafAssociatorEquality, EveryInstructionSetGivesTheBaselinePersons) {
  std::vector<PafCandidates> views;
  std::mt19937 rng(31);
  for (int v = 0; v < 60; ++v) views.push_back(RandomCandidates(Body25PafSkeleton(), 2 + v % 10, &rng, v % 2 == 0));
  if (std::filesystem::exists(test::SharedData("shelf/4d_association/detection/0.txt"))) {
    InputWarnings warnings;
    const FourDaDetections d =
        ReadFourDaDetections(test::SharedData("shelf/4d_association/detection/0.txt"), &warnings);
    for (size_t f = 0; f < d.frames.size(); f += 10) views.push_back(d.frames[f]);
  }
  int paths = 0;
  simd::ForEachPathForTest([&] {
    ++paths;
    PafAssociator associator;
    PafPersons persons;
    for (size_t v = 0; v < views.size(); ++v) {
      for (const PafAssociationOptions& options : OptionVariants()) {
        associator.Run(Body25PafSkeleton(), views[v], options, &persons);
        ASSERT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(Body25PafSkeleton(), views[v], options))
            << "path " << simd::ActivePath() << ", view " << v;
      }
    }
  });
  EXPECT_GE(paths, 1);
}

TEST(PafAssociatorEquality, HandBuiltMergeAndTieCases) {
  // Two fragments (0-1, 2-3) that a weaker 1-2 link merges, then a 0-3 link inside the merged
  // person; all with equal scores so the order is the tie-break's (limb, a, b).
  const PafSkeleton skeleton{4, {{0, 1}, {2, 3}, {1, 2}, {0, 3}}};
  PafCandidates c;
  for (int j = 0; j < 4; ++j) c.joints.push_back((Eigen::Matrix3Xd(3, 2) << 0, 1, 0, 0, 0.9, 0.9).finished());
  for (int k = 0; k < 4; ++k) c.pafs.push_back(Eigen::MatrixXd::Constant(2, 2, 0.5));
  PafAssociator associator;
  PafPersons persons;
  associator.Run(skeleton, c, {0.05, 2}, &persons);
  EXPECT_EQ(Unflatten(persons), (std::vector<PafPerson>{{0, 0, 0, 0}, {1, 1, 1, 1}}));
  EXPECT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(skeleton, c, {0.05, 2}));
  // Scores that differ in their last bit only: ordered by score, not by index (the sort's check).
  const PafSkeleton one_limb{2, {{0, 1}}};
  PafCandidates close;
  for (int j = 0; j < 2; ++j) close.joints.push_back((Eigen::Matrix3Xd(3, 2) << 0, 1, 0, 0, 0.9, 0.9).finished());
  close.pafs.push_back((Eigen::MatrixXd(2, 2) << 0.5, std::nextafter(0.5, 1.0), 0.4, 0.3).finished());
  associator.Run(one_limb, close, {0.05, 2}, &persons);
  EXPECT_EQ(Unflatten(persons), (std::vector<PafPerson>{{0, 1}, {1, 0}}));
  EXPECT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(one_limb, close, {0.05, 2}));
  // The same with more connections than std::sort takes (vqsort, then the exact re-sort): 4 x 4
  // scores a few ulps apart, in an order that differs from their (a, b) order.
  PafCandidates many;
  for (int j = 0; j < 2; ++j)
    many.joints.push_back((Eigen::Matrix3Xd(3, 4) << 0, 1, 2, 3, 0, 0, 0, 0, 0.9, 0.9, 0.9, 0.9).finished());
  Eigen::MatrixXd ulps(4, 4);
  double value = 0.5;
  for (const int at : {5, 12, 3, 9, 0, 14, 7, 10, 2, 15, 6, 11, 1, 13, 4, 8}) {
    ulps(at) = value;
    value = std::nextafter(value, 1.0);
  }
  many.pafs.push_back(ulps);
  associator.Run(one_limb, many, {0.05, 2}, &persons);
  EXPECT_EQ(persons.size(), 4);
  EXPECT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(one_limb, many, {0.05, 2}));
  // A PAF score equal to min_paf_score makes a connection, one an ulp below does not: with every
  // candidate score > 0 (the sparse way) and with one candidate scored 0 (the dense way).
  for (const double third_score : {0.9, 0.0}) {
    PafCandidates edge;
    edge.joints.push_back((Eigen::Matrix3Xd(3, 3) << 0, 1, 2, 0, 0, 0, 0.9, 0.9, third_score).finished());
    edge.joints.push_back((Eigen::Matrix3Xd(3, 2) << 0, 1, 0, 0, 0.9, 0.9).finished());
    edge.pafs.push_back((Eigen::MatrixXd(3, 2) << 0.3, 0, 0, std::nextafter(0.3, 0.0), 0, 0).finished());
    associator.Run(one_limb, edge, {0.3, 2}, &persons);
    EXPECT_EQ(Unflatten(persons), (std::vector<PafPerson>{{0, 0}})) << "third candidate's score " << third_score;
    EXPECT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(one_limb, edge, {0.3, 2}));
  }
  // No candidates at all: no persons, and the associator still works afterwards.
  PafCandidates empty;
  for (int j = 0; j < 4; ++j) empty.joints.emplace_back(3, 0);
  for (int k = 0; k < 4; ++k) empty.pafs.emplace_back(0, 0);
  associator.Run(skeleton, empty, {}, &persons);
  EXPECT_EQ(persons.size(), 0);
  associator.Run(skeleton, c, {0.05, 2}, &persons);
  EXPECT_EQ(persons.size(), 2);
}

TEST(PafAssociatorEquality, RealShelfBundleGivesTheBaselinePersons) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association/detection/0.txt");
  PafAssociator associator;
  PafPersons persons;
  long views = 0, total = 0, at_defaults = 0;
  for (int c = 0; c < 5; ++c) {
    InputWarnings warnings;
    const FourDaDetections d =
        ReadFourDaDetections(test::SharedData("shelf/4d_association/detection/" + std::to_string(c) + ".txt"), &warnings);
    for (const PafCandidates& frame : d.frames) {
      ++views;
      for (const PafAssociationOptions& options : OptionVariants()) {
        associator.Run(Body25PafSkeleton(), frame, options, &persons);
        ASSERT_EQ(Unflatten(persons), bench::AssociatePafsBaseline(Body25PafSkeleton(), frame, options))
            << "camera " << c << ", view " << views;
        total += persons.size();
      }
      associator.Run(Body25PafSkeleton(), frame, {}, &persons);
      at_defaults += persons.size();
    }
  }
  EXPECT_EQ(views, 5 * 301);
  // The persons the shelf-4da reader assembled before this change (readers_shelf_4da_test.cc
  // measures 4391 at the defaults).
  EXPECT_EQ(at_defaults, 4391);
  EXPECT_GT(total, 9 * 3000);
}

TEST(PafAssociatorEquality, AWarmAssociatorAllocatesNothing) {
  std::mt19937 rng(5);
  std::vector<PafCandidates> views;
  for (int v = 0; v < 50; ++v) views.push_back(RandomCandidates(Body25PafSkeleton(), 6, &rng, v % 2 == 0));
  PafAssociator associator;
  PafPersons persons;
  long found = 0;
  for (const PafCandidates& view : views) associator.Run(Body25PafSkeleton(), view, {0.05, 3}, &persons);  // warm up
  g_allocations = 0;
  g_counting = true;
  for (const PafCandidates& view : views) {
    associator.Run(Body25PafSkeleton(), view, {0.05, 3}, &persons);
    found += persons.size();
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_GT(found, 50);
  // The baseline, by contrast, allocates on every call (the counter works).
  g_allocations = 0;
  g_counting = true;
  const std::vector<PafPerson> baseline = bench::AssociatePafsBaseline(Body25PafSkeleton(), views[0], {0.05, 3});
  g_counting = false;
  EXPECT_GT(g_allocations.load(), 0);
}

}  // namespace
}  // namespace rpt
