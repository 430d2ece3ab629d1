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
enum Stage : int { kRead = 0, kProcess = 1, kEmit = 2, kNone = 3 };

// Where in a one-thread run stage `stage` of frame `frame` happens: errors compare by it.
long OrderKey(long frame, Stage stage) { return frame * 3 + stage; }

class Pipeline {
 public:
  Pipeline(const FrameStages& stages, int threads, long capacity)
      : stages_(stages), threads_(std::max(1, threads)), capacity_(std::max(1L, capacity)) {}

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
    if (running_[s] || failed_[s]) return false;  // a stage that threw never runs again
    switch (s) {
      case kRead:
        return !source_done_ && read_ < emitted_ + capacity_ && OrderKey(read_, kRead) < error_key_;
      case kProcess:
        if (processed_ < read_) return OrderKey(processed_, kProcess) < error_key_;
        return source_done_ && !flushed_ && OrderKey(read_, kProcess) < error_key_;
      case kEmit:
        return emitted_ < ready_ && OrderKey(emitted_, kEmit) < error_key_;
      case kNone:
        break;
    }
    return false;
  }

  // The stage a worker takes next: the one it just ran while that has work (fewer hand-overs),
  // else the stage nearest the output (it frees slots). One worker alone takes them in a one-thread
  // run's order: emit, process, read.
  Stage Pick(Stage last) const {
    if (threads_ > 1 && last != kNone && Runnable(last)) return last;
    for (Stage s : {kEmit, kProcess, kRead}) {
      if (Runnable(s)) return s;
    }
    return kNone;
  }

  bool AnyRunning() const { return running_[kRead] || running_[kProcess] || running_[kEmit]; }
  bool Complete() const { return source_done_ && flushed_ && emitted_ == read_; }

  void Work() {
    std::unique_lock<std::mutex> lock(mutex_);
    Stage last = kNone;
    while (!finished_) {
      const Stage s = Pick(last);
      if (s == kNone) {
        last = kNone;
        if (!AnyRunning()) {
          if (error_ || Complete()) {
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
      running_[s] = true;
      // Another stage may have work for a sleeping worker now.
      if (sleeping_ > 0 && (Runnable(kRead) || Runnable(kProcess) || Runnable(kEmit))) wake_.notify_one();
      const long frame = s == kRead ? read_ : s == kProcess ? processed_ : emitted_;
      const bool flush = s == kProcess && processed_ == read_;
      lock.unlock();
      bool more = true;
      long ready = 0;
      std::exception_ptr error;
      try {
        switch (s) {
          case kRead:
            more = stages_.read(frame);
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
      running_[s] = false;
      last = s;
      if (error) {
        failed_[s] = true;
        const long key = flush ? OrderKey(frame, kProcess) : OrderKey(frame, s);
        if (key < error_key_) {
          error_key_ = key;
          error_ = error;
        }
      } else if (s == kRead) {
        if (more) {
          ++read_;
        } else {
          source_done_ = true;
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

  // Doubles the ring (no stage is running).
  void Grow() {
    const long grown = capacity_ * 2;
    if (stages_.grow) stages_.grow(capacity_, grown, emitted_, read_);
    capacity_ = grown;
  }

  const FrameStages& stages_;
  int threads_;
  long capacity_;

  std::mutex mutex_;
  std::condition_variable wake_;
  // Frames [emitted_, read_) are in the ring: [emitted_, ready_) ready to emit, [ready_,
  // processed_) held back by the process stage, [processed_, read_) read and waiting for it.
  long read_ = 0, processed_ = 0, ready_ = 0, emitted_ = 0;
  bool source_done_ = false;  // read returned false
  bool flushed_ = false;      // flush ran (after the last frame was processed)
  bool running_[3] = {false, false, false};
  bool failed_[3] = {false, false, false};
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
