// SPDX-License-Identifier: MIT
// Seeded random numbers with hand-written distributions, so synthetic data is bit-identical on
// every platform and standard library (std::normal_distribution & co. are implementation-defined).
//
// Draw once per statement: the arguments of one call (Eigen::Vector2d(rng.Normal(), rng.Normal()))
// are evaluated in an unspecified order, GCC the last first and clang the first first, so such a
// call draws different numbers per compiler. The readers draw into variables, in GCC's order where
// a call used to draw several (the order that made every published number).
#pragma once

#include <cstdint>
#include <random>

namespace rpt::synthetic {

// SplitMix64 finaliser: a well-mixed 64-bit hash of `value`.
uint64_t MixBits(uint64_t value);
// Derives an independent stream seed from a seed and a stream label (e.g. frame index, view).
uint64_t DeriveSeed(uint64_t seed, uint64_t stream);
uint64_t DeriveSeed(uint64_t seed, uint64_t stream_a, uint64_t stream_b);

// std::mt19937_64 with portable sampling functions.
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  uint64_t NextBits() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double Uniform();
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform integer in [0, n); n > 0.
  int UniformInt(int n);
  // True with probability p.
  bool Bernoulli(double p) { return Uniform() < p; }
  // Standard normal (Box-Muller; the second value is cached).
  double Normal();
  double Normal(double mean, double sigma) { return mean + sigma * Normal(); }
  // Poisson with the given mean (Knuth's multiplication method; fine for small means).
  int Poisson(double mean);
  // Gamma with the given shape > 0 and scale 1 (Marsaglia-Tsang; shape < 1 by boosting).
  double Gamma(double shape);
  // Beta(a, b), a, b > 0, from two Gamma draws.
  double Beta(double a, double b);
  // The radius factor of a 2D Student-t with `dof` degrees of freedom: sqrt(dof / chi2_dof), to
  // multiply a 2D standard normal with; 1 for dof <= 0 (Gaussian).
  double StudentScale(double dof);

 private:
  std::mt19937_64 engine_;
  double cached_normal_ = 0.0;
  bool has_cached_normal_ = false;
};

}  // namespace rpt::synthetic
