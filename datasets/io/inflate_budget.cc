// SPDX-License-Identifier: MIT
#include "datasets/io/inflate_budget.h"

#include <algorithm>
#include <cstdio>

#include "core/errors.h"
#include "datasets/io/input_limits.h"

namespace rpt::io {
namespace {

std::atomic<std::uint64_t> configured_megabytes{0};

}  // namespace

void SetInflateLimitMb(std::uint64_t megabytes) { configured_megabytes = megabytes; }

std::uint64_t InflateLimitFor(std::uint64_t file_bytes) {
  const std::uint64_t megabytes = configured_megabytes;
  if (megabytes > 0) return megabytes > (UINT64_MAX >> 20) ? UINT64_MAX : megabytes << 20;
  const std::uint64_t scaled = file_bytes > kMaxInflateBytes / kInflateFactor ? kMaxInflateBytes : file_bytes * kInflateFactor;
  return std::clamp(scaled, kMinInflateBytes, kMaxInflateBytes);
}

InflateBudget::InflateBudget(std::string source, std::uint64_t file_bytes)
    : source_(std::move(source)), limit_(InflateLimitFor(file_bytes)) {}

void InflateBudget::Reserve(std::uint64_t bytes, const std::string& what) {
  if (bytes > limit_ - used_) {
    const bool configured = configured_megabytes > 0;
    throw InputError(
        what + ": decompressing " + MegabytesText(bytes) + " MB would take the data decompressed from " + source_ +
        " to " + MegabytesText(used_ + std::min(bytes, UINT64_MAX - used_)) + " MB, above the limit of " +
        MegabytesText(limit_) + " MB (" +
        (configured ? std::string("set by --max-inflate-mb") : "64 x the file size, at least 64 MB, at most 4096 MB") +
        "; raise it with --max-inflate-mb N if the file is genuine)");
  }
  used_ += bytes;
}

}  // namespace rpt::io
