// SPDX-License-Identifier: MIT
// Step 11b on hand-made geometry: re-scoring persons against all views (verify.h), judged by the
// other views (view_verdict.h). Step 12b's use of the same verdict: single_view_test.cc.
#include <gtest/gtest.h>

#include <vector>

#include "core/pipeline/undistort.h"
#include "core/pipeline/verify.h"
#include "core/pipeline/view_geometry.h"
#include "tests/pipeline/test_scene.h"

namespace rpt {
namespace {

// Five ring cameras see `detected`; the persons to verify are `candidates`, each merged from the
// pair (view 0, view 1) of pose `source` (an index into `detected`).
struct VerifyFixture {
  VerifyFixture(std::vector<Eigen::Matrix4Xd> detected, std::vector<std::pair<Eigen::Matrix4Xd, int>> candidates)
      : cameras(test::RingCameras(5)) {
    test::UndistortCocoViews(cameras, test::ProjectPersons(cameras, detected), &geometry, &core, &prepared);
    persons.Clear(17);
    proposals.Clear(17);
    groups.begin = {0};
    for (const auto& [body, source] : candidates) {
      persons.AddPerson() = body;
      // Pose `source` in view 0 and in view 1 (every detected person is seen by every camera here).
      proposals.Add(PosePair{prepared.view_begin[0] + source, prepared.view_begin[1] + source});
      groups.members.push_back(proposals.size() - 1);
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
};

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

TEST(Verify, AnOccludedPersonIsNotAPhantom) {
  // The candidate stands where another detected person (c) covers it in the other views: those
  // views are occupied, not empty, so it is kept even though no pose there agrees with it.
  const auto a = test::StandingPerson(-1.5, 0), c = test::StandingPerson(1.0, 0.0);
  const auto hidden = test::StandingPerson(1.0, 0.25);
  VerifyFixture f({a, c}, {{hidden, 0}});
  EXPECT_EQ(f.Run(), 1);
  EXPECT_EQ(f.dropped, 0);
}

}  // namespace
}  // namespace rpt
