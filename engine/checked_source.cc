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
  long origin = 0;
  for (Poses2D& view : frame->views) {
    for (size_t i = 0; i + 2 < view.data.size(); i += 3) {
      if (view.data[i] == 0 && view.data[i + 1] == 0 && view.data[i + 2] > 0) {
        view.data[i + 2] = 0;
        ++origin;
      }
    }
  }
  if (origin > 0) origin_joints_.fetch_add(origin, std::memory_order_relaxed);
  ValidateFrame(h, *frame, h.name);
}

const InputWarnings& CheckedSource::warnings() const {
  warnings_ = frames_->warnings();
  warnings_.Add(frames_->header().name,
                "detected joints at pixel (0, 0) with a score above 0 read as missing (what detectors write for a "
                "joint they did not find)",
                "", 0, origin_joints_.load(std::memory_order_relaxed));
  return warnings_;
}

}  // namespace rpt::engine
