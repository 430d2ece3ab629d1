// SPDX-License-Identifier: MIT
#include "datasets/io/input_limits.h"

#include <atomic>
#include <cstdio>

#include "core/errors.h"
#include "core/text.h"

namespace rpt::io {
namespace {

std::atomic<std::uint64_t> max_input_mb{0};
std::atomic<std::uint64_t> max_cameras{0};

}  // namespace

void SetMaxInputMb(std::uint64_t megabytes) { max_input_mb = megabytes; }
void SetMaxCameras(std::uint64_t count) { max_cameras = count; }

std::uint64_t MaxInputBytes() {
  const std::uint64_t megabytes = max_input_mb > 0 ? max_input_mb.load() : kDefaultMaxInputMb;
  return megabytes > (UINT64_MAX >> 20) ? UINT64_MAX : megabytes << 20;
}

std::uint64_t MaxCameras() { return max_cameras > 0 ? max_cameras.load() : kDefaultMaxCameras; }

void CheckInputFileSize(std::uint64_t bytes, const std::string& source) {
  if (bytes <= MaxInputBytes()) return;
  throw InputError(source + ": " + MegabytesText(bytes) + " MB, above the limit of " + MegabytesText(MaxInputBytes()) +
                   " MB for a file read whole (raise it with --max-input-mb N if the file is genuine)");
}

void CheckCameraCount(std::uint64_t count, const std::string& where) {
  if (count <= MaxCameras()) return;
  throw InputError(where + ": " + std::to_string(count) + " cameras, above the limit of " + std::to_string(MaxCameras()) +
                   " (raise it with --max-cameras N if the input is genuine)");
}

std::string MegabytesText(std::uint64_t bytes) {
  return FixedText(static_cast<double>(bytes) / (1 << 20), 1);
}

}  // namespace rpt::io
