// SPDX-License-Identifier: MIT
// A FrameSource wrapper for tests that counts the input frames a consumer holds at once.
#pragma once

#include <memory>
#include <set>
#include <utility>

#include "datasets/frame_source.h"

namespace rpt {

// Counts the frames a consumer holds: the distinct buffers it passes to Pull (a consumer that
// kept frames would need a new buffer per kept frame).
class CountingSource final : public FrameSource {
 public:
  // The counts, also kept up to date in `*report` when given (for consumers that destroy the source).
  struct Counts {
    size_t frames_alive_peak = 0;
    long delivered = 0;
  };
  explicit CountingSource(std::unique_ptr<FrameSource> inner, Counts* report = nullptr)
      : inner_(std::move(inner)), report_(report) {}
  const SequenceHeader& header() const override { return inner_->header(); }
  long num_frames() const override { return inner_->num_frames(); }
  bool Pull(SequenceFrame* frame) override {
    buffers_.insert(frame);
    const bool more = inner_->Pull(frame);
    delivered_ += more ? 1 : 0;
    if (report_ != nullptr) *report_ = {buffers_.size(), delivered_};
    return more;
  }
  void Complete(long frame_idx, SequenceFrame* frame) const override { inner_->Complete(frame_idx, frame); }
  const InputWarnings& warnings() const override { return inner_->warnings(); }

  size_t frames_alive_peak() const { return buffers_.size(); }
  long delivered() const { return delivered_; }

 private:
  std::unique_ptr<FrameSource> inner_;
  Counts* report_;
  std::set<const SequenceFrame*> buffers_;
  long delivered_ = 0;
};

}  // namespace rpt
