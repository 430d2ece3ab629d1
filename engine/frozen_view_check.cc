// SPDX-License-Identifier: MIT
#include "engine/frozen_view_check.h"

#include <algorithm>
#include <cstdio>

#include "core/printable_text.h"

namespace rpt::engine {

FrozenViewCheck::FrozenViewCheck(size_t num_cameras)
    : last_(num_cameras), repeated_(num_cameras, 0), run_(num_cameras, 0), longest_(num_cameras, 0) {}

void FrozenViewCheck::Add(const SequenceFrame& frame) {
  const size_t n = std::min(frame.views.size(), last_.size());
  bool any_changed = false;
  for (size_t c = 0; c < n; ++c) {
    const Poses2D& view = frame.views[c];
    const bool same = view.num_joints == last_[c].num_joints && view.data == last_[c].data;
    repeated_[c] = !view.unavailable && view.num_persons() > 0 && same;
    any_changed |= !view.unavailable && !same;  // nobody again is no change
  }
  for (size_t c = 0; c < n; ++c) {
    if (!repeated_[c]) {
      run_[c] = 0;
    } else if (any_changed) {  // a still scene (every view repeated) neither counts nor breaks a run
      longest_[c] = std::max(longest_[c], ++run_[c]);
    }
    const Poses2D& view = frame.views[c];
    if (view.unavailable) continue;
    last_[c].num_joints = view.num_joints;
    last_[c].data.assign(view.data.begin(), view.data.end());
  }
}

std::vector<std::string> FrozenViewWarnings(const std::string& sequence, const std::vector<Camera>& cameras,
                                            const std::vector<long>& longest, double fps) {
  std::vector<std::string> lines;
  for (size_t c = 0; c < longest.size() && c < cameras.size(); ++c) {
    if (longest[c] < kMinFrozenFrames) continue;
    char time[48] = "";
    if (fps > 0) std::snprintf(time, sizeof(time), " (%.1f s)", static_cast<double>(longest[c]) / fps);
    lines.push_back(PrintableText(sequence + ", camera " + QuoteName(cameras[c].name) + ": its detections repeat the " +
                                  "frame before, bit for bit, for " + std::to_string(longest[c]) + " frames in a row" +
                                  time + " while the other cameras' change: has its stream frozen (a hung camera or "
                                  "detector)? The persons made with it there are ghosts or stale"));
  }
  return lines;
}

}  // namespace rpt::engine
