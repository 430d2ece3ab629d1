// SPDX-License-Identifier: MIT
// Limits on what one input may make rpt allocate, checked before the allocation (issue 19): the
// size of a file read whole (JSON, NPY, MAT, pickle files) and the number of cameras a file
// declares. Each is process-wide, set once by the CLI's global options before anything is read:
//   --max-input-mb N   files read whole, in MiB (default 2048)
//   --max-cameras N    cameras of one label, calibration or frame (default 1000)
// A file or count above its limit is an InputError naming the file, the place and the option.
#pragma once

#include <cstdint>
#include <string>

namespace rpt::io {

inline constexpr std::uint64_t kDefaultMaxInputMb = 2048;
inline constexpr std::uint64_t kDefaultMaxCameras = 1000;

// 0 restores the default.
void SetMaxInputMb(std::uint64_t megabytes);
void SetMaxCameras(std::uint64_t count);

std::uint64_t MaxInputBytes();
std::uint64_t MaxCameras();

// Throws InputError "<source>: <bytes> MB, above the limit of <n> MB for a file read whole (raise it
// with --max-input-mb N if the file is genuine)" when `bytes` is above MaxInputBytes().
void CheckInputFileSize(std::uint64_t bytes, const std::string& source);
// Throws InputError "<where>: <count> cameras, above the limit of <n> (raise it with --max-cameras N)"
// when `count` is above MaxCameras(); `where` names the file and the place.
void CheckCameraCount(std::uint64_t count, const std::string& where);

// `bytes` in MiB with one decimal ("12.5"), as the limit messages print sizes.
std::string MegabytesText(std::uint64_t bytes);

}  // namespace rpt::io
