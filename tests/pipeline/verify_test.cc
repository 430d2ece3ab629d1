// SPDX-License-Identifier: MIT
// Step 11b on hand-made geometry: re-scoring persons against all views (verify.h), judged by the
// other views (view_verdict.h). Step 12b's use of the same verdict: single_view_test.cc.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "core/pipeline/undistort.h"
#include "core/pipeline/verify.h"
#include "core/pipeline/view_geometry.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// A person to verify: `body`, merged from the pairs `view_pairs` of pose `source` (an index into
// `detected`; every detected person is seen by every camera here).
struct Candidate {
  Eigen::Matrix4Xd body;
  int source = 0;
  std::vector<std::pair<int, int>> view_pairs = {{0, 1}};
};

// `num_cameras` ring cameras see `detected`; the persons to verify are `candidates`.
struct VerifyFixture {
  // `edit` changes the projected views before they are prepared.
  VerifyFixture(std::vector<Eigen::Matrix4Xd> detected, std::vector<Candidate> candidates, int num_cameras = 5,
                const std::function<void(std::vector<Poses2D>*)>& edit = nullptr)
      : cameras(test::RingCameras(num_cameras)) {
    std::vector<Poses2D> views = test::ProjectPersons(cameras, detected);
    if (edit) edit(&views);
    test::UndistortCocoViews(cameras, views, &geometry, &core, &prepared);
    persons.Clear(17);
    proposals.Clear(17);
    groups.begin = {0};
    for (const Candidate& candidate : candidates) {
      persons.AddPerson() = candidate.body;
      for (const auto& [va, vb] : candidate.view_pairs) {
        proposals.Add(PosePair{prepared.view_begin[va] + candidate.source, prepared.view_begin[vb] + candidate.source});
        groups.members.push_back(proposals.size() - 1);
      }
      groups.begin.push_back(proposals.size());
    }
  }
  int Run(const VerifyOptions& options = {}) {
    FrameStats stats;
    ScoreKernel kernel;
    kernel.scale_m = 0.05;
    const int kept = steps::Verify(options,
                                   {.views = prepared,
                                    .geometry = geometry,
                                    .core_joints = core,
                                    .proposals = proposals,
                                    .groups = groups,
                                    .kernel = kernel},
                                   &scratch, &persons, &stats);
    dropped = stats.unsupported_persons;
    duplicates = stats.duplicate_persons;
    return kept;
  }
  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;
  std::vector<int> core;
  PreparedViews prepared;
  Proposals proposals;
  Groups groups;
  Poses3D persons;
  VerifyScratch scratch;
  int dropped = 0;
  int duplicates = 0;
};

// `body` moved by `dx` metres along x.
Eigen::Matrix4Xd Shifted(Eigen::Matrix4Xd body, double dx) {
  body.row(0).array() += dx;
  return body;
}

TEST(Verify, KeepsPersonsTheOtherViewsSee) {
  const auto a = test::StandingPerson(-1, 0), b = test::StandingPerson(1, 0.5);
  VerifyFixture f({a, b}, {{a, 0}, {b, 1}});
  EXPECT_EQ(f.Run(), 2);
  EXPECT_EQ(f.dropped, 0);
}

TEST(Verify, DropsAPersonWhereEveryOtherCameraSeesNobody) {
  // A phantom in the middle of the room, "made" from person a's poses in views 0 and 1: the other
  // three cameras look at an empty spot (a is 1.5 m away).
  const auto a = test::StandingPerson(-1.5, 0);
  const auto phantom = test::StandingPerson(1.0, 0.0);
  VerifyFixture f({a}, {{a, 0}, {phantom, 0}});
  ASSERT_EQ(f.Run(), 1);
  EXPECT_EQ(f.dropped, 1);
  EXPECT_LT((f.persons.Person(0) - a).norm(), 1e-12) << "the real person is kept, in place";
  // Off: nothing is dropped. Stricter: with 4 empty views required, 3 are not enough.
  VerifyFixture off({a}, {{a, 0}, {phantom, 0}});
  VerifyOptions disabled;
  disabled.enabled = false;
  EXPECT_EQ(off.Run(disabled), 2);
  VerifyFixture strict({a}, {{a, 0}, {phantom, 0}});
  VerifyOptions four;
  four.min_empty_views = 4;
  EXPECT_EQ(strict.Run(four), 2);
}

TEST(Verify, ACameraWithoutDataThisFrameDoesNotVoteAgainstAPerson) {
  // Cameras 2-4 drop out while 0 and 1 still see the person: as empty views (looked, saw nobody)
  // three cameras outvote the two; as unavailable views (no data) they do not vote, and the
  // person stays.
  const auto a = test::StandingPerson(0.2, -0.1);
  const auto empty_2_to_4 = [](bool unavailable) {
    return [unavailable](std::vector<Poses2D>* views) {
      for (size_t v = 2; v < views->size(); ++v) {
        (*views)[v].Clear((*views)[v].num_joints);
        (*views)[v].unavailable = unavailable;
      }
    };
  };
  VerifyFixture empty({a}, {{a, 0}}, 5, empty_2_to_4(false));
  EXPECT_EQ(empty.Run(), 0);
  EXPECT_EQ(empty.dropped, 1);
  VerifyFixture unavailable({a}, {{a, 0}}, 5, empty_2_to_4(true));
  ASSERT_EQ(unavailable.prepared.unavailable, (std::vector<char>{0, 0, 1, 1, 1}));
  EXPECT_EQ(unavailable.Run(), 1);
  EXPECT_EQ(unavailable.dropped, 0);
}

TEST(Verify, AnOccludedPersonIsNotAPhantom) {
  // The candidate stands where another detected person (c) covers it in the other views: those
  // views are occupied, not empty, so it is kept even though no pose there agrees with it.
  const auto a = test::StandingPerson(-1.5, 0), c = test::StandingPerson(1.0, 0.0);
  const auto hidden = test::StandingPerson(1.0, 0.25);
  VerifyFixture f({a, c}, {{hidden, 0}});
  EXPECT_EQ(f.Run(), 1);
  EXPECT_EQ(f.dropped, 0);
}

TEST(Verify, DropsAWeakerCopyOfAPersonFromOtherViews) {
  // Person a seen by all five cameras, merged twice: from views 0-2 and from views 3-4 (whose
  // pairs with views 0-2 did not survive), 0.1 m apart. The copy from fewer views goes, whichever
  // comes first.
  const auto a = test::StandingPerson(0, 0);
  const Candidate strong{a, 0, {{0, 1}, {1, 2}}}, weak{Shifted(a, 0.1), 0, {{3, 4}}};
  for (const bool weak_first : {false, true}) {
    VerifyFixture f({a}, weak_first ? std::vector<Candidate>{weak, strong} : std::vector<Candidate>{strong, weak});
    ASSERT_EQ(f.Run(), 1) << weak_first;
    EXPECT_EQ(f.duplicates, 1);
    EXPECT_EQ(f.dropped, 0);
    EXPECT_LT((f.persons.Person(0) - a).norm(), 1e-12) << "the copy from three views is kept";
  }
}

TEST(Verify, ADuplicateIsWithinTheDistanceAndSharesNoView) {
  const auto a = test::StandingPerson(0, 0);
  const auto run = [&](double dx, std::vector<std::pair<int, int>> weak_pairs, double distance = 0.25) {
    VerifyFixture f({a}, {{a, 0, {{0, 1}, {1, 2}}}, {Shifted(a, dx), 0, std::move(weak_pairs)}});
    VerifyOptions options;
    options.duplicate_distance_m = distance;
    f.Run(options);
    return f.duplicates;
  };
  // A pure shift moves every joint by dx: the mean joint distance is dx.
  EXPECT_EQ(run(0.24, {{3, 4}}), 1);
  EXPECT_EQ(run(0.26, {{3, 4}}), 0) << "farther than duplicate_distance_m: another person";
  EXPECT_EQ(run(0.24, {{3, 4}}, 0.2), 0) << "the option sets the distance";
  EXPECT_EQ(run(0.1, {{2, 3}}), 0) << "view 2 holds a pose of each: two people to that camera";
  EXPECT_EQ(run(0.1, {{3, 4}}, 0.0), 0) << "0 turns the check off";
  // Joints missing in the copy (confidence 0, left anywhere) are not compared.
  auto partial = Shifted(a, 0.1);
  partial.rightCols(8).row(3).setZero();
  partial.rightCols(8).topRows(3).array() += 5.0;
  VerifyFixture f({a}, {{a, 0, {{0, 1}, {1, 2}}}, {partial, 0, {{3, 4}}}});
  f.Run();
  EXPECT_EQ(f.duplicates, 1);
}

TEST(Verify, TheStrongerOfTwoDuplicatesHasMoreViewsThenMorePairs) {
  // Six cameras: the first person from views 0-2 in two pairs, the second from views 3-5 in three.
  const auto a = test::StandingPerson(0, 0);
  VerifyFixture f({a}, {{a, 0, {{0, 1}, {1, 2}}}, {Shifted(a, 0.1), 0, {{3, 4}, {4, 5}, {3, 5}}}}, 6);
  ASSERT_EQ(f.Run(), 1);
  EXPECT_EQ(f.duplicates, 1);
  EXPECT_LT((f.persons.Person(0) - Shifted(a, 0.1)).norm(), 1e-12) << "three pairs beat two";
  // Equal views and pairs: the earlier person stays.
  VerifyFixture tie({a}, {{Shifted(a, 0.1), 0, {{0, 1}}}, {a, 0, {{2, 3}}}});
  ASSERT_EQ(tie.Run(), 1);
  EXPECT_LT((tie.persons.Person(0) - Shifted(a, 0.1)).norm(), 1e-12);
}

TEST(Verify, APersonIsComparedWithTheKeptPersonsOnly) {
  // b duplicates a (0.2 m), c duplicates b (0.2 m) but not a (0.4 m): b goes, c stays, as does a.
  const auto a = test::StandingPerson(0, 0);
  const auto b = Shifted(a, 0.2), c = Shifted(a, 0.4);
  VerifyFixture f({a, c}, {{a, 0, {{0, 1}, {1, 2}}}, {b, 0, {{3, 4}}}, {c, 1, {{5, 6}}}}, 7);
  ASSERT_EQ(f.Run(), 2);
  EXPECT_EQ(f.duplicates, 1);
  EXPECT_LT((f.persons.Person(0) - a).norm(), 1e-12);
  EXPECT_LT((f.persons.Person(1) - c).norm(), 1e-12);
}

// A part of `whole`: its right elbow and wrist (joints 8, 10) moved `near_dx` along x, its knee and
// ankles (14-16) moved `far_dx`, no other joint (score 0).
Eigen::Matrix4Xd PartOf(const Eigen::Matrix4Xd& whole, double near_dx, double far_dx) {
  Eigen::Matrix4Xd part = Shifted(whole, far_dx);
  part.row(3).setZero();
  for (const int j : {14, 15, 16}) part(3, j) = 1;
  for (const int j : {8, 10}) {
    part.col(j) = whole.col(j);
    part(0, j) += near_dx;
    part(3, j) = 1;
  }
  return part;
}

TEST(Verify, APersonWithFewerJointsTwoOfThemOnAnothersIsAPartOfIt) {
  // Person a from views 0-2; a second person from views 1 and 3 (sharing view 1, so it is not a
  // duplicate) holding a's right arm and legs 0.6 m away: a's body split into two groups. The
  // phantom check is off (min_empty_views 100): only the part rule can drop it.
  const auto a = test::StandingPerson(0, 0);
  const auto run = [&](const Eigen::Matrix4Xd& other, bool other_first, double distance = 0.15) {
    const Candidate whole{a, 0, {{0, 1}, {1, 2}}}, second{other, 0, {{1, 3}}};
    VerifyFixture f({a}, other_first ? std::vector<Candidate>{second, whole} : std::vector<Candidate>{whole, second});
    VerifyOptions options;
    options.min_empty_views = 100;
    options.part_distance_m = distance;
    const int kept = f.Run(options);
    EXPECT_EQ(f.dropped, 0);
    if (kept == 1) {
      EXPECT_LT((f.persons.Person(0) - a).norm(), 1e-12) << "the whole person is kept";
    }
    EXPECT_EQ(kept + f.duplicates, 2);
    return f.duplicates;
  };
  for (const bool other_first : {false, true}) {
    SCOPED_TRACE(other_first);
    EXPECT_EQ(run(PartOf(a, 0.14, 0.6), other_first), 1) << "5 joints, 2 of them within 0.15 m of a's";
    EXPECT_EQ(run(PartOf(a, 0.16, 0.6), other_first), 0) << "farther than part_distance_m";
    EXPECT_EQ(run(PartOf(a, 0.16, 0.6), other_first, 0.17), 1) << "the option sets the distance";
    EXPECT_EQ(run(PartOf(a, 0.14, 0.6), other_first, 0.0), 0) << "0 turns the check off";
    auto one_near = PartOf(a, 0.14, 0.6);
    one_near(0, 8) += 0.1;  // the elbow 0.24 m off: one joint on a's is not enough
    EXPECT_EQ(run(one_near, other_first), 0);
    // As many joints as a (every other joint 0.6 m off): not fewer, so not a part of a.
    auto full = Shifted(a, 0.6);
    for (const int j : {8, 10}) full(0, j) = a(0, j) + 0.14;
    EXPECT_EQ(run(full, other_first), 0);
  }
}

}  // namespace
}  // namespace rpt
