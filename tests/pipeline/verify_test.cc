// SPDX-License-Identifier: MIT
// Steps 11b and 12b on hand-made geometry: re-scoring persons against all views (verify.h) and
// lifting persons seen by one view (single_view.h), both judged by the other views
// (view_verdict.h).
#include <gtest/gtest.h>

#include <vector>

#include "core/joints.h"
#include "core/pipeline/single_view.h"
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

// A person detected by camera 0 of `num_cameras` ring cameras only, standing in plain view of the
// others, which detect nobody: step 12b with `options` (enabled) lifts it or not.
struct OneViewFixture {
  explicit OneViewFixture(int num_cameras) : cameras(test::RingCameras(num_cameras)) {
    std::vector<Poses2D> views = test::ProjectPersons(cameras, {person});
    for (size_t v = 1; v < views.size(); ++v) views[v].Clear(17);
    test::UndistortCocoViews(cameras, views, &geometry, &core, &prepared);
    kernel.scale_m = 0.05;
    found.Clear(17);
    options.enabled = true;
  }
  // The number of persons lifted.
  int Run() {
    const steps::SingleViewInput input{.views = prepared,
                                       .geometry = geometry,
                                       .core_joints = core,
                                       .limbs = limbs,
                                       .ground = ground,
                                       .room = no_room,
                                       .proposals = no_proposals,
                                       .groups = no_groups,
                                       .kernel = kernel,
                                       .found = found};
    return steps::SingleView(options, input, &scratch, &lifted, &stats);
  }

  const Eigen::Matrix4Xd person = test::StandingPerson(0.5, 0.2);
  std::vector<Camera> cameras;
  std::vector<ViewGeometry> geometry;
  std::vector<int> core;
  PreparedViews prepared;
  const std::vector<TypicalLimb> limbs = ResolveTypicalLimbs(CocoBodyJoints());
  const GroundJoints ground = ResolveGroundJoints(CocoBodyJoints());
  const Room no_room;
  const Proposals no_proposals;
  const Groups no_groups;
  ScoreKernel kernel;
  Poses3D found;
  SingleViewOptions options;
  SingleViewScratch scratch;
  Poses3D lifted;
  FrameStats stats;
};

TEST(SingleView, LiftsAPoseOnlyWhenTheOtherViewsDoNotSeeAnEmptySpot) {
  // Four empty views contradict the pose. With single_view.min_empty_views above four they do
  // not, and the pose is lifted to about the person's place.
  OneViewFixture f(5);
  EXPECT_EQ(f.Run(), 0) << "four empty views";
  f.options.min_empty_views = 5;
  ASSERT_EQ(f.Run(), 1);
  EXPECT_EQ(f.stats.single_view_persons, 1);
  const Eigen::Vector3d hips = 0.5 * (f.lifted.Person(0).col(11) + f.lifted.Person(0).col(12)).head<3>();
  EXPECT_LT((hips - 0.5 * (f.person.col(11) + f.person.col(12)).head<3>()).norm(), 0.5);
}

TEST(SingleView, MinEmptyViewsCountsTheEmptyViewsAlone) {
  // Two cameras: the one other view is empty. Under the default (two empty views) that does not
  // veto; with min_empty_views = 1 a single empty view does.
  OneViewFixture f(2);
  EXPECT_EQ(f.Run(), 1) << "one empty view, two needed";
  f.options.min_empty_views = 1;
  EXPECT_EQ(f.Run(), 0) << "one empty view, one needed";
}

}  // namespace
}  // namespace rpt
