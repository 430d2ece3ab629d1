// SPDX-License-Identifier: MIT
// Google Benchmark: the greedy PAF association (datasets/readers/openpose_paf_association.h) on the
// real OpenPose candidates of the 4D-Association Shelf bundle, before (bench/
// baseline_paf_association.h, allocating) and after (PafAssociator, buffers reused) in the same
// run. One iteration groups one whole frame: the candidates of its 5 views, frames cycling
// through all 301 (the candidates mostly not in cache, as when a reader converts frames parsed
// before), or through RPT_PAF_FRAMES frames spread evenly over them (e.g. 8: in cache, as
// candidates fresh from a detector). RPT_PAF_ITERATIONS=N runs every benchmark exactly N
// iterations (frames), for instruction counts under valgrind --tool=callgrind that do not depend
// on the timer. The bundle folder is the first argument (default
// ../shared/data/shelf/4d_association); without it the benchmark says so and exits 0.
//
//   taskset -c 1 ./build/bench/rpt_paf_benchmark ../shared/data/shelf/4d_association
//       --benchmark_repetitions=9 --benchmark_report_aggregates_only=true
//       [--benchmark_enable_random_interleaving=true: on a shared machine, load changes hit both]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/baseline_paf_association.h"
#include "datasets/input_warnings.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/openpose_paf_association.h"

namespace rpt::bench {
namespace {

// frames[f][c]: the candidates of camera c in frame f.
std::vector<std::vector<PafCandidates>>& Frames() {
  static std::vector<std::vector<PafCandidates>> frames;
  return frames;
}

// The same candidates packed in one store, frame by frame (image f * 5 + c), as the shelf-4da
// reader keeps them.
PafCandidateStore& PackedFrames() {
  static PafCandidateStore frames;
  return frames;
}

void BM_PafBaseline(benchmark::State& state) {
  const auto& frames = Frames();
  const PafAssociationOptions options;
  size_t f = 0;
  long persons = 0;
  for (auto _ : state) {
    for (const PafCandidates& view : frames[f]) {
      const std::vector<PafPerson> out = AssociatePafsBaseline(Body25PafSkeleton(), view, options);
      persons += static_cast<long>(out.size());
      benchmark::DoNotOptimize(out.data());
    }
    f = f + 1 == frames.size() ? 0 : f + 1;
  }
  state.counters["persons_per_frame"] = benchmark::Counter(static_cast<double>(persons), benchmark::Counter::kAvgIterations);
}

// PafAssociator on the candidates as parsed (one block per joint and limb; it packs them first).
void BM_PafAssociatorUnpacked(benchmark::State& state) {
  const auto& frames = Frames();
  const PafAssociationOptions options;
  PafAssociator associator;
  PafPersons out;
  size_t f = 0;
  long persons = 0;
  for (auto _ : state) {
    for (const PafCandidates& view : frames[f]) {
      associator.Run(Body25PafSkeleton(), view, options, &out);
      persons += out.size();
      benchmark::DoNotOptimize(out.candidate.data());
    }
    f = f + 1 == frames.size() ? 0 : f + 1;
  }
  state.counters["persons_per_frame"] = benchmark::Counter(static_cast<double>(persons), benchmark::Counter::kAvgIterations);
}

// PafAssociator on packed candidates: what the shelf-4da reader runs.
void BM_PafAssociator(benchmark::State& state) {
  const PafCandidateStore& images = PackedFrames();
  const size_t views = Frames()[0].size();
  const PafAssociationOptions options;
  PafAssociator associator;
  PafPersons out;
  size_t i = 0;
  long persons = 0;
  for (auto _ : state) {
    for (size_t c = 0; c < views; ++c) {
      associator.Run(Body25PafSkeleton(), images[i++], options, &out);
      persons += out.size();
      benchmark::DoNotOptimize(out.candidate.data());
    }
    if (i == images.size()) i = 0;
  }
  state.counters["persons_per_frame"] = benchmark::Counter(static_cast<double>(persons), benchmark::Counter::kAvgIterations);
}

}  // namespace
}  // namespace rpt::bench

int main(int argc, char** argv) {
  std::filesystem::path root = "../shared/data/shelf/4d_association";
  if (argc > 1 && argv[1][0] != '-') {
    root = argv[1];
    for (int i = 1; i + 1 < argc; ++i) argv[i] = argv[i + 1];
    --argc;
  }
  if (!std::filesystem::exists(root / "detection" / "0.txt")) {
    std::printf("skipped: no 4D-Association Shelf bundle at %s (give its folder as the first argument)\n",
                root.string().c_str());
    return 0;
  }
  auto& frames = rpt::bench::Frames();
  for (int c = 0; c < 5; ++c) {
    rpt::InputWarnings warnings;
    const rpt::FourDaDetections d = rpt::ReadFourDaDetections(root / "detection" / (std::to_string(c) + ".txt"), &warnings);
    frames.resize(d.frames.size());
    for (size_t f = 0; f < d.frames.size(); ++f) frames[f].push_back(d.frames[f]);
  }
  if (const char* n = std::getenv("RPT_PAF_FRAMES")) {  // n frames spread over the sequence
    const size_t keep = std::clamp<size_t>(std::strtoul(n, nullptr, 10), 1, frames.size());
    std::vector<std::vector<rpt::PafCandidates>> spread;
    for (size_t i = 0; i < keep; ++i) spread.push_back(frames[i * frames.size() / keep]);
    frames = std::move(spread);
  }
  for (const auto& frame : frames) {
    for (const rpt::PafCandidates& view : frame) rpt::bench::PackedFrames().Append(rpt::Body25PafSkeleton(), view);
  }
  std::vector<benchmark::internal::Benchmark*> benchmarks = {
      benchmark::RegisterBenchmark("paf_association/before_baseline", rpt::bench::BM_PafBaseline),
      benchmark::RegisterBenchmark("paf_association/after_PafAssociator_packed", rpt::bench::BM_PafAssociator),
      benchmark::RegisterBenchmark("paf_association/after_PafAssociator_unpacked",
                                   rpt::bench::BM_PafAssociatorUnpacked)};
  for (benchmark::internal::Benchmark* b : benchmarks) {
    b->Unit(benchmark::kMicrosecond);
    if (const char* n = std::getenv("RPT_PAF_ITERATIONS"))
      b->Iterations(static_cast<benchmark::IterationCount>(std::strtoul(n, nullptr, 10)));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
