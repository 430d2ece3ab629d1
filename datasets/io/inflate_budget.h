// SPDX-License-Identifier: MIT
// One memory budget for all data decompressed from one file (MAT compressed variables, NPZ
// members, filtered HDF5 datasets): a 1 MB file cannot make a reader allocate gigabytes. Readers
// reserve the size a file declares before they inflate anything, so a decompression bomb is
// refused before it costs memory or time.
//
// The limit per file: kInflateFactor x the file's size, at least kMinInflateBytes, at most
// kMaxInflateBytes (64 x, 64 MiB, 4 GiB). `rpt --max-inflate-mb N` (SetInflateLimitMb) replaces
// the rule with exactly N MiB for every file.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

namespace rpt::io {

inline constexpr std::uint64_t kInflateFactor = 64;
inline constexpr std::uint64_t kMinInflateBytes = std::uint64_t{64} << 20;
inline constexpr std::uint64_t kMaxInflateBytes = std::uint64_t{4} << 30;

// 0 restores the default rule. Process-wide (the CLI sets it once, before reading).
void SetInflateLimitMb(std::uint64_t megabytes);

// The limit for a file of `file_bytes` bytes under the current setting.
std::uint64_t InflateLimitFor(std::uint64_t file_bytes);

class InflateBudget {
 public:
  // `source`: the file as named in messages.
  InflateBudget(std::string source, std::uint64_t file_bytes);

  // Takes `bytes` from the budget; throws InputError "<what>: decompressing <n> MB would take the
  // data decompressed from <source> to <m> MB, above the limit of <l> MB (... --max-inflate-mb)".
  void Reserve(std::uint64_t bytes, const std::string& what);
  // Gives back what a reservation did not use (data shorter than declared).
  void Release(std::uint64_t bytes) { used_ -= bytes < used_ ? bytes : used_; }

  std::uint64_t limit() const { return limit_; }
  std::uint64_t used() const { return used_; }

 private:
  std::string source_;
  std::uint64_t limit_ = 0;
  std::uint64_t used_ = 0;
};

}  // namespace rpt::io
