// SPDX-License-Identifier: MIT
// The reader contract: a sequence as a header plus frames pulled one by one.
//
// A FrameSource announces its SequenceHeader (name, cameras, joint names, room, fps) before the
// first frame and then hands out the frames in order. The caller owns the frame buffers, so a
// consumer that does not keep frames holds one frame at a time whatever the length of the
// sequence (memory flat in the number of frames). Every dataset reader opens its sequences as
// sources (datasets/dataset_request.h): formats that can be walked frame by frame read or generate
// each frame when it is pulled (the synthetic generator, Panoptic's and EgoHumans' file per
// frame); formats with every frame in one file keep that file parsed and convert one frame at a
// time (IndexedFrameSource). Reading a whole sequence is its source materialised (Materialize).
//
// A frame is delivered in two parts, so that a consumer on several threads (engine/frame_pipeline.h)
// can run the second part of different frames at the same time:
//   * Pull, in order, one call at a time: everything that depends on the frames before (a file
//     position, a random walk, counters, warnings, repeated-id checks). It sets at least the
//     frame's id and time, so that checks which need the order can run on them.
//   * Complete, per frame: the rest of the frame from what Pull left in it and the source's
//     constant state (a simulated detector, a grouping of candidates, a validation). It must be
//     thread-safe: Complete of different frames (into different buffers) may run at the same time,
//     and at the same time as Pull of later frames; it reads nothing Pull changes. Until it has
//     run the frame is not finished. A source with nothing of the kind keeps the default (nothing).
// Next is the two in a row, for callers on one thread. A caller uses either Next or Pull +
// Complete on a source, not both. A source that wraps another forwards both parts: its Pull calls
// the wrapped Pull and its Complete the wrapped Complete, with the same frame_idx, before its own;
// a wrapper that drops frames, or whose in-order work needs the finished frame, calls the wrapped
// Next in its Pull instead (and the wrapped Complete never).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "datasets/input_warnings.h"
#include "datasets/sequence.h"

namespace rpt {

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // What the frames belong to; valid from construction on.
  virtual const SequenceHeader& header() const = 0;
  // Number of frames this source will deliver when known in advance (progress), else -1.
  virtual long num_frames() const = 0;
  // Overwrites *frame with the next frame (its vectors' capacity may be reused), completed, and
  // returns true, or returns false after the last frame: Pull, then Complete. Throws InputError
  // naming the file and place on bad input.
  bool Next(SequenceFrame* frame);
  // The in-order part of Next (see above): overwrites *frame with the next frame, at least its id
  // and time, and returns true, or returns false after the last frame. Throws like Next.
  virtual bool Pull(SequenceFrame* frame) = 0;
  // The per-frame part of Next (see above): finishes `frame`, the `frame_idx`-th frame Pull
  // delivered (0 for the first). Thread-safe; may throw like Next. Default: nothing to do.
  virtual void Complete(long frame_idx, SequenceFrame* frame) const;
  // Corrections the reader applied so far (input_warnings.h); complete once Pull returned false.
  virtual const InputWarnings& warnings() const = 0;

 private:
  long next_idx_ = 0;  // frames Next delivered
};

// A sequence whose frames are all in data the source holds (one .mat, JSON, NumPy or text file
// for every frame, kept parsed): `convert` writes frame `frame_idx` into a cleared frame (empty id,
// time 0, no persons, no views, no 2D labels), converting it from that data, and counts the
// corrections it applies in `warnings`; it runs in Pull. `complete`, when given, finishes the
// frame in Complete (the same frame_idx): it reads only the frame and constant data and must be
// thread-safe (the contract above), so a conversion that counts warnings stays in `convert`.
// Frames are converted one at a time, never all at once.
class IndexedFrameSource final : public FrameSource {
 public:
  using ConvertFrame = std::function<void(size_t frame_idx, SequenceFrame* frame, InputWarnings* warnings)>;
  using CompleteFrame = std::function<void(size_t frame_idx, SequenceFrame* frame)>;
  // `warnings`: the corrections made while opening (cameras, the file's index).
  IndexedFrameSource(SequenceHeader header, size_t num_frames, ConvertFrame convert, InputWarnings warnings = {},
                     CompleteFrame complete = {});

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return static_cast<long>(num_frames_); }
  bool Pull(SequenceFrame* frame) override;
  void Complete(long frame_idx, SequenceFrame* frame) const override;
  const InputWarnings& warnings() const override { return warnings_; }

 private:
  SequenceHeader header_;
  size_t num_frames_;
  ConvertFrame convert_;
  CompleteFrame complete_;
  InputWarnings warnings_;
  size_t next_ = 0;
};

// A materialised sequence as a FrameSource. Owns the sequence and moves each frame out as it is
// pulled, so the frames already delivered are freed.
class SequenceSource final : public FrameSource {
 public:
  explicit SequenceSource(Sequence sequence);

  const SequenceHeader& header() const override { return sequence_; }
  long num_frames() const override { return static_cast<long>(sequence_.frames.size()); }
  bool Pull(SequenceFrame* frame) override;
  const InputWarnings& warnings() const override { return sequence_.warnings; }

 private:
  Sequence sequence_;
  size_t next_ = 0;
};

// Pulls every frame of `source` into a Sequence (what a whole-sequence consumer needs), with the
// source's warnings once it is exhausted.
// With max_frames >= 0, a source with more frames is refused (InputError naming the sequence) before
// they are read: memory stays bounded for an input that is not the one expected (`rpt report`).
Sequence Materialize(FrameSource& source, long max_frames = -1);
// Every source materialised in turn (the sources of one dataset: its sequences, in order).
std::vector<Sequence> MaterializeAll(std::vector<std::unique_ptr<FrameSource>> sources);

}  // namespace rpt
