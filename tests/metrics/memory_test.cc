// SPDX-License-Identifier: MIT
// The accumulators' memory is flat in frames: feeding 3 800 more frames grows the live heap (counted
// by a replaced global operator new) by less than 16 bytes per frame, plus, for the metrics, the
// 24-byte entry that average precision keeps per counted prediction (its score, error and
// true-positive flags; AP ranks all of them at the end). Eigen's dynamic arrays are allocated with
// malloc, not counted here: the accumulators keep none beyond the frame being added.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "metrics/accumulator.h"
#include "metrics/step_counts.h"
#include "metrics/timing.h"
#include "tests/metrics/random_frames.h"

namespace {
// Live bytes allocated through operator new: each block carries its size in a 16-byte header.
std::atomic<long> g_live_bytes{0};
constexpr std::size_t kHeader = 16;
}  // namespace

// These replacements pair operator new with std::malloc and operator delete with std::free, as
// they should; GCC, once it inlines them (-O1 and above), reports every delete as mismatched.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  void* block = std::malloc(size + kHeader);
  if (block == nullptr) throw std::bad_alloc();
  std::memcpy(block, &size, sizeof(size));
  g_live_bytes.fetch_add(static_cast<long>(size), std::memory_order_relaxed);
  return static_cast<char*>(block) + kHeader;
}
void* operator new[](std::size_t size) { return operator new(size); }
// The nothrow forms too (std::stable_sort's temporary buffer uses them): they are freed by the
// operator delete below, which reads the header. Under ASan an unreplaced form is ASan's own.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return operator new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  void* block = static_cast<char*>(p) - kHeader;
  std::size_t size;
  std::memcpy(&size, block, sizeof(size));
  g_live_bytes.fetch_sub(static_cast<long>(size), std::memory_order_relaxed);
  std::free(block);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { operator delete(p); }

namespace rpt::metrics {
namespace {

struct FedFrames {
  long frames = 0;
  long counted_predictions = 0;
};

void Feed(test::RandomFrames* source, int num_frames, MetricsAccumulator* accumulator, FedFrames* run) {
  for (int f = 0; f < num_frames; ++f) {
    const test::RandomFrame frame = source->Next();
    accumulator->Add(frame.id, frame.gt, *frame.gt_names, frame.pred, *frame.pred_names, frame.scores);
    ++run->frames;
    run->counted_predictions += frame.pred.num_persons();  // count_preds_without_gt: all are counted
  }
}

TEST(Memory, MetricsAccumulatorGrowsOnlyByTheApEntryPerPredictionAndAFrameIdHash) {
  EvalOptions options;
  options.legacy_pcp = LegacyPcpLayout::kShelf;
  for (const MatchingMode matching : {MatchingMode::kGreedy, MatchingMode::kHungarian}) {
    options.matching = matching;
    test::RandomFrames source(11, /*wholebody=*/true, /*person_scores=*/false);
    MetricsAccumulator accumulator(options);
    FedFrames before, after;
    Feed(&source, 200, &accumulator, &before);
    const long live_200 = g_live_bytes.load();
    Feed(&source, 3800, &accumulator, &after);
    const long live_4000 = g_live_bytes.load();
    const double per_frame = static_cast<double>(live_4000 - live_200) / after.frames;
    const double predictions_per_frame = static_cast<double>(after.counted_predictions) / after.frames;
    std::printf("MetricsAccumulator (%s): %.1f bytes per frame with %.2f counted predictions per frame\n",
                matching == MatchingMode::kGreedy ? "greedy" : "hungarian", per_frame, predictions_per_frame);
    EXPECT_LT(per_frame, 16.0 + 24.0 * predictions_per_frame);
    EXPECT_GT(accumulator.Finalize().num_matches, 1000) << "the frames must be matched, not ignored";
  }
}

TEST(Memory, TimingAndStepCountAccumulatorsDoNotGrow) {
  TimingAccumulator timing;
  StepCountAccumulator counts;
  std::uint64_t state = 5;
  auto unit = [&state] {  // xorshift64*, [0, 1)
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return static_cast<double>((state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
  };
  auto feed = [&](int num_frames) {
    for (int f = 0; f < num_frames; ++f) {
      FrameStats stats;
      for (int s = 0; s < kNumSteps; ++s) stats.time_us[s] = s % 3 == 0 ? 0.0 : std::exp(std::log(5.0) + 7.0 * unit());
      stats.total_us = 100.0 + 1e4 * unit();
      stats.noise_m = f % 2 == 0 ? 0.0 : 0.002 + 0.05 * unit();
      stats.count[0] = f % 7;
      timing.Add(stats);
      counts.Add(stats);
    }
  };
  feed(200);
  const long live_200 = g_live_bytes.load();
  feed(3800);
  const long live_4000 = g_live_bytes.load();
  const double per_frame = static_cast<double>(live_4000 - live_200) / 3800;
  std::printf("TimingAccumulator + StepCountAccumulator: %.1f bytes per frame\n", per_frame);
  EXPECT_LT(per_frame, 1.0);
  EXPECT_EQ(timing.Finalize().frames, 4000);
  EXPECT_EQ(counts.Finalize().noise_frames, 2000);
}

}  // namespace
}  // namespace rpt::metrics
