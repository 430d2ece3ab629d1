// SPDX-License-Identifier: MIT
// LogHistogram: medians and quantiles of many positive values (frame and step times, noise
// estimates) in memory that does not grow with their number.
//
// Up to kExactValues values are kept as they are and quantiles are exact (Median() equals
// metrics::Median of the values). Beyond, quantiles come from the histogram: kBinsPerDecade
// log-spaced bins per decade over [min_value, min_value * 10^num_decades), so each bin spans a
// relative width of 10^(1/480) - 1 = 0.48 %, and the value of a rank is interpolated geometrically
// inside its bin, assuming the bin's values evenly spread: its error is below 0.48 % (an estimate
// never leaves [smallest, largest] value added). Values below min_value (zero included) count as
// the smallest value added, values at or above the range as the largest.
//
// Memory: bins are allocated a tenth of a decade (48 bins, 192 bytes) at a time, when a value falls
// there first; at most num_decades * 1.9 KB, plus 0.5 KB for the exact values.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rpt::metrics {

class LogHistogram {
 public:
  static constexpr int kBinsPerDecade = 480;
  static constexpr int kExactValues = 64;

  LogHistogram(double min_value, int num_decades);

  void Add(double value);
  // Adds the values of `other` (same range), as if they had been added here after this one's.
  void Merge(const LogHistogram& other);

  long count() const { return count_; }
  // Median (mean of the two middle values for an even count); 0 when empty.
  double Median() const;
  // The value of rank floor(q * count) (0-based, at most count - 1) in sorted order; 0 when empty.
  double Quantile(double q) const;

 private:
  static constexpr int kBinsPerChunk = kBinsPerDecade / 10;
  static constexpr std::uint32_t kNoChunk = 0xffffffffu;

  double ValueAtRank(long rank) const;
  std::uint32_t* Bin(int bin_idx);  // allocates its chunk when needed

  double min_value_;
  int num_bins_;
  long count_ = 0;
  std::array<double, kExactValues> exact_{};  // the first kExactValues values
  long below_ = 0;                            // values below min_value
  long above_ = 0;                            // values at or above the range
  double smallest_ = 0.0, largest_ = 0.0;     // over all values added
  std::vector<std::uint32_t> chunk_start_;    // per chunk: its first bin in counts_, or kNoChunk
  std::vector<std::uint32_t> counts_;         // the allocated chunks' bins
};

}  // namespace rpt::metrics
