// SPDX-License-Identifier: MIT
// Content digests of input files and folders, recorded in run.json by `rpt eval` and compared by
// `rpt report` before it re-loads the run's input (docs/report.md): they tell a changed input from
// the one the run used. A checksum for changes, not a defence against a forger: CRC-32 (zlib) of
// the bytes with the size, e.g. "crc32:1c291ca3/size:48213".
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rpt::io {

// CRC-32 of `bytes` continuing `crc` (0 to start).
std::uint32_t Crc32(std::uint32_t crc, std::string_view bytes);

// A regular file: "crc32:<8 hex digits>/size:<bytes>" of its bytes (read in blocks). A folder:
// "listing-crc32:<8 hex>/files:<n>" of the relative paths and sizes of the regular files under it
// (sorted; names and sizes, not contents: a dataset folder can hold gigabytes of images). Throws
// InputError naming the path when it is missing, not a regular file or folder (a FIFO), unreadable,
// or a folder holding more than kMaxDigestFiles files.
inline constexpr std::size_t kMaxDigestFiles = 1000000;
std::string PathDigest(const std::filesystem::path& path);

}  // namespace rpt::io
