// SPDX-License-Identifier: MIT
// The stages of one sequence on several threads (engine/frame_pipeline.h): every stage sees the
// frames in order, one at a time, whatever the thread count; the ring bounds the frames in flight
// and grows only when held-back frames fill it; an error stops the run cleanly with the error a
// single thread would have met first.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/frame_pipeline.h"
#include "tests/allocation_counting.h"

namespace rpt::engine {
namespace {

// A pipeline over `frames` numbered frames whose slots hold the frame number: process doubles it,
// emit records it. Each stage checks it runs alone and in order; the slots check that no frame
// is overwritten before it was emitted.
struct Recorder {
  long frames = 0;
  long capacity = 1;
  std::vector<long> slots;       // frame number (read), then 2 x it (processed)
  std::vector<long> emitted;     // what emit found in the slot, in emit order
  std::vector<long> read_order, process_order;
  std::atomic<int> in_stage[3] = {0, 0, 0};
  std::atomic<bool> overlap{false};
  long max_in_flight = 0;
  std::atomic<long> reads{0}, emits{0};

  FrameStages Stages() {
    slots.assign(static_cast<size_t>(capacity), -1);
    FrameStages s;
    s.read = [this](long f) {
      Enter(0);
      const bool more = f < frames;
      if (more) {
        read_order.push_back(f);
        slots[static_cast<size_t>(f % capacity)] = f;
        max_in_flight = std::max(max_in_flight, ++reads - emits);
      }
      Leave(0);
      return more;
    };
    s.process = [this](long f) -> long {
      Enter(1);
      process_order.push_back(f);
      slots[static_cast<size_t>(f % capacity)] *= 2;
      Leave(1);
      return 1;
    };
    s.emit = [this](long f) {
      Enter(2);
      emitted.push_back(slots[static_cast<size_t>(f % capacity)]);
      ++emits;
      Leave(2);
    };
    return s;
  }
  void Enter(int stage) {
    if (in_stage[stage]++ != 0) overlap = true;
    std::this_thread::yield();  // let the other stages interleave
  }
  void Leave(int stage) { --in_stage[stage]; }
};

std::vector<long> Doubled(long frames) {
  std::vector<long> v;
  for (long f = 0; f < frames; ++f) v.push_back(2 * f);
  return v;
}

TEST(FramePipelineTest, EveryStageSeesTheFramesInOrderWhateverTheThreads) {
  for (const int threads : {1, 2, 3, 4}) {
    for (const long capacity : {1L, 2L, 16L}) {
      Recorder r;
      r.frames = 2000;
      r.capacity = capacity;
      RunFramePipeline(r.Stages(), threads, capacity);
      EXPECT_FALSE(r.overlap) << "a stage ran on two threads at once";
      ASSERT_EQ(r.emitted.size(), 2000u) << threads << " threads, ring " << capacity;
      EXPECT_EQ(r.emitted, Doubled(2000)) << threads << " threads, ring " << capacity;
      EXPECT_LE(r.max_in_flight, capacity) << "frames read but not emitted";
    }
  }
}

TEST(FramePipelineTest, OneThreadTakesTheStagesInTurnFrameByFrame) {
  std::vector<std::string> calls;
  FrameStages s;
  s.read = [&](long f) {
    calls.push_back("read " + std::to_string(f));
    return f < 2;
  };
  s.process = [&](long f) -> long {
    calls.push_back("process " + std::to_string(f));
    return 1;
  };
  s.emit = [&](long f) { calls.push_back("emit " + std::to_string(f)); };
  RunFramePipeline(s, 1, 1);
  EXPECT_EQ(calls, (std::vector<std::string>{"read 0", "process 0", "emit 0", "read 1", "process 1", "emit 1",
                                             "read 2"}));
}

TEST(FramePipelineTest, StagesRunAtTheSameTime) {
  // Each stage sleeps: three stages of 2 ms per frame on three threads take about 2 ms a frame, not 6.
  FrameStages s;
  const auto work = [] { std::this_thread::sleep_for(std::chrono::milliseconds(2)); };
  s.read = [&](long f) {
    work();
    return f < 30;
  };
  s.process = [&](long) -> long {
    work();
    return 1;
  };
  s.emit = [&](long) { work(); };
  const auto start = std::chrono::steady_clock::now();
  RunFramePipeline(s, 3, 16);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.7 * 30 * 3 * 0.002) << "the stages overlap";
}

// Frames held back by the process stage (like offline smoothing): each frame is ready once the
// `lag` frames after it were processed, or at the flush. The ring grows to hold them.
TEST(FramePipelineTest, HeldBackFramesGrowTheRingAndComeOutInOrder) {
  for (const int threads : {1, 2, 3}) {
    const long frames = 500, lag = 37;
    const long capacity = threads > 1 ? 16 : 1;
    std::vector<long> slots(static_cast<size_t>(capacity), -1);
    long grown_to = capacity;
    std::vector<long> emitted;
    long processed = 0, handed = 0;
    FrameStages s;
    s.read = [&](long f) {
      if (f >= frames) return false;
      slots[static_cast<size_t>(f) % slots.size()] = f;
      return true;
    };
    s.process = [&](long) -> long {
      ++processed;
      long ready = 0;
      while (processed - handed > lag) {
        ++handed;
        ++ready;
      }
      return ready;
    };
    s.flush = [&]() -> long {
      const long ready = processed - handed;
      handed = processed;
      return ready;
    };
    s.emit = [&](long f) { emitted.push_back(slots[static_cast<size_t>(f) % slots.size()]); };
    s.grow = [&](long old_capacity, long new_capacity, long first, long end) {
      EXPECT_EQ(old_capacity, static_cast<long>(slots.size()));
      std::vector<long> grown(static_cast<size_t>(new_capacity), -1);
      for (long f = first; f < end; ++f) grown[f % new_capacity] = slots[f % old_capacity];
      slots = grown;
      grown_to = new_capacity;
    };
    RunFramePipeline(s, threads, capacity);
    ASSERT_EQ(emitted.size(), static_cast<size_t>(frames)) << threads << " threads";
    for (long f = 0; f < frames; ++f) ASSERT_EQ(emitted[f], f) << threads << " threads";
    EXPECT_EQ(grown_to, 64) << "the smallest doubling above the " << lag + 1 << " frames held";
  }
}

// A read error at frame 700 while frame 300 fails to process: one thread stops at frame 300, and
// so must every thread count, after emitting exactly the frames before it and without hanging.
TEST(FramePipelineTest, TheErrorIsTheOneOneThreadMeetsFirst) {
  for (const int threads : {1, 2, 3}) {
    for (const long bad_process : {300L, 5000L}) {
      long emitted = 0;
      FrameStages s;
      s.read = [&](long f) {
        if (f == 700) throw std::runtime_error("read " + std::to_string(f));
        return f < 1000;
      };
      s.process = [&](long f) -> long {
        if (f == bad_process) throw std::runtime_error("process " + std::to_string(f));
        std::this_thread::sleep_for(std::chrono::microseconds(20));  // the reader runs ahead
        return 1;
      };
      s.emit = [&](long f) {
        EXPECT_EQ(f, emitted);
        ++emitted;
      };
      try {
        RunFramePipeline(s, threads, 1024);  // room for the reader to reach its error first
        ADD_FAILURE() << "no error";
      } catch (const std::runtime_error& e) {
        const long first_bad = std::min(bad_process, 700L);
        EXPECT_EQ(std::string(e.what()), (bad_process < 700 ? "process " : "read ") + std::to_string(first_bad))
            << threads << " threads";
        EXPECT_EQ(emitted, first_bad) << "the frames before the error, and no other";
      }
    }
  }
}

TEST(FramePipelineTest, AnEmitErrorStopsTheReaderToo) {
  for (const int threads : {1, 2, 3}) {
    std::atomic<long> reads{0};
    FrameStages s;
    s.read = [&](long) {
      ++reads;
      return true;  // endless
    };
    s.process = [](long) -> long { return 1; };
    s.emit = [](long f) {
      if (f == 50) throw std::runtime_error("disk full");
    };
    EXPECT_THROW(RunFramePipeline(s, threads, 16), std::runtime_error);
    EXPECT_LE(reads.load(), 50 + 16 + 1) << "the reader stops within the ring";
  }
}

// The hand-overs between the stages allocate nothing per frame: a long run makes no more
// allocations than a short one (counted on every thread that runs a stage).
TEST(FramePipelineTest, AllocatesNothingPerFrame) {
  const auto allocations = [](long frames, int threads) {
    FrameStages s;
    s.read = [frames](long f) {
      g_counting = true;
      return f < frames;
    };
    s.process = [](long) -> long {
      g_counting = true;
      return 1;
    };
    s.emit = [](long) { g_counting = true; };
    g_allocations = 0;
    RunFramePipeline(s, threads, 16);
    g_counting = false;
    return g_allocations.load();
  };
  for (const int threads : {1, 2, 3}) {
    const long short_run = allocations(100, threads);
    EXPECT_EQ(allocations(20000, threads), short_run) << threads << " threads";
  }
}

}  // namespace
}  // namespace rpt::engine
