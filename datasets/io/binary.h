// SPDX-License-Identifier: MIT
// Internal helpers shared by the container readers: whole-file reads, bounds-checked
// little-endian loads, overflow-checked arithmetic and bounded zlib inflation.
// Not part of the public API (only included from datasets/io/*.cc).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "datasets/io/inflate_budget.h"

namespace rpt::io::detail {

using Bytes = std::span<const std::uint8_t>;

// Reads a whole file; throws InputError naming the path when it is missing or unreadable.
std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path);

// Name used in messages for a file: the path exactly as the caller gave it.
std::string SourceName(const std::filesystem::path& path);

// Appends code point `cp` as UTF-8 (invalid code points become U+FFFD).
void AppendUtf8(std::string& out, std::uint32_t cp);

// Unaligned little-endian loads; callers check the bounds first.
inline std::uint16_t LoadU16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t LoadU32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
inline std::uint64_t LoadU64(const std::uint8_t* p) {
  return static_cast<std::uint64_t>(LoadU32(p)) | (static_cast<std::uint64_t>(LoadU32(p + 4)) << 32);
}

// a * b and a + b, returning false on std::size_t overflow.
inline bool CheckedMul(std::size_t a, std::size_t b, std::size_t* out) {
  return !__builtin_mul_overflow(a, b, out);
}
inline bool CheckedAdd(std::size_t a, std::size_t b, std::size_t* out) {
  return !__builtin_add_overflow(a, b, out);
}

// "0x3f"
std::string HexByte(std::uint8_t value);

// Inflates `input` (zlib-wrapped when raw_deflate is false, bare deflate as in ZIP when
// true) and returns at most `limit` bytes; it stops early at the end of the stream. `limit` is
// reserved from the file's `budget` before anything is inflated (what the stream did not fill
// is given back). The output buffer grows with the data actually produced, never with a size
// claimed by the file. Throws InputError("<what>: ...") on corrupt data or when the budget
// cannot take `limit`.
std::vector<std::uint8_t> InflateUpTo(Bytes input, bool raw_deflate, std::size_t limit, InflateBudget* budget,
                                      const std::string& what);

}  // namespace rpt::io::detail
