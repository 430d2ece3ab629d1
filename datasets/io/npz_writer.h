// SPDX-License-Identifier: MIT
// NumPy .npz writer: a stored (uncompressed) ZIP archive of .npy members, as np.savez writes it,
// readable by np.load and by our ReadNpz (npy.h). Members are written one after the other as their
// values stream in, so no array has to be in memory: BeginArray writes the member's local header
// and NPY header (format 1.0, or 2.0 when the header needs it), Write appends the element bytes
// (little-endian, C order), EndArray checks their count and patches the local header's CRC-32.
// The archive is built in a staged file (staged_output.h) and renamed over the target by Commit().
// No zip64: a member or the archive past 4 GiB is an InputError naming the file and the member.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/io/staged_output.h"

namespace rpt::io {

class NpzWriter {
 public:
  // A file rpt names (NamedBy::kRpt: whatever is at the name is replaced). Throws InputError naming
  // the target when the temporary cannot be created.
  explicit NpzWriter(const std::filesystem::path& target);
  ~NpzWriter();  // without Commit(): the temporary is removed, the target stays as it was
  NpzWriter(const NpzWriter&) = delete;
  NpzWriter& operator=(const NpzWriter&) = delete;

  // Starts member `name`.npy of numpy type `descr` ("<f8", "<i4", "<i8", "|u1", "<U12") and
  // `shape` (C order; empty: a 0-d array).
  void BeginArray(const std::string& name, const std::string& descr, const std::vector<std::int64_t>& shape);
  // Appends raw element bytes.
  void Write(const void* data, std::size_t bytes);
  // Appends one element of a "<U<width>" array: `text` (UTF-8; invalid bytes become U+FFFD) as
  // UTF-32, cut or padded with NULs to `width` code points.
  void WriteString(std::string_view text, std::size_t width);
  // Ends the member; std::logic_error when the bytes written differ from what its shape needs.
  void EndArray();

  // Whole small arrays in one call.
  void Doubles(const std::string& name, const std::vector<std::int64_t>& shape, const std::vector<double>& values);
  void Int64s(const std::string& name, const std::vector<std::int64_t>& values);  // 1-d
  // A 1-d "<U" array (shape {values.size()}), or with `scalar` a 0-d one of values[0].
  void Strings(const std::string& name, const std::vector<std::string>& values, bool scalar = false);

  // Writes the central directory, flushes and renames the archive over the target.
  void Commit();

 private:
  struct Member {
    std::string name;  // in the archive, with ".npy"
    std::uint64_t local_offset = 0;
    std::uint64_t size = 0;
    std::uint32_t crc = 0;
  };
  void Fail(const std::string& what) const;
  void Put(const void* data, std::size_t bytes);  // to the file, no CRC
  std::uint64_t Position();

  StagedFile staged_;
  std::ofstream out_;
  std::vector<Member> members_;
  bool open_member_ = false;
  std::uint64_t expected_bytes_ = 0, written_bytes_ = 0;
  std::vector<char> buffer_;  // WriteString's code units
};

// Number of code points of `text` once invalid bytes are replaced (each by one U+FFFD), the width
// of a "<U" array that holds it whole.
std::size_t Utf32Length(std::string_view text);

}  // namespace rpt::io
