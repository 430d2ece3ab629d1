// SPDX-License-Identifier: MIT
// An HDF5 file of arrays written in slabs of rows (along the first dimension), so a long run's
// arrays never sit in memory whole: each dataset is chunked along its first dimension, extendible
// (every dimension unlimited) and compressed (shuffle + deflate) where the HDF5 library has the
// filter. The file is built in a staged file (staged_output.h) and renamed over the target by
// Commit(). Errors are InputErrors naming the file and the dataset (hdf5_file.h). The HDF5 types
// stay inside rpt_io: this header does not include <hdf5.h>.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace rpt::io {

class Hdf5ArrayWriter {
 public:
  // Element types: little-endian IEEE double, two's-complement int32/int64, uint8, and fixed-width
  // NUL-padded UTF-8 strings.
  enum class Type { kFloat64, kInt32, kInt64, kUInt8, kString };

  // A file rpt names (whatever is at the name is replaced, never written through). Throws
  // InputError naming the target when it cannot be created.
  explicit Hdf5ArrayWriter(const std::filesystem::path& target);
  ~Hdf5ArrayWriter();  // without Commit(): the temporary is removed, the target stays as it was
  Hdf5ArrayWriter(const Hdf5ArrayWriter&) = delete;
  Hdf5ArrayWriter& operator=(const Hdf5ArrayWriter&) = delete;

  // Creates dataset `name` (a path from the root, "/poses") of shape `dims` (C order), chunks of
  // `rows_per_chunk` rows; strings are `string_width` bytes wide (at least 1).
  void Create(const std::string& name, Type type, const std::vector<std::uint64_t>& dims, std::uint64_t rows_per_chunk,
              std::size_t string_width = 0);
  // Writes rows [first_row, first_row + rows) of dataset `name` from `data`: C order, the elements
  // of the type (strings: `string_width` bytes each, NUL-padded, valid UTF-8 expected).
  void WriteRows(const std::string& name, std::uint64_t first_row, std::uint64_t rows, const void* data);

  // Whole small arrays in one call.
  void Doubles(const std::string& name, const std::vector<std::uint64_t>& dims, const std::vector<double>& values);
  void Int64s(const std::string& name, const std::vector<std::int64_t>& values);  // 1-d
  void Strings(const std::string& name, const std::vector<std::string>& values);  // 1-d, invalid UTF-8 replaced
  // A string attribute of the root group.
  void StringAttribute(const std::string& name, const std::string& value);

  // Closes the datasets and the file, flushes it and renames it over the target.
  void Commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rpt::io
