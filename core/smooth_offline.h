// SPDX-License-Identifier: MIT
// Offline (two-sided) temporal smoothing of a whole triangulated sequence, smooth.mode = offline.
//
// Not a step of Triangulator::Process, which only sees the past: this runs after a sequence has
// been triangulated (engine/run.cc does it for rpt eval, sweep, check, demo and bench), and
// uses the frames on both sides of each one, so it adds no lag. It cannot be used online.
//
// Method: per track and joint, a local polynomial fit in time with Gaussian weights (a
// Savitzky-Golay filter generalised to uneven times and missing frames; also known as LOESS with a
// Gaussian kernel). For a frame at time t0 where the joint is observed, the observations of the
// same track within |t - t0| <= 3 sigma (sigma = smooth.offline_sigma_s) are fitted with a
// polynomial of degree smooth.offline_degree in (t - t0), weighted by exp(-(t - t0)^2 / 2 sigma^2),
// and the joint becomes the fit's value at t0. A polynomial of degree >= 1 reproduces linear
// motion exactly, also at the ends of a track (where a plain moving average would lag). The
// degree drops when too few observations are in reach; a lone observation stays as it is.
//
// Rules shared with the causal filter: a sequence is cut where consecutive frames are more than
// max_gap_s apart or a time is unknown (NaN), and nothing is smoothed across a cut (even if a
// track id went on); tracks are never mixed; joints at or below `filled_score` (missing, or filled
// by post-processing) are neither used nor changed; coasting persons (beyond `num_detected[f]`)
// and untracked persons (id -1) are left as is.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

// Smooths `frames` in place. `timestamps_s[f]` is frame f's time (NaN = unknown);
// `num_detected[f]` the number of persons of frame f that were detected (the coasting ones follow
// them), empty = all. Returns the number of joints changed. Does nothing unless options.mode is
// kOffline.
long SmoothOffline(const SmoothOptions& options, double max_gap_s, double filled_score,
                   std::span<const double> timestamps_s, std::span<const int> num_detected,
                   std::vector<Poses3D>* frames);

}  // namespace rpt
