// SPDX-License-Identifier: MIT
#include "datasets/io/npz_writer.h"

#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/utf8.h"
#include "datasets/io/json_output.h"

namespace rpt::io {
namespace {

constexpr std::uint64_t kZipLimit = 0xFFFFFFFFull;           // without zip64
constexpr std::uint16_t kVersion = 20;                       // ZIP 2.0
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01, as np.savez's zipfile writes

void PutU16(std::vector<char>* out, std::uint16_t v) {
  out->push_back(static_cast<char>(v & 0xFF));
  out->push_back(static_cast<char>(v >> 8));
}
void PutU32(std::vector<char>* out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}

// The NPY header (magic, version, length, dict) padded so that the data starts at a multiple of 64.
std::string NpyHeader(const std::string& descr, const std::vector<std::int64_t>& shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (size_t i = 0; i < shape.size(); ++i) dict += (i ? ", " : "") + std::to_string(shape[i]);
  dict += shape.size() == 1 ? ",), }" : "), }";
  const bool v1 = dict.size() + 1 + 10 < 65536;
  const size_t prefix = v1 ? 10 : 12;
  const size_t total = (prefix + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - prefix - dict.size() - 1, ' ');
  dict += '\n';
  std::string header("\x93NUMPY", 6);
  header += static_cast<char>(v1 ? 1 : 2);
  header += '\0';
  const size_t length = dict.size();
  for (size_t k = 0; k < (v1 ? 2u : 4u); ++k) header += static_cast<char>((length >> (8 * k)) & 0xFF);
  return header + dict;
}

std::uint64_t ItemSize(const std::string& descr) {
  if (descr.size() < 3) throw std::logic_error("NpzWriter: bad descr " + descr);
  const std::uint64_t n = std::stoull(descr.substr(2));
  return descr[1] == 'U' ? 4 * n : n;
}

// The code points of `text`, invalid UTF-8 replaced as in the JSON outputs (json_output.h).
template <typename F>
void ForEachCodePoint(std::string_view text, F&& f) {
  const std::string valid = ValidUtf8(std::string(text));
  const auto* s = reinterpret_cast<const unsigned char*>(valid.data());
  for (size_t i = 0; i < valid.size();) {
    const size_t n = Utf8SequenceLength(valid, i);
    std::uint32_t cp = 0xFFFD;
    if (n == 1) cp = s[i];
    if (n == 2) cp = ((s[i] & 0x1Fu) << 6) | (s[i + 1] & 0x3Fu);
    if (n == 3) cp = ((s[i] & 0x0Fu) << 12) | ((s[i + 1] & 0x3Fu) << 6) | (s[i + 2] & 0x3Fu);
    if (n == 4)
      cp = ((s[i] & 0x07u) << 18) | ((s[i + 1] & 0x3Fu) << 12) | ((s[i + 2] & 0x3Fu) << 6) | (s[i + 3] & 0x3Fu);
    f(cp);
    i += n == 0 ? 1 : n;
  }
}

}  // namespace

std::size_t Utf32Length(std::string_view text) {
  std::size_t count = 0;
  ForEachCodePoint(text, [&](std::uint32_t) { ++count; });
  return count;
}

NpzWriter::NpzWriter(const std::filesystem::path& target) : staged_(target, NamedBy::kRpt) {
  out_.open(staged_.path(), std::ios::binary | std::ios::trunc);
  if (!out_) Fail(std::string("cannot open for writing: ") + std::strerror(errno));
}

NpzWriter::~NpzWriter() = default;

void NpzWriter::Fail(const std::string& what) const { throw InputError(staged_.target().string() + ": " + what); }

std::uint64_t NpzWriter::Position() {
  const std::streamoff at = out_.tellp();
  if (at < 0) Fail("write failed (" + WriteFailureReason(staged_.path(), errno) + ")");
  return static_cast<std::uint64_t>(at);
}

void NpzWriter::Put(const void* data, std::size_t bytes) {
  out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
  if (!out_) Fail("write failed (" + WriteFailureReason(staged_.path(), errno) + ")");
}

void NpzWriter::BeginArray(const std::string& name, const std::string& descr, const std::vector<std::int64_t>& shape) {
  if (open_member_) throw std::logic_error("NpzWriter: " + name + " begun inside another member");
  Member member;
  member.name = name + ".npy";
  member.local_offset = Position();
  const std::string header = NpyHeader(descr, shape);
  std::uint64_t count = 1;
  for (const std::int64_t extent : shape) count *= static_cast<std::uint64_t>(extent);
  expected_bytes_ = count * ItemSize(descr);
  member.size = header.size() + expected_bytes_;
  if (member.size > kZipLimit || member.local_offset > kZipLimit) {
    Fail("member " + QuoteName(member.name) + " would reach " + std::to_string(member.local_offset + member.size) +
         " bytes; an NPZ without zip64 holds at most 4 GiB (use --export h5)");
  }
  std::vector<char> local;
  PutU32(&local, 0x04034b50);
  PutU16(&local, kVersion);
  PutU16(&local, 0);  // flags
  PutU16(&local, 0);  // stored
  PutU16(&local, 0);  // time
  PutU16(&local, kDosDate);
  PutU32(&local, 0);  // CRC-32, patched by EndArray
  PutU32(&local, static_cast<std::uint32_t>(member.size));
  PutU32(&local, static_cast<std::uint32_t>(member.size));
  PutU16(&local, static_cast<std::uint16_t>(member.name.size()));
  PutU16(&local, 0);  // extra
  local.insert(local.end(), member.name.begin(), member.name.end());
  Put(local.data(), local.size());
  members_.push_back(std::move(member));
  open_member_ = true;
  written_bytes_ = 0;
  members_.back().crc = static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0));
  // The NPY header is part of the member's data.
  members_.back().crc = static_cast<std::uint32_t>(
      crc32(members_.back().crc, reinterpret_cast<const Bytef*>(header.data()), static_cast<uInt>(header.size())));
  Put(header.data(), header.size());
}

void NpzWriter::Write(const void* data, std::size_t bytes) {
  if (!open_member_) throw std::logic_error("NpzWriter: Write outside a member");
  Member& member = members_.back();
  const auto* p = static_cast<const Bytef*>(data);
  for (std::size_t done = 0; done < bytes;) {  // crc32 takes at most 4 GiB - 1 at once
    const std::size_t n = std::min<std::size_t>(bytes - done, 1u << 30);
    member.crc = static_cast<std::uint32_t>(crc32(member.crc, p + done, static_cast<uInt>(n)));
    done += n;
  }
  Put(data, bytes);
  written_bytes_ += bytes;
}

void NpzWriter::WriteString(std::string_view text, std::size_t width) {
  buffer_.assign(4 * width, '\0');
  std::size_t k = 0;
  ForEachCodePoint(text, [&](std::uint32_t cp) {
    if (k >= width) return;
    for (int b = 0; b < 4; ++b) buffer_[4 * k + b] = static_cast<char>((cp >> (8 * b)) & 0xFF);
    ++k;
  });
  Write(buffer_.data(), buffer_.size());
}

void NpzWriter::EndArray() {
  if (!open_member_) throw std::logic_error("NpzWriter: EndArray outside a member");
  Member& member = members_.back();
  if (written_bytes_ != expected_bytes_) {
    throw std::logic_error("NpzWriter: " + member.name + ": " + std::to_string(written_bytes_) + " bytes written, " +
                           std::to_string(expected_bytes_) + " expected");
  }
  const std::uint64_t end = Position();
  std::vector<char> crc;
  PutU32(&crc, member.crc);
  out_.seekp(static_cast<std::streamoff>(member.local_offset + 14));
  Put(crc.data(), crc.size());
  out_.seekp(static_cast<std::streamoff>(end));
  if (!out_) Fail("write failed (" + WriteFailureReason(staged_.path(), errno) + ")");
  open_member_ = false;
}

void NpzWriter::Doubles(const std::string& name, const std::vector<std::int64_t>& shape,
                        const std::vector<double>& values) {
  BeginArray(name, "<f8", shape);
  Write(values.data(), values.size() * sizeof(double));
  EndArray();
}

void NpzWriter::Int64s(const std::string& name, const std::vector<std::int64_t>& values) {
  BeginArray(name, "<i8", {static_cast<std::int64_t>(values.size())});
  Write(values.data(), values.size() * sizeof(std::int64_t));
  EndArray();
}

void NpzWriter::Strings(const std::string& name, const std::vector<std::string>& values, bool scalar) {
  if (scalar && values.size() != 1) throw std::logic_error("NpzWriter::Strings: a 0-d array holds one value");
  std::size_t width = 1;
  for (const std::string& value : values) width = std::max(width, Utf32Length(value));
  BeginArray(
      name, "<U" + std::to_string(width),
      scalar ? std::vector<std::int64_t>{} : std::vector<std::int64_t>{static_cast<std::int64_t>(values.size())});
  for (const std::string& value : values) WriteString(value, width);
  EndArray();
}

void NpzWriter::Commit() {
  if (open_member_) throw std::logic_error("NpzWriter: Commit inside a member");
  const std::uint64_t directory_offset = Position();
  std::vector<char> directory;
  for (const Member& member : members_) {
    PutU32(&directory, 0x02014b50);
    PutU16(&directory, kVersion);  // made by
    PutU16(&directory, kVersion);  // needed
    PutU16(&directory, 0);         // flags
    PutU16(&directory, 0);         // stored
    PutU16(&directory, 0);         // time
    PutU16(&directory, kDosDate);
    PutU32(&directory, member.crc);
    PutU32(&directory, static_cast<std::uint32_t>(member.size));
    PutU32(&directory, static_cast<std::uint32_t>(member.size));
    PutU16(&directory, static_cast<std::uint16_t>(member.name.size()));
    PutU16(&directory, 0);  // extra
    PutU16(&directory, 0);  // comment
    PutU16(&directory, 0);  // disk
    PutU16(&directory, 0);  // internal attributes
    PutU32(&directory, 0);  // external attributes
    PutU32(&directory, static_cast<std::uint32_t>(member.local_offset));
    directory.insert(directory.end(), member.name.begin(), member.name.end());
  }
  if (directory_offset + directory.size() > kZipLimit || members_.size() >= 0xFFFF) {
    Fail("the archive would pass 4 GiB or 65535 members; an NPZ without zip64 cannot hold it (use --export h5)");
  }
  const auto directory_size = static_cast<std::uint32_t>(directory.size());
  PutU32(&directory, 0x06054b50);
  PutU16(&directory, 0);
  PutU16(&directory, 0);
  PutU16(&directory, static_cast<std::uint16_t>(members_.size()));
  PutU16(&directory, static_cast<std::uint16_t>(members_.size()));
  PutU32(&directory, directory_size);
  PutU32(&directory, static_cast<std::uint32_t>(directory_offset));
  PutU16(&directory, 0);  // comment
  Put(directory.data(), directory.size());
  out_.close();
  if (!out_) Fail("write failed (" + WriteFailureReason(staged_.path(), errno) + ")");
  staged_.Commit();
}

}  // namespace rpt::io
