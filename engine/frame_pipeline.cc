// SPDX-License-Identifier: MIT
#include "engine/frame_pipeline.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace rpt::engine {
namespace {

// The stages in the order one thread runs them on a frame.
enum Stage : int { kRead = 0, kComplete = 1, kProcess = 2, kEmit = 3, kNone = 4 };
constexpr long kNumStages = 4;

// Where in a one-thread run stage `stage` of frame `frame` happens: errors compare by it.
long OrderKey(long frame, Stage stage) { return frame * kNumStages + stage; }

class Pipeline {
 public:
  Pipeline(const FrameStages& stages, int threads, long capacity)
      : stages_(stages),
        threads_(std::max(1, threads)),
        capacity_(std::max(1L, capacity)),
        complete_done_(static_cast<size_t>(capacity_), 0) {}

  void Run() {
    std::vector<std::thread> others;
    others.reserve(static_cast<size_t>(threads_ - 1));
    try {
      for (int i = 1; i < threads_; ++i) others.emplace_back([this] { Work(); });
    } catch (...) {  // no thread could be started: the workers that exist finish the run
      std::lock_guard<std::mutex> lock(mutex_);
      threads_ = 1 + static_cast<int>(others.size());
    }
    Work();
    for (std::thread& t : others) t.join();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  // Whether stage s has a frame (or the flush) to handle now. Called with the lock held.
  bool Runnable(Stage s) const {
    if (failed_[s]) return false;  // a stage that threw never runs again
    switch (s) {
      case kRead:
        return !running_[kRead] && !source_done_ && read_ < emitted_ + capacity_ && OrderKey(read_, kRead) < error_key_;
      case kComplete:  // several workers at once, on different frames
        return handed_ < read_ && OrderKey(handed_, kComplete) < error_key_;
      case kProcess:
        if (running_[kProcess]) return false;
        if (processed_ < completed_) return OrderKey(processed_, kProcess) < error_key_;
        return source_done_ && processed_ == read_ && !flushed_ && OrderKey(read_, kProcess) < error_key_;
      case kEmit:
        return !running_[kEmit] && emitted_ < ready_ && OrderKey(emitted_, kEmit) < error_key_;
      case kNone:
        break;
    }
    return false;
  }

  // The stage a worker takes next. One worker alone takes them in a one-thread run's order (emit,
  // process, complete, read: the frame in flight first). Several take the stages only one worker
  // can run first (emit and process free slots, read fills them) and complete frames meanwhile.
  Stage Pick() const {
    static constexpr Stage kAlone[] = {kEmit, kProcess, kComplete, kRead};
    static constexpr Stage kShared[] = {kEmit, kProcess, kRead, kComplete};
    for (Stage s : threads_ > 1 ? kShared : kAlone) {
      if (Runnable(s)) return s;
    }
    return kNone;
  }

  bool AnyRunnable() const { return Runnable(kRead) || Runnable(kComplete) || Runnable(kProcess) || Runnable(kEmit); }
  bool AnyRunning() const { return running_[kRead] || completing_ > 0 || running_[kProcess] || running_[kEmit]; }
  bool Finished() const { return source_done_ && flushed_ && emitted_ == read_; }

  void Work() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!finished_) {
      const Stage s = Pick();
      if (s == kNone) {
        if (!AnyRunning()) {
          if (error_ || Finished()) {
            finished_ = true;
            wake_.notify_all();
            return;
          }
          // Every stage waits on another: the frames held back by the process stage fill the ring.
          Grow();
          continue;
        }
        ++sleeping_;
        wake_.wait(lock);
        --sleeping_;
        continue;
      }
      long frame = 0;
      bool flush = false;
      switch (s) {
        case kRead:
          frame = read_;
          break;
        case kComplete:
          frame = handed_++;
          ++completing_;
          break;
        case kProcess:
          frame = processed_;
          flush = processed_ == read_;
          break;
        case kEmit:
          frame = emitted_;
          break;
        case kNone:
          break;
      }
      if (s != kComplete) running_[s] = true;
      // Another stage (or frame) may have work for a sleeping worker now.
      if (sleeping_ > 0 && AnyRunnable()) wake_.notify_one();
      lock.unlock();
      bool more = true;
      long ready = 0;
      std::exception_ptr error;
      try {
        switch (s) {
          case kRead:
            more = stages_.read(frame);
            break;
          case kComplete:
            stages_.complete(frame);
            break;
          case kProcess:
            ready = flush ? (stages_.flush ? stages_.flush() : 0) : stages_.process(frame);
            break;
          case kEmit:
            stages_.emit(frame);
            break;
          case kNone:
            break;
        }
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (s == kComplete) {
        --completing_;
      } else {
        running_[s] = false;
      }
      if (error) {
        failed_[s] = true;
        const long key = flush ? OrderKey(frame, kProcess) : OrderKey(frame, s);
        if (key < error_key_) {
          error_key_ = key;
          error_ = error;
        }
      } else if (s == kRead) {
        if (!more) {
          source_done_ = true;
        } else if (stages_.complete) {
          ++read_;
        } else {  // nothing to complete: the frame is complete once read
          handed_ = completed_ = ++read_;
        }
      } else if (s == kComplete) {
        complete_done_[Slot(frame)] = 1;
        // The frames complete so far in a row go on to the process stage.
        while (completed_ < handed_ && complete_done_[Slot(completed_)] != 0) {
          complete_done_[Slot(completed_)] = 0;
          ++completed_;
        }
      } else if (s == kProcess) {
        if (flush) {
          flushed_ = true;
        } else {
          ++processed_;
        }
        ready_ = std::min(ready_ + ready, processed_);
      } else {
        ++emitted_;
      }
      if (sleeping_ > 0) wake_.notify_one();
    }
  }

  size_t Slot(long frame) const { return static_cast<size_t>(frame % capacity_); }

  // Doubles the ring (no stage is running, so every frame handed to complete is complete).
  void Grow() {
    const long grown = capacity_ * 2;
    if (stages_.grow) stages_.grow(capacity_, grown, emitted_, read_);
    capacity_ = grown;
    complete_done_.assign(static_cast<size_t>(capacity_), 0);
  }

  const FrameStages& stages_;
  int threads_;
  long capacity_;

  std::mutex mutex_;
  std::condition_variable wake_;
  // Frames [emitted_, read_) are in the ring: [emitted_, ready_) ready to emit, [ready_,
  // processed_) held back by the process stage, [processed_, completed_) complete and waiting for
  // it, [completed_, handed_) being completed or complete after one that is not yet, [handed_,
  // read_) read and waiting to be completed.
  long read_ = 0, handed_ = 0, completed_ = 0, processed_ = 0, ready_ = 0, emitted_ = 0;
  // Per slot, whether its frame in [completed_, handed_) is complete.
  std::vector<char> complete_done_;
  int completing_ = 0;        // complete stages running
  bool source_done_ = false;  // read returned false
  bool flushed_ = false;      // flush ran (after the last frame was processed)
  bool running_[kNumStages] = {false, false, false, false};  // read, process, emit (complete: completing_)
  bool failed_[kNumStages] = {false, false, false, false};
  bool finished_ = false;
  int sleeping_ = 0;
  long error_key_ = std::numeric_limits<long>::max();
  std::exception_ptr error_;
};

}  // namespace

void RunFramePipeline(const FrameStages& stages, int threads, long capacity) {
  Pipeline(stages, threads, capacity).Run();
}

}  // namespace rpt::engine
