// SPDX-License-Identifier: MIT
#include "datasets/io/binary.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <system_error>

#include "core/errors.h"
#include "datasets/io/input_limits.h"

namespace rpt::io::detail {

std::string SourceName(const std::filesystem::path& path) { return path.string(); }

std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path) {
  const std::string name = SourceName(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(name + ": file not found");
  if (std::filesystem::is_directory(path, ec)) throw InputError(name + ": is a directory, expected a file");
  // A FIFO, a device or a socket would block the read or never end.
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(name + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(name + ": cannot determine file size");
  CheckInputFileSize(static_cast<std::uint64_t>(size), name);
  in.seekg(0, std::ios::beg);
  std::vector<std::uint8_t> bytes;
  try {
    bytes.resize(static_cast<std::size_t>(size));
  } catch (const std::bad_alloc&) {
    throw InputError(name + ": out of memory reading the file (" + std::to_string(size >> 20) +
                     " MiB)");
  }
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size)) {
    throw InputError(name + ": read error");
  }
  return bytes;
}

std::string HexByte(std::uint8_t value) {
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "0x%02x", static_cast<unsigned>(value));
  return buffer;
}

std::vector<std::uint8_t> InflateUpTo(Bytes input, bool raw_deflate, std::size_t limit, InflateBudget* budget,
                                      const std::string& what) {
  budget->Reserve(limit, what);
  z_stream stream{};
  const int init = raw_deflate ? inflateInit2(&stream, -MAX_WBITS) : inflateInit(&stream);
  if (init != Z_OK) throw InputError(what + ": zlib initialisation failed");

  std::vector<std::uint8_t> out;
  // Grow geometrically from a small start so a lying size field costs nothing up front.
  out.resize(std::min<std::size_t>(limit, 64 * 1024));
  std::size_t produced = 0;
  std::size_t consumed = 0;
  bool finished = false;
  while (produced < limit) {
    if (produced == out.size()) out.resize(std::min(limit, std::max<std::size_t>(out.size() * 2, 1)));
    // zlib counts in uInt (32 bit); feed in slices.
    const std::size_t in_slice = std::min<std::size_t>(input.size() - consumed, 1u << 30);
    const std::size_t out_slice = std::min<std::size_t>(out.size() - produced, 1u << 30);
    stream.next_in = const_cast<Bytef*>(input.data() + consumed);
    stream.avail_in = static_cast<uInt>(in_slice);
    stream.next_out = out.data() + produced;
    stream.avail_out = static_cast<uInt>(out_slice);
    const int rc = inflate(&stream, Z_NO_FLUSH);
    consumed += in_slice - stream.avail_in;
    produced += out_slice - stream.avail_out;
    if (rc == Z_STREAM_END) {
      finished = true;
      break;
    }
    if (rc == Z_BUF_ERROR && stream.avail_in == 0 && consumed == input.size()) {
      inflateEnd(&stream);
      throw InputError(what + ": compressed data is truncated (stream ended after " +
                       std::to_string(produced) + " bytes)");
    }
    if (rc != Z_OK && rc != Z_BUF_ERROR) {
      const std::string msg = stream.msg ? stream.msg : "error " + std::to_string(rc);
      inflateEnd(&stream);
      throw InputError(what + ": corrupt compressed data (zlib: " + msg + ")");
    }
    if (rc == Z_BUF_ERROR && stream.avail_out != 0) {
      // No progress possible although there is room: the input is exhausted mid-stream.
      inflateEnd(&stream);
      throw InputError(what + ": compressed data is truncated");
    }
  }
  inflateEnd(&stream);
  (void)finished;
  budget->Release(limit - produced);
  out.resize(produced);
  return out;
}

void AppendUtf8(std::string& out, std::uint32_t cp) {
  if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = 0xFFFD;
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else if (cp < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

}  // namespace rpt::io::detail
