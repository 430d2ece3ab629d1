// SPDX-License-Identifier: MIT
// The stages of one sequence on several threads (engine/frame_pipeline.h): read, process and emit
// see the frames in order, one at a time, whatever the thread count; complete sees each frame once,
// several frames at once with several threads, and before process; the ring bounds the frames in
// flight and grows only when held-back frames fill it; an error stops the run cleanly with the
// error a single thread would have met first.
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

// A pipeline over `frames` numbered frames whose slots hold the frame number: complete makes it
// 3 f + 1, process doubles that, emit records it. Read, process and emit check they run alone and
// in order; complete and process check they find the frame as the stage before left it; the slots
// check that no frame is overwritten before it was emitted.
struct Recorder {
  long frames = 0;
  long capacity = 1;
  std::vector<long> slots;       // frame number (read), 3 x it + 1 (complete), then doubled (processed)
  std::vector<long> emitted;     // what emit found in the slot, in emit order
  std::vector<long> read_order, process_order;
  std::atomic<int> in_stage[3] = {0, 0, 0};  // read, process, emit
  std::atomic<bool> overlap{false};
  std::atomic<int> completing{0}, max_completing{0};
  std::atomic<long> wrong_slot{-1};  // a frame complete or process found in the wrong state
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
    s.complete = [this](long f) {
      const int now = ++completing;
      for (int seen = max_completing; now > seen && !max_completing.compare_exchange_weak(seen, now);) {
      }
      std::this_thread::yield();
      long& slot = slots[static_cast<size_t>(f % capacity)];
      if (slot != f) wrong_slot = f;
      slot = 3 * f + 1;
      --completing;
    };
    s.process = [this](long f) -> long {
      Enter(1);
      process_order.push_back(f);
      long& slot = slots[static_cast<size_t>(f % capacity)];
      if (slot != 3 * f + 1) wrong_slot = f;
      slot *= 2;
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

// What emit records for `frames` frames: 2 (3 f + 1).
std::vector<long> Expected(long frames) {
  std::vector<long> v;
  for (long f = 0; f < frames; ++f) v.push_back(2 * (3 * f + 1));
  return v;
}

TEST(FramePipelineTest, EveryStageSeesTheFramesInOrderWhateverTheThreads) {
  for (const int threads : {1, 2, 3, 4}) {
    for (const long capacity : {1L, 2L, 16L}) {
      Recorder r;
      r.frames = 2000;
      r.capacity = capacity;
      RunFramePipeline(r.Stages(), threads, capacity);
      EXPECT_FALSE(r.overlap) << "read, process or emit ran on two threads at once";
      EXPECT_EQ(r.wrong_slot, -1) << "complete or process found a frame not read, or not complete";
      ASSERT_EQ(r.emitted.size(), 2000u) << threads << " threads, ring " << capacity;
      EXPECT_EQ(r.emitted, Expected(2000)) << threads << " threads, ring " << capacity;
      EXPECT_LE(r.max_in_flight, capacity) << "frames read but not emitted";
      if (threads == 1) {
        EXPECT_EQ(r.max_completing, 1);
      }
      EXPECT_LE(r.max_completing, threads);
    }
  }
}

// The same numbers whatever the thread count, with a completion that takes a different time for
// each frame (so that they finish out of order).
TEST(FramePipelineTest, OutOfOrderCompletionsGiveTheOutputOfOneThread) {
  std::vector<long> one;
  for (const int threads : {1, 2, 3}) {
    const long frames = 300;
    std::vector<long> slots(16, -1), emitted;
    FrameStages s;
    s.read = [&](long f) {
      if (f < frames) slots[static_cast<size_t>(f % 16)] = f;
      return f < frames;
    };
    s.complete = [&](long f) {
      std::this_thread::sleep_for(std::chrono::microseconds((f * 7919) % 13 * 50));
      slots[static_cast<size_t>(f % 16)] = slots[static_cast<size_t>(f % 16)] * slots[static_cast<size_t>(f % 16)];
    };
    long sum = 0;  // carried from frame to frame, as the triangulator's state
    s.process = [&](long f) -> long {
      sum += slots[static_cast<size_t>(f % 16)];
      slots[static_cast<size_t>(f % 16)] = sum;
      return 1;
    };
    s.emit = [&](long f) { emitted.push_back(slots[static_cast<size_t>(f % 16)]); };
    RunFramePipeline(s, threads, 16);
    ASSERT_EQ(emitted.size(), static_cast<size_t>(frames)) << threads << " threads";
    if (threads == 1) {
      one = emitted;
      EXPECT_EQ(one.back(), (frames - 1) * frames * (2 * frames - 1) / 6) << "the sum of the squares";
    } else {
      EXPECT_EQ(emitted, one) << threads << " threads";
    }
  }
}

TEST(FramePipelineTest, OneThreadTakesTheStagesInTurnFrameByFrame) {
  for (const long capacity : {1L, 16L}) {
    std::vector<std::string> calls;
    FrameStages s;
    s.read = [&](long f) {
      calls.push_back("read " + std::to_string(f));
      return f < 2;
    };
    s.complete = [&](long f) { calls.push_back("complete " + std::to_string(f)); };
    s.process = [&](long f) -> long {
      calls.push_back("process " + std::to_string(f));
      return 1;
    };
    s.emit = [&](long f) { calls.push_back("emit " + std::to_string(f)); };
    RunFramePipeline(s, 1, capacity);
    EXPECT_EQ(calls, (std::vector<std::string>{"read 0", "complete 0", "process 0", "emit 0", "read 1", "complete 1",
                                               "process 1", "emit 1", "read 2"}))
        << "ring " << capacity;
  }
}

// Without a complete stage the frames go from read to process (which here does complete's work too).
TEST(FramePipelineTest, TheCompleteStageIsOptional) {
  for (const int threads : {1, 2, 3}) {
    Recorder r;
    r.frames = 500;
    r.capacity = 16;
    FrameStages s = r.Stages();
    s.complete = nullptr;
    s.process = [&r](long f) -> long {
      r.slots[static_cast<size_t>(f % 16)] = 2 * (3 * r.slots[static_cast<size_t>(f % 16)] + 1);
      return 1;
    };
    RunFramePipeline(s, threads, 16);
    EXPECT_EQ(r.emitted, Expected(500)) << threads << " threads";
  }
}

// Waits until `flag` is set, at most 10 s (so that a pipeline that does not overlap completions
// fails instead of hanging); returns whether it was set.
bool WaitFor(const std::atomic<bool>& flag) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!flag && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  return flag;
}

// With several threads, completions of different frames run at the same time: frame 5's does not
// finish before frame 6's started (and one thread, which cannot wait for it, is not asked to).
TEST(FramePipelineTest, CompletionsOfDifferentFramesOverlap) {
  for (const int threads : {2, 3}) {
    std::atomic<bool> sixth_started{false}, fifth_saw_it{false};
    std::atomic<long> emitted{0};
    FrameStages s;
    s.read = [](long f) { return f < 40; };
    s.complete = [&](long f) {
      if (f == 6) sixth_started = true;
      if (f == 5) fifth_saw_it = WaitFor(sixth_started);
    };
    s.process = [](long) -> long { return 1; };
    s.emit = [&](long) { ++emitted; };
    RunFramePipeline(s, threads, 16);
    EXPECT_TRUE(fifth_saw_it) << threads << " threads: frame 6's completion did not start while frame 5's ran";
    EXPECT_EQ(emitted, 40);
  }
}

TEST(FramePipelineTest, CompletionsRunAtTheSameTime) {
  // Only completions do work, 2 ms a frame: three threads complete 60 frames in about 40 ms, not 120.
  FrameStages s;
  s.read = [](long f) { return f < 60; };
  s.complete = [](long) { std::this_thread::sleep_for(std::chrono::milliseconds(2)); };
  s.process = [](long) -> long { return 1; };
  s.emit = [](long) {};
  const auto start = std::chrono::steady_clock::now();
  RunFramePipeline(s, 3, 16);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.6 * 60 * 0.002) << "the completions overlap";
}

TEST(FramePipelineTest, StagesRunAtTheSameTime) {
  // Each stage sleeps: four stages of 2 ms per frame on four threads take about 2 ms a frame, not 8.
  FrameStages s;
  const auto work = [] { std::this_thread::sleep_for(std::chrono::milliseconds(2)); };
  s.read = [&](long f) {
    work();
    return f < 30;
  };
  s.complete = [&](long) { work(); };
  s.process = [&](long) -> long {
    work();
    return 1;
  };
  s.emit = [&](long) { work(); };
  const auto start = std::chrono::steady_clock::now();
  RunFramePipeline(s, 4, 16);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.7 * 30 * 4 * 0.002) << "the stages overlap";
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
    s.complete = [&](long f) { slots[static_cast<size_t>(f) % slots.size()] += 1000000; };
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
    s.emit = [&](long f) { emitted.push_back(slots[static_cast<size_t>(f) % slots.size()] - 1000000); };
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

// An error in the completion of frame 300 against errors of the other stages (and of another
// completion) at frames around it: the one of the earliest frame wins, and within a frame read
// before complete before process before emit, as with one thread. Frame 300's completion is slow
// (unless another is), so that with several threads the later errors happen first.
TEST(FramePipelineTest, ACompletionErrorIsOrderedLikeTheOtherStages) {
  struct Case {
    long read = -1, complete = -1, process = -1, emit = -1;  // frame whose stage throws besides frame 300's complete
    std::string expected;
  };
  const std::vector<Case> cases = {
      {.read = 301, .expected = "complete 300"},    {.complete = 301, .expected = "complete 300"},
      {.process = 300, .expected = "complete 300"}, {.emit = 300, .expected = "complete 300"},
      {.read = 300, .expected = "read 300"},        {.process = 299, .expected = "process 299"},
      {.emit = 299, .expected = "emit 299"},        {.complete = 250, .expected = "complete 250"},
  };
  for (const Case& c : cases) {
    for (const int threads : {1, 2, 3}) {
      long emitted = 0;
      FrameStages s;
      s.read = [&](long f) {
        if (f == c.read) throw std::runtime_error("read " + std::to_string(f));
        return f < 1000;
      };
      s.complete = [&](long f) {
        if (f == 300) std::this_thread::sleep_for(std::chrono::milliseconds(30));  // the others run ahead
        if (f == 300 || f == c.complete) throw std::runtime_error("complete " + std::to_string(f));
      };
      s.process = [&](long f) -> long {
        if (f == c.process) throw std::runtime_error("process " + std::to_string(f));
        return 1;
      };
      s.emit = [&](long f) {
        if (f == c.emit) throw std::runtime_error("emit " + std::to_string(f));
        EXPECT_EQ(f, emitted);
        ++emitted;
      };
      try {
        RunFramePipeline(s, threads, 1024);  // room for the reader to run ahead
        ADD_FAILURE() << "no error";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), c.expected) << threads << " threads";
        const long first_bad = std::stol(c.expected.substr(c.expected.find(' ') + 1));
        EXPECT_EQ(emitted, first_bad) << c.expected << ", " << threads << " threads: the frames before it, no other";
      }
    }
  }
}

// Two completions fail at once: frame 300's first, then frame 301's (which started while 300's ran);
// frame 300's error wins, as with one thread, where 301's never runs.
TEST(FramePipelineTest, AnEarlierFramesCompletionErrorBeatsALaterOneThatFailsAfterIt) {
  for (const int threads : {2, 3}) {
    std::atomic<bool> started_301{false};
    std::atomic<long> emitted{0};
    FrameStages s;
    s.read = [](long f) { return f < 1000; };
    s.complete = [&](long f) {
      if (f == 300) {
        EXPECT_TRUE(WaitFor(started_301)) << threads << " threads: frame 301's completion did not start";
        throw std::runtime_error("complete 300");
      }
      if (f == 301) {
        started_301 = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(30));  // fails after frame 300's
        throw std::runtime_error("complete 301");
      }
    };
    s.process = [](long) -> long { return 1; };
    s.emit = [&](long) { ++emitted; };
    try {
      RunFramePipeline(s, threads, 16);
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "complete 300") << threads << " threads";
      EXPECT_EQ(emitted, 300) << threads << " threads";
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
    s.complete = [](long) {};
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
    s.complete = [](long) { g_counting = true; };
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
