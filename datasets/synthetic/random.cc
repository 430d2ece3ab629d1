// SPDX-License-Identifier: MIT
#include "datasets/synthetic/random.h"

#include <cmath>
#include <numbers>

namespace rpt::synthetic {

uint64_t MixBits(uint64_t value) {
  value += 0x9E3779B97F4A7C15ULL;
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
  return value ^ (value >> 31);
}

uint64_t DeriveSeed(uint64_t seed, uint64_t stream) { return MixBits(MixBits(seed) ^ (stream * 0xD1B54A32D192ED03ULL + 1)); }

uint64_t DeriveSeed(uint64_t seed, uint64_t stream_a, uint64_t stream_b) {
  return DeriveSeed(DeriveSeed(seed, stream_a), stream_b);
}

double Rng::Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

int Rng::UniformInt(int n) {
  if (n <= 1) return 0;
  // Rejection sampling: no modulo bias.
  const uint64_t range = static_cast<uint64_t>(n);
  const uint64_t limit = UINT64_MAX - UINT64_MAX % range;
  uint64_t value = engine_();
  while (value >= limit) value = engine_();
  return static_cast<int>(value % range);
}

double Rng::Normal() {
  if (has_cached_normal_) {
    has_cached_normal_ = false;
    return cached_normal_;
  }
  // 1 - Uniform() is in (0, 1], so the logarithm is finite.
  const double u1 = 1.0 - Uniform();
  const double u2 = Uniform();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  cached_normal_ = radius * std::sin(angle);
  has_cached_normal_ = true;
  return radius * std::cos(angle);
}

int Rng::Poisson(double mean) {
  if (!(mean > 0.0)) return 0;
  const double limit = std::exp(-mean);
  int count = 0;
  double product = Uniform();
  while (product > limit) {
    ++count;
    product *= Uniform();
  }
  return count;
}

double Rng::Gamma(double shape) {
  if (!(shape > 0.0)) return 0.0;
  if (shape < 1.0) {
    // Gamma(a) = Gamma(a + 1) * U^(1/a).
    const double boost = std::pow(1.0 - Uniform(), 1.0 / shape);
    return Gamma(shape + 1.0) * boost;
  }
  const double d = shape - 1.0 / 3.0;
  const double c = 1.0 / std::sqrt(9.0 * d);
  while (true) {
    double x, v;
    do {
      x = Normal();
      v = 1.0 + c * x;
    } while (v <= 0.0);
    v = v * v * v;
    const double u = 1.0 - Uniform();  // (0, 1]
    if (u < 1.0 - 0.0331 * x * x * x * x) return d * v;
    if (std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v))) return d * v;
  }
}

double Rng::Beta(double a, double b) {
  const double x = Gamma(a);
  const double y = Gamma(b);
  return x + y > 0.0 ? x / (x + y) : 0.5;
}

double Rng::StudentScale(double dof) {
  if (!(dof > 0.0)) return 1.0;
  const double chi2 = 2.0 * Gamma(0.5 * dof);
  return chi2 > 0.0 ? std::sqrt(dof / chi2) : 1e6;
}

}  // namespace rpt::synthetic
