// SPDX-License-Identifier: MIT
// The benchmark scenes, shared by `rpt bench` and the Google Benchmark executables, so both
// measure exactly the same inputs.
#pragma once

#include <string>
#include <vector>

#include "datasets/sequence.h"

namespace rpt::bench {

struct BenchScene {
  std::string name;         // e.g. "shelf-like"
  std::string description;  // one line
  int cameras = 5;
  int people = 4;
  bool whole_body = false;
  int frames = 300;
  double target_us = 0;     // frame-time target (median, one thread), 0 = none
};

// shelf-like, whole-body, panoptic-like, few-views.
const std::vector<BenchScene>& StandardScenes();
// Scaling series: cameras 2..31 with 4 people; people 1..20 with 5 cameras.
std::vector<BenchScene> ScalingScenes();

// The frame-time target of a dataset's real frames (`rpt bench --dataset NAME`), in us per frame
// including the reader's grouping of raw candidates where it has one; 0 = none.
double DatasetTargetUs(const std::string& dataset);

// The scene with simulated detections (seeded, deterministic). The default detector profile is
// "clean", the model results/bench.md was measured with: a speed benchmark needs a workload that
// stays the same across commits (the fitted "realistic" profile reports fewer persons and joints).
Sequence MakeBenchSequence(const BenchScene& scene, uint64_t seed = 1, const std::string& detector = "clean");

}  // namespace rpt::bench
