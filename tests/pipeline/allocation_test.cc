// SPDX-License-Identifier: MIT
// A warm Triangulator performs no heap allocation per frame (counting operator new), also with
// the optional temporal steps (bone_lengths, causal smoothing) enabled, and neither does a warm
// OfflineSmoother.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/pipeline/offline_smoother.h"
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"
#include "tests/allocation_counting.h"

namespace rpt {
namespace {

long CountAllocations(Triangulator& tri, const std::vector<std::vector<Poses2D>>& frames, double fps, Poses3D* persons,
                      FrameStats* stats) {
  g_allocations = 0;
  g_counting = true;
  for (size_t f = 0; f < frames.size(); ++f) tri.Process(frames[f], f / fps, persons, stats);
  g_counting = false;
  return g_allocations.load();
}

// single_view: 0 off, 1 the limb-length depth, 2 the ground prior and track assistance.
void CheckNoAllocationOnceWarm(bool whole_body, int cameras, int people, bool temporal = false, bool robust = false,
                               int single_view = 0) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = cameras;
  options.num_people = people;
  options.whole_body = whole_body;
  options.num_frames = 80;
  options.seed = 3;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 3);
  std::vector<std::vector<Poses2D>> frames(options.num_frames);
  for (int f = 0; f < options.num_frames; ++f) detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &frames[f]);

  TriangulatorOptions tri_options;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  if (temporal) {
    tri_options.bone_lengths.enabled = true;
    tri_options.smooth.mode = SmoothMode::kCausal;
  }
  tri_options.triangulate.robust_views = robust;
  tri_options.single_view.enabled = single_view > 0;
  tri_options.single_view.ground_prior = single_view == 2;
  tri_options.single_view.track_assist = single_view == 2;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  Poses3D persons;
  FrameStats stats;
  const long warmup = CountAllocations(tri, frames, scene.fps, &persons, &stats);
  EXPECT_GT(warmup, 0) << "the counter must see the warm-up allocations";
  tri.Reset();
  EXPECT_EQ(CountAllocations(tri, frames, scene.fps, &persons, &stats), 0);
}

TEST(Allocation, WarmTriangulatorDoesNotAllocateBody) { CheckNoAllocationOnceWarm(false, 5, 4); }
TEST(Allocation, WarmTriangulatorDoesNotAllocateWholeBody) { CheckNoAllocationOnceWarm(true, 5, 2); }
TEST(Allocation, WarmTriangulatorDoesNotAllocateManyCameras) { CheckNoAllocationOnceWarm(false, 12, 8); }
TEST(Allocation, WarmTriangulatorWithTemporalStepsDoesNotAllocateBody) { CheckNoAllocationOnceWarm(false, 5, 4, true); }
TEST(Allocation, WarmTriangulatorWithTemporalStepsDoesNotAllocateWholeBody) {
  CheckNoAllocationOnceWarm(true, 5, 2, true);
}
TEST(Allocation, WarmTriangulatorWithRobustViewsDoesNotAllocate) {
  CheckNoAllocationOnceWarm(false, 12, 8, false, true);
  CheckNoAllocationOnceWarm(true, 5, 2, false, true);
}
TEST(Allocation, WarmTriangulatorWithSingleViewDoesNotAllocate) {
  // Three cameras and six people: persons seen by one camera only occur.
  CheckNoAllocationOnceWarm(false, 3, 6, false, false, 1);
  CheckNoAllocationOnceWarm(false, 3, 6, false, false, 2);
}

// Smooths a sequence streamed through `smoother` (a whole sequence, then Flush), counting the
// allocations.
long CountSmootherAllocations(OfflineSmoother* smoother, const std::vector<Poses3D>& frames, double fps,
                              Poses3D* persons, FrameStats* stats) {
  g_allocations = 0;
  g_counting = true;
  int handed_back = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    smoother->Push(f / fps, frames[f], frames[f].num_persons(), FrameStats{});
    while (smoother->Pop(persons, stats)) ++handed_back;
  }
  smoother->Flush();
  while (smoother->Pop(persons, stats)) ++handed_back;
  g_counting = false;
  EXPECT_EQ(handed_back, static_cast<int>(frames.size()));
  return g_allocations.load();
}

TEST(Allocation, WarmOfflineSmootherDoesNotAllocate) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = 5;
  options.num_people = 4;
  options.num_frames = 80;
  options.seed = 3;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 3);
  TriangulatorOptions tri_options;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  tri_options.smooth.mode = SmoothMode::kOffline;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  std::vector<Poses3D> frames(options.num_frames);
  std::vector<Poses2D> views;
  FrameStats stats;
  for (int f = 0; f < options.num_frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views);
    tri.Process(views, f / scene.fps, &frames[f], &stats);
  }
  OfflineSmoother smoother(tri_options.smooth, tri_options.track.max_gap_s, tri_options.UnobservedScore());
  Poses3D persons;
  EXPECT_GT(CountSmootherAllocations(&smoother, frames, scene.fps, &persons, &stats), 0)
      << "the counter must see the warm-up allocations";
  EXPECT_EQ(CountSmootherAllocations(&smoother, frames, scene.fps, &persons, &stats), 0);
}

}  // namespace
}  // namespace rpt
