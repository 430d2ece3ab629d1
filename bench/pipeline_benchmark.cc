// SPDX-License-Identifier: MIT
// Google Benchmark: whole frames of the benchmark scenes (bench_scenes.h) and the scaling series,
// one thread. Each iteration triangulates the next frame of the scene (cycling); counters report
// the mean time of every pipeline step over the run and the accuracy of the same run (MPJPE in mm
// over matched persons), so a speed-up that costs accuracy is visible.
//
//   ./build/bench/rpt_benchmarks --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <memory>
#include <string>

#include "bench/bench_scenes.h"
#include "engine/run.h"
#include "core/pipeline/triangulator.h"

namespace rpt::bench {
namespace {

struct Prepared {
  Sequence sequence;
  std::unique_ptr<Triangulator> triangulator;
};

// Scenes are generated once per process.
Prepared& Get(const BenchScene& scene) {
  static std::map<std::string, Prepared> cache;
  auto it = cache.find(scene.name);
  if (it == cache.end()) {
    Prepared p;
    p.sequence = MakeBenchSequence(scene);
    p.triangulator = std::make_unique<Triangulator>(p.sequence.cameras, p.sequence.detection_joints,
                                                    engine::TriangulatorOptionsFor({}, p.sequence));
    it = cache.emplace(scene.name, std::move(p)).first;
  }
  return it->second;
}

// Mean distance (m) of each GT person to its nearest prediction over shared joints; summed.
double NearestError(const Poses3D& gt, const JointNames& gt_names, const Poses3D& pred, const JointNames& pred_names,
                    int* persons) {
  double total = 0;
  for (int g = 0; g < gt.num_persons(); ++g) {
    double best = 1e9;
    for (int p = 0; p < pred.num_persons(); ++p) {
      double sum = 0;
      int n = 0;
      for (size_t j = 0; j < gt_names.size(); ++j) {
        const int k = FindJoint(pred_names, gt_names[j]);
        if (k < 0 || pred.Person(p)(3, k) <= 0) continue;
        sum += (gt.Person(g).col(j).head<3>() - pred.Person(p).col(k).head<3>()).norm();
        ++n;
      }
      if (n > 0) best = std::min(best, sum / n);
    }
    if (best < 0.5) {
      total += best;
      ++*persons;
    }
  }
  return total;
}

void BM_Frame(benchmark::State& state, BenchScene scene) {
  Prepared& p = Get(scene);
  const auto& frames = p.sequence.frames;
  Poses3D persons;
  FrameStats stats;
  // Warm up: one pass so buffers reach their size.
  p.triangulator->Reset();
  for (const auto& f : frames) p.triangulator->Process(f.views, f.timestamp_s, &persons, &stats);
  p.triangulator->Reset();
  std::array<double, kNumSteps> step_sum{};
  double error_sum = 0;
  int matched = 0;
  size_t f = 0;
  for (auto _ : state) {
    const SequenceFrame& frame = frames[f];
    p.triangulator->Process(frame.views, frame.timestamp_s, &persons, &stats);
    benchmark::DoNotOptimize(persons.data.data());
    state.PauseTiming();
    for (int s = 0; s < kNumSteps; ++s) step_sum[s] += stats.time_us[s];
    error_sum += NearestError(frame.gt, p.sequence.gt_joints, persons, p.triangulator->output_joints(), &matched);
    if (++f == frames.size()) {
      f = 0;
      p.triangulator->Reset();
    }
    state.ResumeTiming();
  }
  const double iterations = static_cast<double>(state.iterations());
  for (int s = 0; s < kNumSteps; ++s) state.counters[std::string(kSteps[s].key) + "_us"] = step_sum[s] / iterations;
  state.counters["mpjpe_mm"] = matched > 0 ? 1000.0 * error_sum / matched : 0.0;
  state.counters["frames_per_s"] = benchmark::Counter(iterations, benchmark::Counter::kIsRate);
}

int RegisterAll() {
  for (const BenchScene& scene : StandardScenes()) {
    benchmark::RegisterBenchmark(("Frame/" + scene.name).c_str(), BM_Frame, scene)->Unit(benchmark::kMicrosecond);
  }
  for (const BenchScene& scene : ScalingScenes()) {
    benchmark::RegisterBenchmark(("Scaling/" + scene.name).c_str(), BM_Frame, scene)->Unit(benchmark::kMicrosecond);
  }
  return 0;
}
const int registered = RegisterAll();

}  // namespace
}  // namespace rpt::bench
