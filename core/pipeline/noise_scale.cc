// SPDX-License-Identifier: MIT
#include "core/pipeline/noise_scale.h"

#include <algorithm>
#include <cmath>

namespace rpt {
namespace {

// Bins cover [kLow, kHigh) m on a log scale; values outside fall into the end bins.
constexpr double kLow = 1e-3;
constexpr double kHigh = 0.3;

const double kBinWidth = std::log(kHigh / kLow) / NoiseScale::kBins;  // in log(m)

int BinOf(double value) {
  const double position = std::log(std::max(value, kLow) / kLow) / kBinWidth;
  return std::clamp(static_cast<int>(position), 0, NoiseScale::kBins - 1);
}

}  // namespace

void NoiseScale::Reset(double prior_m) {
  counts_.fill(0.0);
  counts_[BinOf(prior_m)] = kPriorWeight;
  votes_ = 0;
  Update();
}

void NoiseScale::BeginFrame() {
  for (double& c : counts_) c *= kDecayPerFrame;
}

void NoiseScale::Vote(double residual_m) {
  if (!(residual_m >= 0) || residual_m > kMaxPlausibleResidualM) return;
  counts_[BinOf(residual_m)] += 1.0;
  ++votes_;
  dirty_ = true;
}

void NoiseScale::Update() const {
  dirty_ = false;
  double total = 0;
  for (double c : counts_) total += c;
  if (!(total > 0)) return;
  // Median with linear interpolation inside its bin (log scale).
  double below = 0;
  for (int b = 0; b < kBins; ++b) {
    if (below + counts_[b] >= 0.5 * total) {
      const double fraction = counts_[b] > 0 ? (0.5 * total - below) / counts_[b] : 0.5;
      estimate_ = std::clamp(kLow * std::exp((b + fraction) * kBinWidth), kMinNoiseM, kMaxNoiseM);
      return;
    }
    below += counts_[b];
  }
}

}  // namespace rpt
