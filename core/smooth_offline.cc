// SPDX-License-Identifier: MIT
#include "core/smooth_offline.h"

#include <stdexcept>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/offline_smoother.h"

namespace rpt {

long SmoothOffline(const SmoothOptions& options, double max_gap_s, double unobserved_score,
                   std::span<const double> timestamps_s, std::span<const int> num_detected,
                   std::vector<Poses3D>* frames) {
  if (options.mode != SmoothMode::kOffline) return 0;
  const size_t num_frames = frames->size();
  if (timestamps_s.size() != num_frames || (!num_detected.empty() && num_detected.size() != num_frames)) {
    throw std::invalid_argument("SmoothOffline: one timestamp (and detected count) per frame expected");
  }
  OfflineSmoother smoother(options, max_gap_s, unobserved_score);
  long changed = 0;
  size_t done = 0;  // frames handed back (they are written over their inputs, already copied in)
  FrameStats stats;
  const auto take_ready = [&] {
    while (smoother.Pop(&(*frames)[done], &stats)) {
      changed += stats.count[static_cast<int>(Step::kSmooth)];
      ++done;
    }
  };
  for (size_t f = 0; f < num_frames; ++f) {
    const Poses3D& persons = (*frames)[f];
    smoother.Push(timestamps_s[f], persons, num_detected.empty() ? persons.num_persons() : num_detected[f],
                  FrameStats{});
    take_ready();
  }
  smoother.Flush();
  take_ready();
  return changed;
}

}  // namespace rpt
