// SPDX-License-Identifier: MIT
#include "metrics/log_histogram.h"

#include <algorithm>
#include <cmath>

#include "metrics/timing.h"

namespace rpt::metrics {

LogHistogram::LogHistogram(double min_value, int num_decades)
    : min_value_(min_value),
      num_bins_(num_decades * kBinsPerDecade),
      chunk_start_(static_cast<size_t>(num_bins_ / kBinsPerChunk), kNoChunk) {}

std::uint32_t* LogHistogram::Bin(int bin_idx) {
  std::uint32_t& start = chunk_start_[bin_idx / kBinsPerChunk];
  if (start == kNoChunk) {
    start = static_cast<std::uint32_t>(counts_.size());
    std::vector<std::uint32_t> grown(counts_.size() + kBinsPerChunk, 0);  // no capacity beyond the bins
    std::copy(counts_.begin(), counts_.end(), grown.begin());
    counts_.swap(grown);
  }
  return &counts_[start + bin_idx % kBinsPerChunk];
}

void LogHistogram::Add(double value) {
  if (count_ < kExactValues) exact_[count_] = value;
  smallest_ = count_ == 0 ? value : std::min(smallest_, value);
  largest_ = count_ == 0 ? value : std::max(largest_, value);
  ++count_;
  if (!(value >= min_value_)) {
    ++below_;
    return;
  }
  const double position = std::log10(value / min_value_) * kBinsPerDecade;
  if (!(position < num_bins_)) {
    ++above_;
    return;
  }
  ++*Bin(static_cast<int>(position));
}

void LogHistogram::Merge(const LogHistogram& other) {
  if (other.count_ == 0) return;
  for (long i = 0; i < other.count_ && count_ + i < kExactValues; ++i) exact_[count_ + i] = other.exact_[i];
  smallest_ = count_ == 0 ? other.smallest_ : std::min(smallest_, other.smallest_);
  largest_ = count_ == 0 ? other.largest_ : std::max(largest_, other.largest_);
  count_ += other.count_;
  below_ += other.below_;
  above_ += other.above_;
  for (size_t chunk = 0; chunk < other.chunk_start_.size(); ++chunk) {
    if (other.chunk_start_[chunk] == kNoChunk) continue;
    for (int i = 0; i < kBinsPerChunk; ++i) {
      const std::uint32_t n = other.counts_[other.chunk_start_[chunk] + i];
      if (n > 0) *Bin(static_cast<int>(chunk) * kBinsPerChunk + i) += n;
    }
  }
}

double LogHistogram::ValueAtRank(long rank) const {
  if (rank < below_) return smallest_;
  long seen = below_;
  for (size_t chunk = 0; chunk < chunk_start_.size(); ++chunk) {
    if (chunk_start_[chunk] == kNoChunk) continue;
    for (int i = 0; i < kBinsPerChunk; ++i) {
      const long n = counts_[chunk_start_[chunk] + i];
      if (rank >= seen + n) {
        seen += n;
        continue;
      }
      // Rank `rank - seen` of the n values in [lo, lo * 10^(1/480)), spread evenly in log scale.
      const double bin = static_cast<double>(chunk * kBinsPerChunk + i);
      const double fraction = (static_cast<double>(rank - seen) + 0.5) / static_cast<double>(n);
      const double value = min_value_ * std::pow(10.0, (bin + fraction) / kBinsPerDecade);
      return std::clamp(value, smallest_, largest_);
    }
  }
  return largest_;  // at or above the range
}

double LogHistogram::Median() const {
  if (count_ <= kExactValues) return metrics::Median(std::vector<double>(exact_.begin(), exact_.begin() + count_));
  if (count_ % 2 == 1) return ValueAtRank(count_ / 2);
  return 0.5 * (ValueAtRank(count_ / 2 - 1) + ValueAtRank(count_ / 2));
}

double LogHistogram::Quantile(double q) const {
  if (count_ == 0) return 0.0;
  const long rank = std::min(count_ - 1, static_cast<long>(q * static_cast<double>(count_)));
  if (count_ <= kExactValues) {
    std::vector<double> values(exact_.begin(), exact_.begin() + count_);
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    return values[rank];
  }
  return ValueAtRank(rank);
}

}  // namespace rpt::metrics
