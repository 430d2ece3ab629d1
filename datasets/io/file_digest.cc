// SPDX-License-Identifier: MIT
#include "datasets/io/file_digest.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <system_error>
#include <utility>
#include <vector>

#include "core/errors.h"

namespace rpt::io {
namespace {

std::string Hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof(text), "%08x", static_cast<unsigned>(value));
  return text;
}

std::string FileDigest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open file");
  std::vector<char> block(1 << 20);
  std::uint32_t crc = 0;
  std::uint64_t size = 0;
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::streamsize got = in.gcount();
    if (got <= 0) break;
    crc = Crc32(crc, std::string_view(block.data(), static_cast<std::size_t>(got)));
    size += static_cast<std::uint64_t>(got);
  }
  if (in.bad()) throw InputError(path.string() + ": read error");
  return "crc32:" + Hex(crc) + "/size:" + std::to_string(size);
}

std::string FolderDigest(const std::filesystem::path& folder) {
  std::vector<std::pair<std::string, std::uintmax_t>> files;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, ec); !ec && it != std::filesystem::end(it);
       it.increment(ec)) {
    std::error_code type_ec;
    if (!it->is_regular_file(type_ec)) continue;
    if (files.size() == kMaxDigestFiles) {
      throw InputError(folder.string() + ": more than " + std::to_string(kMaxDigestFiles) + " files");
    }
    files.emplace_back(std::filesystem::relative(it->path(), folder, type_ec).generic_string(), it->file_size(type_ec));
  }
  if (ec) throw InputError(folder.string() + ": cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  std::uint32_t crc = 0;
  for (const auto& [name, size] : files) {
    crc = Crc32(crc, name);
    crc = Crc32(crc, std::string_view("\0", 1));
    crc = Crc32(crc, std::to_string(size) + "\n");
  }
  return "listing-crc32:" + Hex(crc) + "/files:" + std::to_string(files.size());
}

}  // namespace

std::uint32_t Crc32(std::uint32_t crc, std::string_view bytes) {
  while (!bytes.empty()) {
    const auto n = static_cast<uInt>(std::min<std::size_t>(bytes.size(), 1u << 30));
    crc = static_cast<std::uint32_t>(crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), n));
    bytes.remove_prefix(n);
  }
  return crc;
}

std::string PathDigest(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(path.string() + ": not found");
  if (std::filesystem::is_directory(status)) return FolderDigest(path);
  if (!std::filesystem::is_regular_file(status)) throw InputError(path.string() + ": not a regular file or folder");
  return FileDigest(path);
}

}  // namespace rpt::io
