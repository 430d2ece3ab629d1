// SPDX-License-Identifier: MIT
#include "engine/checked_source.h"

#include <functional>
#include <string>
#include <utility>

#include "core/errors.h"

namespace rpt::engine {

CheckedSource::CheckedSource(std::unique_ptr<FrameSource> frames, bool check_ids)
    : frames_(std::move(frames)), check_ids_(check_ids) {
  ValidateSequenceHeader(frames_->header(), frames_->header().name);
  if (check_ids_ && frames_->num_frames() > 0) id_hashes_.reserve(static_cast<size_t>(frames_->num_frames()));
}

bool CheckedSource::Next(SequenceFrame* frame) {
  if (!frames_->Next(frame)) return false;
  const SequenceHeader& h = frames_->header();
  if (check_ids_ && !id_hashes_.insert(std::hash<std::string>{}(frame->id)).second) {
    throw InputError(h.name + ": frame '" + frame->id + "': repeated frame id");
  }
  ValidateFrame(h, *frame, h.name);
  return true;
}

}  // namespace rpt::engine
