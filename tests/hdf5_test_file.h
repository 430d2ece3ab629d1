// SPDX-License-Identifier: MIT
// An HDF5 file read through the C API only (not through the project's readers), for the tests that
// check what the exports wrote: a dataset's shape, its values as doubles, its strings (UTF-8), and a
// root attribute.
#pragma once

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace rpt::test {

class Hdf5TestFile {
 public:
  explicit Hdf5TestFile(const std::filesystem::path& path)
      : file_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {}
  ~Hdf5TestFile() {
    if (file_ >= 0) H5Fclose(file_);
  }
  Hdf5TestFile(const Hdf5TestFile&) = delete;
  Hdf5TestFile& operator=(const Hdf5TestFile&) = delete;

  bool ok() const { return file_ >= 0; }
  std::vector<std::int64_t> Shape(const std::string& name) const {
    const hid_t dataset = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    std::vector<hsize_t> dims(static_cast<size_t>(std::max(0, H5Sget_simple_extent_ndims(space))));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    H5Dclose(dataset);
    return {dims.begin(), dims.end()};
  }
  std::vector<double> Doubles(const std::string& name) const {
    size_t count = 1;
    for (const std::int64_t d : Shape(name)) count *= static_cast<size_t>(d);
    std::vector<double> values(count);
    const hid_t dataset = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << name;
    H5Dclose(dataset);
    return values;
  }
  // Fixed-width strings of a 1-d dataset; expects them marked UTF-8.
  std::vector<std::string> Strings(const std::string& name) const {
    const hid_t dataset = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Dget_type(dataset);
    EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8) << name;
    const size_t width = H5Tget_size(type), count = static_cast<size_t>(Shape(name).at(0));
    std::vector<char> buffer(width * count);
    EXPECT_GE(H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()), 0) << name;
    H5Tclose(type);
    H5Dclose(dataset);
    std::vector<std::string> out;
    for (size_t i = 0; i < count; ++i)
      out.emplace_back(buffer.data() + i * width, strnlen(buffer.data() + i * width, width));
    return out;
  }
  std::string Attribute(const std::string& name) const {
    const hid_t attribute = H5Aopen(file_, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
    H5Aread(attribute, type, buffer.data());
    H5Tclose(type);
    H5Aclose(attribute);
    return buffer.data();
  }

 private:
  hid_t file_;
};

}  // namespace rpt::test
