// SPDX-License-Identifier: MIT
#include "datasets/frame_source.h"

#include "core/errors.h"
#include "core/printable_text.h"

#include <utility>

namespace rpt {

bool FrameSource::Next(SequenceFrame* frame) {
  if (!Pull(frame)) return false;
  Complete(next_idx_++, frame);
  return true;
}

void FrameSource::Complete(long, SequenceFrame*) const {}

IndexedFrameSource::IndexedFrameSource(SequenceHeader header, size_t num_frames, ConvertFrame convert,
                                       InputWarnings warnings, CompleteFrame complete)
    : header_(std::move(header)),
      num_frames_(num_frames),
      convert_(std::move(convert)),
      complete_(std::move(complete)),
      warnings_(std::move(warnings)) {}

bool IndexedFrameSource::Pull(SequenceFrame* frame) {
  if (next_ >= num_frames_) return false;
  frame->id.clear();
  frame->timestamp_s = 0;
  frame->gt.Clear(0);
  frame->views.clear();
  frame->labels_2d.clear();
  frame->paf_grouping_us = -1;
  convert_(next_++, frame, &warnings_);
  return true;
}

void IndexedFrameSource::Complete(long frame_idx, SequenceFrame* frame) const {
  if (complete_) complete_(static_cast<size_t>(frame_idx), frame);
}

SequenceSource::SequenceSource(Sequence sequence) : sequence_(std::move(sequence)) {}

bool SequenceSource::Pull(SequenceFrame* frame) {
  if (next_ >= sequence_.frames.size()) return false;
  *frame = std::move(sequence_.frames[next_]);
  sequence_.frames[next_] = SequenceFrame{};  // delivered: its memory goes with the caller's buffer
  ++next_;
  return true;
}

Sequence Materialize(FrameSource& source, long max_frames) {
  Sequence sequence;
  static_cast<SequenceHeader&>(sequence) = source.header();
  auto too_many = [&] {
    return InputError("sequence " + QuoteName(sequence.name) + ": more than the " + std::to_string(max_frames) +
                      " frames expected (" + (source.num_frames() > max_frames ? std::to_string(source.num_frames())
                                                                                 : std::string("more")) +
                      ")");
  };
  if (max_frames >= 0 && source.num_frames() > max_frames) throw too_many();
  if (source.num_frames() > 0) sequence.frames.reserve(static_cast<size_t>(source.num_frames()));
  SequenceFrame frame;
  while (source.Next(&frame)) {
    if (max_frames >= 0 && static_cast<long>(sequence.frames.size()) == max_frames) throw too_many();
    sequence.frames.push_back(std::move(frame));
  }
  sequence.warnings = source.warnings();
  return sequence;
}

std::vector<Sequence> MaterializeAll(std::vector<std::unique_ptr<FrameSource>> sources) {
  std::vector<Sequence> sequences;
  sequences.reserve(sources.size());
  for (std::unique_ptr<FrameSource>& source : sources) {
    sequences.push_back(Materialize(*source));
    source.reset();  // its parsed file is no longer needed
  }
  return sequences;
}

}  // namespace rpt
