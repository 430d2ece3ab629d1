// SPDX-License-Identifier: MIT
#include "bench/bench_scenes.h"

#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/synthetic_sequence.h"

namespace rpt::bench {

// The targets are the current speed goals (one thread, median per frame on the 2-core CI machine):
// shelf-like 25 us, whole body 60 us, 31 cameras x 8 people 0.5 ms.
const std::vector<BenchScene>& StandardScenes() {
  static const std::vector<BenchScene> scenes = {
      {"shelf-like", "5 cameras, 4 people, 17 joints, pixel noise and false positives", 5, 4, false, 300, 25},
      {"whole-body", "5 cameras, 2 people, 133 joints", 5, 2, true, 200, 60},
      {"panoptic-like", "31 cameras, 8 people, 17 joints", 31, 8, false, 60, 500},
      {"few-views", "3 cameras, 6 people, 17 joints", 3, 6, false, 300, 0},
  };
  return scenes;
}

std::vector<BenchScene> ScalingScenes() {
  std::vector<BenchScene> scenes;
  for (int cameras : {2, 3, 5, 8, 12, 16, 24, 31}) {
    scenes.push_back({"cameras-" + std::to_string(cameras), "4 people", cameras, 4, false, 60, 0});
  }
  for (int people : {1, 2, 4, 8, 12, 16, 20}) {
    scenes.push_back({"people-" + std::to_string(people), "5 cameras", 5, people, false, 60, 0});
  }
  return scenes;
}

// The real Shelf frames of the 4D-Association bundle: 30 us with the part-affinity grouping of
// their OpenPose candidates (the goal of the same issue as the scenes' targets).
double DatasetTargetUs(const std::string& dataset) { return dataset == "shelf-4da" ? 30 : 0; }

Sequence MakeBenchSequence(const BenchScene& scene, uint64_t seed, const std::string& detector) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = scene.cameras;
  options.num_people = scene.people;
  options.whole_body = scene.whole_body;
  options.num_frames = scene.frames;
  options.seed = seed;
  if (scene.people > 12) {
    options.room_size_m = Eigen::Vector3d(12, 12, 3);  // room for a crowd to walk
    options.rig.radius_m = 7.5;
  }
  const synthetic::Scene generated = synthetic::GenerateScene(options);
  return synthetic::MakeSyntheticSequence(generated, synthetic::DetectorProfile(detector), seed, scene.name);
}

}  // namespace rpt::bench
