// SPDX-License-Identifier: MIT
// Part of steps 6-7 (adaptive scoring): the noise level of the 2D detections, estimated from the
// data itself and carried from frame to frame.
//
// The residual of a joint is its reprojection error converted to metres at the joint's depth
// (pixels x depth / focal length), averaged over the pair's two views: it measures how far the
// two viewing rays disagree at the person, independent of how large the person appears and of
// how much of the person's box is cut off by the image border. Real detectors give a few
// centimetres for well-visible people (more when occluded); our clean simulated detector gives
// under one.
//
// Each frame, the pairs that are mutually best (pose a's best partner in b's view is b and vice
// versa, by the median residual over their joints) and plausible (median residual below
// kMaxPlausibleResidualM) vote with their median residual. Votes go into a histogram over
// log-spaced bins whose counts decay by kDecayPerFrame each frame, seeded with `prior_weight`
// votes at the prior. The estimate is the histogram's median, clamped to
// [kMinNoiseM, kMaxNoiseM]. The mutual-best test does not depend on the estimate, so a wrong
// prior cannot lock the estimate in. Fixed size, no allocation.
#pragma once

#include <array>

namespace rpt {

class NoiseScale {
 public:
  static constexpr int kBins = 64;
  static constexpr double kMinNoiseM = 0.003;   // clamp of the estimate
  static constexpr double kMaxNoiseM = 0.1;
  static constexpr double kMaxPlausibleResidualM = 0.15;  // votes above are ignored
  static constexpr double kDecayPerFrame = 0.99;          // about 100 frames of memory
  static constexpr double kPriorWeight = 10.0;            // votes given to the prior

  explicit NoiseScale(double prior_m = 0.02) { Reset(prior_m); }

  // Back to the prior (new sequence).
  void Reset(double prior_m);
  // Starts a new frame: older votes decay.
  void BeginFrame();
  // One vote: the median residual (m) of a mutually best pair.
  void Vote(double residual_m);
  // The current estimate (m).
  double Estimate() const {
    if (dirty_) Update();
    return estimate_;
  }
  // Votes received since the last Reset (not decayed).
  long votes() const { return votes_; }

 private:
  void Update() const;

  std::array<double, kBins> counts_{};
  mutable double estimate_ = 0.02;  // the median, recomputed when asked for after new votes
  mutable bool dirty_ = false;
  long votes_ = 0;
};

}  // namespace rpt
