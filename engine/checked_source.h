// SPDX-License-Identifier: MIT
// The one validation of an input: a source whose header is checked when it is wrapped and each
// frame as it is pulled (ValidateSequenceHeader, ValidateFrame: camera validity, joint counts,
// finite coordinates, scores in [0, 1]; datasets/sequence.h), plus repeated frame ids. Readers
// correct real-world imprecision first, so a reader's frames pass; what does not is an InputError
// naming the sequence, the frame and the view. The repeated-id check remembers the ids, so it runs
// in Pull (in order); ValidateFrame reads only the frame and the header, so it runs in Complete,
// after the wrapped source's Complete (datasets/frame_source.h).
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_set>

#include "datasets/frame_source.h"

namespace rpt::engine {

class CheckedSource final : public FrameSource {
 public:
  // Throws InputError when the header (cameras) is invalid. `check_ids` false: repeated frame ids
  // are left to the source, for a live stream that checks them within a window of recent frames
  // (datasets/readers/detection_lines.h), so memory stays flat however long it runs.
  explicit CheckedSource(std::unique_ptr<FrameSource> frames, bool check_ids = true);

  const SequenceHeader& header() const override { return frames_->header(); }
  long num_frames() const override { return frames_->num_frames(); }
  bool Pull(SequenceFrame* frame) override;
  void Complete(long frame_idx, SequenceFrame* frame) const override;
  const InputWarnings& warnings() const override { return frames_->warnings(); }

 private:
  std::unique_ptr<FrameSource> frames_;
  bool check_ids_;
  // Hashes of the frame ids seen (8 bytes a frame instead of the ids themselves).
  std::unordered_set<std::uint64_t> id_hashes_;
};

}  // namespace rpt::engine
