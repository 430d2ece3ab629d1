// SPDX-License-Identifier: MIT
// The streaming side of the reader contract: a sequence as a header plus frames pulled one by one.
//
// A FrameSource announces its SequenceHeader (name, cameras, joint names, room, fps) before the
// first frame and then hands out the frames in order through Next(). The caller owns the frame
// buffer and passes the same one every time, so a consumer that does not keep frames holds one
// frame at a time whatever the length of the sequence (memory flat in the number of frames).
// Readers of formats that can be walked frame by frame implement FrameSource directly (the
// synthetic generator: datasets/readers/synthetic_dataset.h); every other reader's materialised
// Sequence becomes a source through SequenceSource, so every dataset can be consumed the same way.
#pragma once

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

// A materialised sequence as a FrameSource (the adapter for readers that load whole). Owns the
// sequence and moves each frame out as it is pulled, so the frames already delivered are freed.
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

// Wraps each sequence into a SequenceSource.
std::vector<std::unique_ptr<FrameSource>> SourcesOf(std::vector<Sequence> sequences);

// Pulls every frame of `source` into a Sequence (what a whole-sequence consumer needs).
Sequence Materialize(FrameSource& source);

}  // namespace rpt
