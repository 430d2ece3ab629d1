// SPDX-License-Identifier: MIT
// HDF5 through RAII handles with path context: every error is an InputError naming the file and
// the object path ("cache.h5: /detections/keypoints: shape [2, 16, 3], expected [*, 17, 3]").
// Used by the HDF5 caches (readers/hdf5_cache.cc) and Human3.6M's annot.h5 (readers/human36m.cc).
// Internal to rpt_datasets: it includes <hdf5.h>, whose include path is private to the library.
// Create an Hdf5Quiet guard before any call so HDF5 does not print its own error stack.
#pragma once

#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "core/errors.h"

namespace rpt::io {

// Turns HDF5's automatic error printing off for the lifetime of the guard (errors become our
// exceptions), restoring the previous handler afterwards.
class Hdf5Quiet {
 public:
  Hdf5Quiet() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~Hdf5Quiet() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  Hdf5Quiet(const Hdf5Quiet&) = delete;
  Hdf5Quiet& operator=(const Hdf5Quiet&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Owns one HDF5 identifier.
class Hdf5Id {
 public:
  Hdf5Id() = default;
  Hdf5Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Hdf5Id() { Reset(); }
  Hdf5Id(Hdf5Id&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = H5I_INVALID_HID; }
  Hdf5Id& operator=(Hdf5Id&& other) noexcept {
    if (this != &other) {
      Reset();
      id_ = other.id_;
      close_ = other.close_;
      other.id_ = H5I_INVALID_HID;
    }
    return *this;
  }
  Hdf5Id(const Hdf5Id&) = delete;
  Hdf5Id& operator=(const Hdf5Id&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  void Reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

inline std::string ShapeText(const std::vector<hsize_t>& dims) {
  std::string out = "[";
  for (size_t i = 0; i < dims.size(); ++i) out += (i ? ", " : "") + std::to_string(dims[i]);
  return out + "]";
}

// Creates (or adds to) an HDF5 file; every error names the file and the object path.
class Hdf5Writer {
 public:
  Hdf5Writer(const std::filesystem::path& path, bool add_to_existing) : source_(path.string()) {
    if (add_to_existing) {
      if (H5Fis_hdf5(path.c_str()) <= 0) Fail("", "cannot add to it: not an existing HDF5 file");
      file_ = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    } else {
      file_ = Hdf5Id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    }
    if (!file_.valid()) Fail("", "cannot open for writing");
  }

  [[noreturn]] void Fail(const std::string& place, const std::string& what) const {
    throw InputError(source_ + ": " + (place.empty() ? std::string() : place + ": ") + what);
  }

  hid_t file() const { return file_.get(); }

  // Creates `name` (absolute path), replacing an existing object of that name.
  Hdf5Id Group(const std::string& name) {
    if (H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT) > 0) {
      if (H5Ldelete(file_.get(), name.c_str(), H5P_DEFAULT) < 0) Fail(name, "cannot replace");
    }
    Hdf5Id group(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!group.valid()) Fail(name, "cannot create group");
    return group;
  }

  template <typename T>
  void Numbers(hid_t parent, const std::string& parent_name, const std::string& name, hid_t file_type,
               hid_t memory_type, const std::vector<hsize_t>& dims, const T* data) {
    const std::string place = parent_name + "/" + name;
    Hdf5Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    if (!space.valid()) Fail(place, "cannot create dataspace " + ShapeText(dims));
    Hdf5Id dataset(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
    if (!dataset.valid()) Fail(place, "cannot create dataset");
    const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
    if (count > 0 && H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
      Fail(place, "write failed");
    }
  }

  void Doubles(hid_t parent, const std::string& parent_name, const std::string& name, const std::vector<hsize_t>& dims,
               const std::vector<double>& data) {
    Numbers(parent, parent_name, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data.data());
  }
  void Int64s(hid_t parent, const std::string& parent_name, const std::string& name, const std::vector<std::int64_t>& data) {
    Numbers(parent, parent_name, name, H5T_STD_I64LE, H5T_NATIVE_INT64, {data.size()}, data.data());
  }
  void Int32s(hid_t parent, const std::string& parent_name, const std::string& name, const std::vector<hsize_t>& dims,
              const std::vector<std::int32_t>& data) {
    Numbers(parent, parent_name, name, H5T_STD_I32LE, H5T_NATIVE_INT32, dims, data.data());
  }

  // Fixed-length, NUL-padded strings.
  void Strings(hid_t parent, const std::string& parent_name, const std::string& name,
               const std::vector<std::string>& values) {
    size_t width = 1;
    for (const std::string& v : values) width = std::max(width, v.size());
    std::vector<char> buffer(values.size() * width, '\0');
    for (size_t i = 0; i < values.size(); ++i) std::memcpy(buffer.data() + i * width, values[i].data(), values[i].size());
    Hdf5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), width);
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    Numbers(parent, parent_name, name, type.get(), type.get(), {values.size()}, buffer.data());
  }

  void StringAttribute(hid_t object, const std::string& place, const std::string& name, const std::string& value) {
    Hdf5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), std::max<size_t>(1, value.size()));
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    Hdf5Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Id attribute(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    std::string padded = value;
    padded.resize(std::max<size_t>(1, value.size()), '\0');
    if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), padded.data()) < 0) {
      Fail(place, "cannot write attribute " + name);
    }
  }

  template <typename T>
  void NumberAttribute(hid_t object, const std::string& place, const std::string& name, hid_t file_type,
                       hid_t memory_type, T value) {
    Hdf5Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Id attribute(H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attribute.valid() || H5Awrite(attribute.get(), memory_type, &value) < 0) Fail(place, "cannot write attribute " + name);
  }

  void Close() {
    if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) Fail("", "flush failed");
    file_ = Hdf5Id();
  }

 private:
  std::string source_;
  Hdf5Id file_;
};

// Reads an HDF5 file; every error is an InputError "<file>: <object path>: <problem>".
class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::filesystem::path& path) : source_(path.string()) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(source_ + ": file not found");
    if (std::filesystem::is_directory(path, ec)) throw InputError(source_ + ": is a folder, expected an HDF5 file");
    const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
    if (is_hdf5 <= 0) {
      throw InputError(source_ + ": byte 0: not an HDF5 file (no HDF5 signature at offset 0, 512, 1024, ...)");
    }
    file_ = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file_.valid()) throw InputError(source_ + ": cannot open the HDF5 file (damaged or truncated?)");
  }

  [[noreturn]] void Fail(const std::string& place, const std::string& what) const {
    throw InputError(source_ + ": " + place + ": " + what);
  }

  bool Exists(const std::string& name) const {
    // Check each prefix: H5Lexists fails on a missing intermediate group.
    size_t pos = 0;
    while ((pos = name.find('/', pos + 1)) != std::string::npos) {
      if (H5Lexists(file_.get(), name.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
    }
    return H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT) > 0;
  }

  Hdf5Id OpenGroup(const std::string& name, const std::string& what) const {
    if (!Exists(name)) Fail(name, "missing (" + what + ")");
    Hdf5Id group(H5Gopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.valid()) Fail(name, "not a group");
    return group;
  }

  Hdf5Id OpenDataset(const std::string& name) const {
    if (!Exists(name)) Fail(name, "missing");
    Hdf5Id dataset(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) Fail(name, "not a dataset");
    return dataset;
  }

  std::vector<hsize_t> Dims(hid_t dataset, const std::string& name) const {
    Hdf5Id space(H5Dget_space(dataset), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) Fail(name, "cannot read the shape");
    std::vector<hsize_t> dims(static_cast<size_t>(rank));
    if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return dims;
  }

  // Checks the shape; `expected` entries < 0 accept any size. Returns the dims.
  std::vector<hsize_t> CheckShape(hid_t dataset, const std::string& name, const std::vector<long long>& expected,
                                  const std::string& meaning) const {
    const std::vector<hsize_t> dims = Dims(dataset, name);
    bool ok = dims.size() == expected.size();
    for (size_t i = 0; ok && i < dims.size(); ++i) ok = expected[i] < 0 || dims[i] == static_cast<hsize_t>(expected[i]);
    if (!ok) {
      std::string want = "[";
      for (size_t i = 0; i < expected.size(); ++i) want += (i ? ", " : "") + (expected[i] < 0 ? std::string("*") : std::to_string(expected[i]));
      Fail(name, "shape " + ShapeText(dims) + ", expected " + want + "]" + (meaning.empty() ? "" : " (" + meaning + ")"));
    }
    return dims;
  }

  H5T_class_t TypeClass(hid_t dataset) const {
    Hdf5Id type(H5Dget_type(dataset), H5Tclose);
    return H5Tget_class(type.get());
  }

  template <typename T>
  std::vector<T> Numbers(const std::string& name, hid_t memory_type, const std::vector<long long>& expected,
                         const std::string& meaning = "") const {
    Hdf5Id dataset = OpenDataset(name);
    const H5T_class_t type_class = TypeClass(dataset.get());
    if (type_class != H5T_FLOAT && type_class != H5T_INTEGER) Fail(name, "expected numbers");
    const std::vector<hsize_t> dims = CheckShape(dataset.get(), name, expected, meaning);
    const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
    std::vector<T> values(count);
    if (count > 0 && H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
      Fail(name, "read failed (damaged file?)");
    }
    return values;
  }

  std::vector<double> Doubles(const std::string& name, const std::vector<long long>& expected, const std::string& meaning = "") const {
    std::vector<double> values = Numbers<double>(name, H5T_NATIVE_DOUBLE, expected, meaning);
    for (size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) Fail(name, "element " + std::to_string(i) + " is NaN or infinite");
    }
    return values;
  }

  std::vector<std::int64_t> Int64s(const std::string& name, const std::vector<long long>& expected, const std::string& meaning = "") const {
    return Numbers<std::int64_t>(name, H5T_NATIVE_INT64, expected, meaning);
  }

  std::vector<std::string> Strings(const std::string& name, long long expected_count = -1) const {
    Hdf5Id dataset = OpenDataset(name);
    if (TypeClass(dataset.get()) != H5T_STRING) Fail(name, "expected strings");
    const std::vector<hsize_t> dims = CheckShape(dataset.get(), name, {expected_count}, "");
    const size_t count = dims[0];
    std::vector<std::string> out(count);
    if (count == 0) return out;
    Hdf5Id file_type(H5Dget_type(dataset.get()), H5Tclose);
    if (H5Tis_variable_str(file_type.get()) > 0) {
      Hdf5Id memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(memory_type.get(), H5T_VARIABLE);
      H5Tset_cset(memory_type.get(), H5Tget_cset(file_type.get()));
      std::vector<char*> pointers(count, nullptr);
      if (H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
        Fail(name, "read failed");
      }
      for (size_t i = 0; i < count; ++i) out[i] = pointers[i] ? pointers[i] : "";
      Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose);
      H5Dvlen_reclaim(memory_type.get(), space.get(), H5P_DEFAULT, pointers.data());
      return out;
    }
    const size_t width = H5Tget_size(file_type.get());
    if (width == 0) Fail(name, "bad string size");
    Hdf5Id memory_type(H5Tcopy(file_type.get()), H5Tclose);
    std::vector<char> buffer(count * width);
    if (H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) Fail(name, "read failed");
    for (size_t i = 0; i < count; ++i) {
      const char* begin = buffer.data() + i * width;
      out[i].assign(begin, strnlen(begin, width));
      // Space-padded strings (Fortran / MATLAB style).
      if (H5Tget_strpad(file_type.get()) == H5T_STR_SPACEPAD) out[i].erase(out[i].find_last_not_of(' ') + 1);
    }
    return out;
  }

  // An attribute as text (string attribute) or number (numeric attribute, formatted).
  bool HasAttribute(hid_t object, const std::string& name) const { return H5Aexists(object, name.c_str()) > 0; }

  std::string StringAttribute(hid_t object, const std::string& place, const std::string& name) const {
    if (!HasAttribute(object, name)) Fail(place, "attribute '" + name + "' missing");
    Hdf5Id attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
    Hdf5Id type(H5Aget_type(attribute.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING) Fail(place, "attribute '" + name + "' is not a string");
    if (H5Tis_variable_str(type.get()) > 0) {
      Hdf5Id memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(memory_type.get(), H5T_VARIABLE);
      char* text = nullptr;
      if (H5Aread(attribute.get(), memory_type.get(), &text) < 0) Fail(place, "cannot read attribute '" + name + "'");
      std::string out = text ? text : "";
      H5free_memory(text);
      return out;
    }
    const size_t width = H5Tget_size(type.get());
    std::vector<char> buffer(width + 1, '\0');
    if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) Fail(place, "cannot read attribute '" + name + "'");
    return std::string(buffer.data(), strnlen(buffer.data(), width));
  }

  double NumberAttribute(hid_t object, const std::string& place, const std::string& name) const {
    if (!HasAttribute(object, name)) Fail(place, "attribute '" + name + "' missing");
    Hdf5Id attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
    Hdf5Id type(H5Aget_type(attribute.get()), H5Tclose);
    const H5T_class_t type_class = H5Tget_class(type.get());
    if (type_class != H5T_INTEGER && type_class != H5T_FLOAT) Fail(place, "attribute '" + name + "' is not a number");
    double value = 0;
    if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) Fail(place, "cannot read attribute '" + name + "'");
    return value;
  }

  hid_t file() const { return file_.get(); }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  Hdf5Id file_;
};

}  // namespace rpt::io
