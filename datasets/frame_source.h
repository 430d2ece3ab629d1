// SPDX-License-Identifier: MIT
// The reader contract: a sequence as a header plus frames pulled one by one.
//
// A FrameSource announces its SequenceHeader (name, cameras, joint names, room, fps) before the
// first frame and then hands out the frames in order through Next(). The caller owns the frame
// buffer and passes the same one every time, so a consumer that does not keep frames holds one
// frame at a time whatever the length of the sequence (memory flat in the number of frames).
// Every dataset reader opens its sequences as sources (datasets/dataset_request.h): formats that
// can be walked frame by frame read or generate each frame when it is pulled (the synthetic
// generator, Panoptic's and EgoHumans' file per frame); formats with every frame in one file keep
// that file parsed and convert one frame per Next (IndexedFrameSource). Reading a whole sequence
// is its source materialised (Materialize).
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
  // Overwrites *frame with the next frame (its vectors' capacity may be reused) and returns true,
  // or returns false after the last frame. Throws InputError naming the file and place on bad input.
  virtual bool Next(SequenceFrame* frame) = 0;
  // Corrections the reader applied so far (input_warnings.h); complete once Next returned false.
  virtual const InputWarnings& warnings() const = 0;
};

// A sequence whose frames are all in data the source holds (one .mat, JSON, NumPy or text file
// for every frame, kept parsed): `convert` writes frame `frame_idx` into a cleared frame (empty id,
// time 0, no persons, no views, no 2D labels), converting it from that data, and counts the
// corrections it applies in `warnings`. Frames are converted one per Next, never all at once.
class IndexedFrameSource final : public FrameSource {
 public:
  using ConvertFrame = std::function<void(size_t frame_idx, SequenceFrame* frame, InputWarnings* warnings)>;
  // `warnings`: the corrections made while opening (cameras, the file's index).
  IndexedFrameSource(SequenceHeader header, size_t num_frames, ConvertFrame convert, InputWarnings warnings = {});

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return static_cast<long>(num_frames_); }
  bool Next(SequenceFrame* frame) override;
  const InputWarnings& warnings() const override { return warnings_; }

 private:
  SequenceHeader header_;
  size_t num_frames_;
  ConvertFrame convert_;
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
  bool Next(SequenceFrame* frame) override;
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
