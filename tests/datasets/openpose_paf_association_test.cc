// SPDX-License-Identifier: MIT
// Greedy PAF association on small hand-made candidate sets where the expected persons follow
// directly from the rules in datasets/readers/openpose_paf_association.h.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "datasets/readers/openpose_paf_association.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;

// `counts[j]` candidates for joint j, all with score 0.9 at distinct x.
PafCandidates Candidates(const PafSkeleton& skeleton, const std::vector<int>& counts) {
  PafCandidates c;
  for (int j = 0; j < skeleton.num_joints; ++j) {
    Eigen::Matrix3Xd m(3, counts[static_cast<size_t>(j)]);
    for (int i = 0; i < m.cols(); ++i) m.col(i) << 10.0 * j + i, 0.0, 0.9;
    c.joints.push_back(m);
  }
  for (const auto& [a, b] : skeleton.limbs) {
    c.pafs.push_back(Eigen::MatrixXd::Zero(counts[static_cast<size_t>(a)], counts[static_cast<size_t>(b)]));
  }
  return c;
}

PafAssociationOptions MinJoints(int n) {
  PafAssociationOptions o;
  o.min_joints = n;
  return o;
}

TEST(PafAssociation, EachCandidateIsUsedOncePerLimb) {
  const PafSkeleton skeleton{2, {{0, 1}}};
  PafCandidates c = Candidates(skeleton, {2, 2});
  // (0,0) 0.9 is kept; (0,1) 0.85 is the second best link but a0 is taken, so b1 goes to a1.
  c.pafs[0] << 0.9, 0.85,  //
      0.1, 0.2;
  const std::vector<PafPerson> persons = AssociatePafs(skeleton, c, MinJoints(2));
  ASSERT_EQ(persons.size(), 2u);
  EXPECT_EQ(persons[0], (PafPerson{0, 0}));
  EXPECT_EQ(persons[1], (PafPerson{1, 1}));
}

TEST(PafAssociation, ConnectionsMergeThroughSharedCandidates) {
  // Limbs 0-1 and 2-3 start two persons; the weaker 1-2 link joins them into one.
  const PafSkeleton skeleton{4, {{0, 1}, {2, 3}, {1, 2}}};
  PafCandidates c = Candidates(skeleton, {1, 1, 1, 1});
  c.pafs[0] << 0.9;
  c.pafs[1] << 0.8;
  c.pafs[2] << 0.7;
  const std::vector<PafPerson> persons = AssociatePafs(skeleton, c, MinJoints(2));
  ASSERT_EQ(persons.size(), 1u);
  EXPECT_EQ(persons[0], (PafPerson{0, 0, 0, 0}));
}

TEST(PafAssociation, PersonsSharingAJointAreNotMerged) {
  // Two persons each with a joint-0 candidate; a 1-2 link between them would give one person two
  // joint-0 candidates, so it is dropped.
  const PafSkeleton skeleton{3, {{0, 1}, {0, 2}, {1, 2}}};
  PafCandidates c = Candidates(skeleton, {2, 1, 1});
  c.pafs[0] << 0.9, 0.0;  // a0-b0
  c.pafs[1] << 0.0, 0.8;  // a1-c0
  c.pafs[2] << 0.7;       // b0-c0
  const std::vector<PafPerson> persons = AssociatePafs(skeleton, c, MinJoints(2));
  ASSERT_EQ(persons.size(), 2u);
  EXPECT_EQ(persons[0], (PafPerson{0, 0, -1}));
  EXPECT_EQ(persons[1], (PafPerson{1, -1, 0}));
}

TEST(PafAssociation, APersonKeepsItsFirstCandidateOfAJoint) {
  // Triangle 0-1-2: the person gets c0 through 1-2 first; the later 0-2 link to c1 cannot add a
  // second joint-2 candidate, and c1 alone forms no person.
  const PafSkeleton skeleton{3, {{0, 1}, {1, 2}, {0, 2}}};
  PafCandidates c = Candidates(skeleton, {1, 1, 2});
  c.pafs[0] << 0.9;
  c.pafs[1] << 0.8, 0.0;
  c.pafs[2] << 0.0, 0.7;
  const std::vector<PafPerson> persons = AssociatePafs(skeleton, c, MinJoints(2));
  ASSERT_EQ(persons.size(), 1u);
  EXPECT_EQ(persons[0], (PafPerson{0, 0, 0}));
}

TEST(PafAssociation, ThresholdsOnPafScoreCandidateScoreAndJointCount) {
  const PafSkeleton skeleton{3, {{0, 1}, {1, 2}}};
  PafCandidates c = Candidates(skeleton, {1, 1, 1});
  c.pafs[0] << 0.9;
  c.pafs[1] << 0.04;
  PafAssociationOptions options = MinJoints(2);
  EXPECT_EQ(AssociatePafs(skeleton, c, options), (std::vector<PafPerson>{{0, 0, -1}}));  // 0.04 < 0.05
  options.min_paf_score = 0.01;
  EXPECT_EQ(AssociatePafs(skeleton, c, options), (std::vector<PafPerson>{{0, 0, 0}}));
  options.min_joints = 4;
  EXPECT_TRUE(AssociatePafs(skeleton, c, options).empty());
  options.min_joints = 2;
  c.joints[0](2, 0) = 0.0;  // a candidate with score 0 takes part in no connection
  EXPECT_EQ(AssociatePafs(skeleton, c, options), (std::vector<PafPerson>{{-1, 0, 0}}));
  c.pafs[1] << -0.5;  // negative PAF scores are no link
  EXPECT_TRUE(AssociatePafs(skeleton, c, options).empty());
}

TEST(PafAssociation, EqualScoresAreResolvedByLimbThenCandidate) {
  const PafSkeleton skeleton{2, {{0, 1}}};
  PafCandidates c = Candidates(skeleton, {2, 2});
  c.pafs[0].setConstant(0.5);
  const std::vector<PafPerson> persons = AssociatePafs(skeleton, c, MinJoints(2));
  EXPECT_EQ(persons, (std::vector<PafPerson>{{0, 0}, {1, 1}}));
}

TEST(PafAssociation, CheckNamesShapeMismatches) {
  const PafSkeleton skeleton{2, {{0, 1}}};
  PafCandidates c = Candidates(skeleton, {2, 3});
  EXPECT_EQ(CheckPafCandidates(skeleton, c), "");
  c.pafs[0].resize(3, 2);
  EXPECT_THAT(CheckPafCandidates(skeleton, c), HasSubstr("limb 0: PAF matrix is 3x2, the joints have 2 and 3 candidates"));
  c.pafs.clear();
  EXPECT_THAT(CheckPafCandidates(skeleton, c), HasSubstr("0 PAF matrices, the skeleton has 1 limbs"));
  const PafCandidates one_limb = Candidates(PafSkeleton{2, {{0, 1}}}, {1, 1});
  EXPECT_THAT(CheckPafCandidates(PafSkeleton{2, {{0, 2}}}, one_limb),
              HasSubstr("limb 0: joints (0, 2) are not two different joints of the skeleton"));
  EXPECT_THAT(CheckPafCandidates(PafSkeleton{3, {{0, 1}}}, c), HasSubstr("2 joints, the skeleton has 3"));
}

}  // namespace
}  // namespace rpt
