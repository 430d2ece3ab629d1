// SPDX-License-Identifier: MIT
#include "engine/checked_source.h"

#include <functional>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::engine {

CheckedSource::CheckedSource(std::unique_ptr<FrameSource> frames, bool check_ids)
    : frames_(std::move(frames)), check_ids_(check_ids) {
  ValidateSequenceHeader(frames_->header(), frames_->header().name);
  if (check_ids_ && frames_->num_frames() > 0) id_hashes_.reserve(static_cast<size_t>(frames_->num_frames()));
}

bool CheckedSource::Pull(SequenceFrame* frame) {
  if (!frames_->Pull(frame)) return false;
  if (check_ids_ && !id_hashes_.insert(std::hash<std::string>{}(frame->id)).second) {
    throw InputError(frames_->header().name + ": frame " + QuoteName(frame->id) + ": repeated frame id");
  }
  return true;
}

void CheckedSource::Complete(long frame_idx, SequenceFrame* frame) const {
  frames_->Complete(frame_idx, frame);
  const SequenceHeader& h = frames_->header();
  ValidateFrame(h, *frame, h.name);
}

}  // namespace rpt::engine
