// SPDX-License-Identifier: MIT
// Offline smoothing (smooth.mode = offline) of a whole triangulated sequence at once: the frames
// go through an OfflineSmoother (core/pipeline/offline_smoother.h, which describes the method)
// and come back smoothed. For callers that hold every frame anyway; a caller that streams frames
// uses the OfflineSmoother itself.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

// Smooths `frames` in place. `timestamps_s[f]` is frame f's time (NaN = unknown);
// `num_detected[f]` the number of persons of frame f that were detected (the coasting ones follow
// them), empty = all; `unobserved_score` as for OfflineSmoother. Returns the number of joints
// changed. Does nothing unless options.mode is kOffline.
long SmoothOffline(const SmoothOptions& options, double max_gap_s, double unobserved_score,
                   std::span<const double> timestamps_s, std::span<const int> num_detected,
                   std::vector<Poses3D>* frames);

}  // namespace rpt
