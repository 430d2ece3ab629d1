// SPDX-License-Identifier: MIT
// HDF5 through RAII handles with path context: every error is an InputError naming the file and
// the object path ("cache.h5: /detections/keypoints: shape [2, 16, 3], expected [*, 17, 3]").
// Used by the HDF5 caches (readers/hdf5_cache.cc) and Human3.6M's annot.h5 (readers/human36m.cc).
// Internal to rpt_datasets: it includes <hdf5.h>, whose include path is private to the library.
// Create an Hdf5Quiet guard before any call so HDF5 does not print its own error stack.
#pragma once

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/file_digest.h"
#include "datasets/io/hdf5_preflight.h"
#include "datasets/io/inflate_budget.h"
#include "datasets/io/staged_output.h"

namespace rpt::io {

// Keeps HDF5 from running its library shutdown at process exit (H5dont_atexit); effective only
// before HDF5's first call, so main() calls it first (rpt::SkipHdf5CleanupAtExit, hdf5_cache.h)
// and every Hdf5Quiet guard calls it too (tests, fuzzers). HDF5 1.10 (Debian 12) misbehaves in that
// shutdown after errors: it crashed (SIGSEGV in H5F__close_cb, fixed in 1.14) when closing a file
// had failed, as on a full disk; and it leaks the object header of a damaged header that runs past
// the end of the file (upstream HDFGroup/hdf5 #3790, fixed in 1.14.5), after which the shutdown
// printed "HDF5: infinite loop closing library" below our error line. Every file rpt opens is
// closed by its RAII owner (tests check H5Fget_obj_count); the operating system frees the rest.
inline void SkipHdf5CleanupAtExit() {
  static const bool skipped = (H5dont_atexit(), true);
  (void)skipped;
}

// Turns HDF5's automatic error printing off for the lifetime of the guard (errors become our
// exceptions), restoring the previous handler afterwards.
class Hdf5Quiet {
 public:
  Hdf5Quiet() {
    SkipHdf5CleanupAtExit();
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

// The checksum of a dataset's values, stored by Hdf5Writer in the dataset's attribute "crc32" and
// compared by Hdf5Reader after each read (RequireChecksums): CRC-32 of the values as little-endian
// doubles (numbers, whatever their stored type) or of the strings each followed by a NUL.
template <typename T>
std::uint32_t NumbersCrc(const T* data, std::size_t count) {
  std::uint32_t crc = 0;
  double block[512];
  for (std::size_t first = 0; first < count; first += 512) {
    const std::size_t n = std::min<std::size_t>(512, count - first);
    for (std::size_t i = 0; i < n; ++i) block[i] = static_cast<double>(data[first + i]);
    crc = Crc32(crc, std::string_view(reinterpret_cast<const char*>(block), n * sizeof(double)));
  }
  return crc;
}
inline std::uint32_t StringsCrc(const std::vector<std::string>& values) {
  std::uint32_t crc = 0;
  for (const std::string& value : values) crc = Crc32(Crc32(crc, value), std::string_view("\0", 1));
  return crc;
}
inline constexpr const char* kChecksumAttribute = "crc32";

// Creates (or adds to) an HDF5 file; every error names the file and the object path.
class Hdf5Writer {
 public:
  Hdf5Writer(const std::filesystem::path& path, bool add_to_existing) : source_(path.string()), path_(path) {
    if (add_to_existing) {
      if (H5Fis_hdf5(path.c_str()) <= 0) Fail("", "cannot add to it: not an existing HDF5 file");
      std::error_code ec;
      PreflightHdf5(source_, path, InflateLimitFor(std::filesystem::file_size(path, ec)));
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
    const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
    Hdf5Id dataset = Dataset(parent, parent_name, name, file_type, memory_type, dims, data);
    Checksum(dataset.get(), parent_name + "/" + name, NumbersCrc(data, count));
  }

  // A dataset of `dims` from `data`, without its checksum.
  Hdf5Id Dataset(hid_t parent, const std::string& parent_name, const std::string& name, hid_t file_type,
                 hid_t memory_type, const std::vector<hsize_t>& dims, const void* data) {
    const std::string place = parent_name + "/" + name;
    Hdf5Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    if (!space.valid()) Fail(place, "cannot create dataspace " + ShapeText(dims));
    Hdf5Id dataset(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
    if (!dataset.valid()) Fail(place, "cannot create dataset");
    const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
    if (count > 0 && H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
      Fail(place, "write failed (" + WriteFailureReason(path_, errno) + ")");
    }
    return dataset;
  }

  void Checksum(hid_t dataset, const std::string& place, std::uint32_t crc) {
    NumberAttribute(dataset, place, kChecksumAttribute, H5T_STD_U32LE, H5T_NATIVE_UINT32, crc);
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
    Hdf5Id dataset = Dataset(parent, parent_name, name, type.get(), type.get(), {values.size()}, buffer.data());
    Checksum(dataset.get(), parent_name + "/" + name, StringsCrc(values));
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
    if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) Fail("", "flush failed (" + WriteFailureReason(path_, errno) + ")");
    file_ = Hdf5Id();
  }

 private:
  std::string source_;
  std::filesystem::path path_;
  Hdf5Id file_;
};

// Reads an HDF5 file; every error is an InputError "<file>: <object path>: <problem>".
//
// A damaged file must not crash the reader or make it allocate for sizes it does not hold, so
// before any read it checks what HDF5 reports about the object against what the buffer will be:
// numbers must have a standard IEEE float or integer type, strings a sane width, attributes one
// element and at most kMaxAttributes per object; the element count is computed with overflow
// checks; uncompressed (contiguous) data must lie inside the file on disk; the in-memory size of
// every dataset read is taken from the file's decompression budget (inflate_budget.h) before the
// buffer is allocated, so a compressed or never-written dataset cannot expand without bound.
class Hdf5Reader {
 public:
  static constexpr int kMaxAttributes = 64;
  static constexpr size_t kMaxStringWidth = size_t{1} << 16;

  explicit Hdf5Reader(const std::filesystem::path& path) : source_(path.string()) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(source_ + ": file not found");
    if (std::filesystem::is_directory(path, ec)) throw InputError(source_ + ": is a folder, expected an HDF5 file");
    file_bytes_ = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(source_ + ": cannot determine the file size: " + ec.message());
    budget_ = InflateBudget(source_, file_bytes_);
    const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
    if (is_hdf5 <= 0) {
      throw InputError(source_ + ": byte 0: not an HDF5 file (no HDF5 signature at offset 0, 512, 1024, ...)");
    }
    // A damaged file can crash the library itself: walk it in a child process first.
    PreflightHdf5(source_, path, budget_.limit());
    // Strong close degree: closing the file closes every object still open in it, so an error
    // path cannot leave objects behind for the library's shutdown ("infinite loop closing library").
    Hdf5Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (!access.valid() || H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG) < 0) {
      throw InputError(source_ + ": cannot set up HDF5 file access");
    }
    file_ = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose);
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
    if (!group.valid()) Fail(name, "not a group (or damaged)");
    return group;
  }

  Hdf5Id OpenDataset(const std::string& name) const {
    if (!Exists(name)) Fail(name, "missing");
    Hdf5Id dataset(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) Fail(name, "not a dataset (or damaged)");
    return dataset;
  }

  std::vector<hsize_t> Dims(hid_t dataset, const std::string& name) const {
    Hdf5Id space(H5Dget_space(dataset), H5Sclose);
    if (!space.valid()) Fail(name, "cannot read the shape (damaged?)");
    if (H5Sget_simple_extent_type(space.get()) != H5S_SIMPLE) Fail(name, "not an array (scalar or empty dataspace)");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0 || rank > H5S_MAX_RANK) Fail(name, "cannot read the shape (damaged?)");
    std::vector<hsize_t> dims(static_cast<size_t>(rank));
    if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0) Fail(name, "cannot read the shape");
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

  // The number of elements of `dims`, refusing products that overflow.
  hsize_t Count(const std::vector<hsize_t>& dims, const std::string& name) const {
    hsize_t count = 1;
    for (const hsize_t d : dims) {
      if (__builtin_mul_overflow(count, d, &count)) Fail(name, "shape " + ShapeText(dims) + " is too large");
    }
    return count;
  }

  H5T_class_t TypeClass(hid_t dataset) const {
    Hdf5Id type(H5Dget_type(dataset), H5Tclose);
    return type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
  }

  // True for the standard IEEE floats and two's-complement integers (either byte order): the only
  // number types whose conversion HDF5 does not have to take on trust from the file.
  static bool IsStandardNumber(hid_t type) {
    for (const hid_t standard : {H5T_IEEE_F32LE, H5T_IEEE_F32BE, H5T_IEEE_F64LE, H5T_IEEE_F64BE, H5T_STD_I8LE,
                                 H5T_STD_I8BE, H5T_STD_I16LE, H5T_STD_I16BE, H5T_STD_I32LE, H5T_STD_I32BE,
                                 H5T_STD_I64LE, H5T_STD_I64BE, H5T_STD_U8LE, H5T_STD_U8BE, H5T_STD_U16LE,
                                 H5T_STD_U16BE, H5T_STD_U32LE, H5T_STD_U32BE, H5T_STD_U64LE, H5T_STD_U64BE}) {
      if (H5Tequal(type, standard) > 0) return true;
    }
    return false;
  }

  // Before reading `count` elements of `file_element_bytes` each into a buffer of
  // `memory_element_bytes` each: contiguous data must match its shape and lie inside the file
  // (not checked when `file_element_bytes` is 0), and the buffer is taken from the budget.
  void PrepareRead(hid_t dataset, const std::string& name, hsize_t count, size_t file_element_bytes,
                   size_t memory_element_bytes) const {
    hsize_t file_bytes = 0, memory_bytes = 0;
    if (__builtin_mul_overflow(count, file_element_bytes, &file_bytes) ||
        __builtin_mul_overflow(count, memory_element_bytes, &memory_bytes)) {
      Fail(name, std::to_string(count) + " elements are too many");
    }
    Hdf5Id create(H5Dget_create_plist(dataset), H5Pclose);
    if (!create.valid()) Fail(name, "cannot read the storage layout (damaged?)");
    if (H5Pget_layout(create.get()) == H5D_CONTIGUOUS) {
      const haddr_t offset = H5Dget_offset(dataset);
      if (offset != HADDR_UNDEF && file_element_bytes > 0) {
        // HDF5 trusts the layout's size when it copies the data: a size that disagrees with the
        // shape makes it read past its own buffers.
        const hsize_t stored = H5Dget_storage_size(dataset);
        if (stored != file_bytes) {
          Fail(name, "stores " + std::to_string(stored) + " bytes, its shape and type need " + std::to_string(file_bytes) +
                         " (damaged?)");
        }
        // HDF5 sizes its read buffer by the end of allocation the superblock declares: it must
        // cover the data too, as must the file on disk.
        haddr_t eoa = 0;
        if (H5Fget_eoa(file_.get(), &eoa) < 0 || offset > eoa || file_bytes > eoa - offset) {
          Fail(name, "data of " + std::to_string(file_bytes) + " bytes at byte " + std::to_string(offset) +
                         " lies beyond the end of the file's address space (damaged?)");
        }
        if (offset > file_bytes_ || file_bytes > file_bytes_ - offset) {
          Fail(name, "data of " + std::to_string(file_bytes) + " bytes at byte " + std::to_string(offset) +
                         " runs past the end of the file (" + std::to_string(file_bytes_) +
                         " bytes; truncated or damaged?)");
        }
      }
    }
    budget_.Reserve(memory_bytes, source_ + ": " + name);
  }

  template <typename T>
  std::vector<T> Numbers(const std::string& name, hid_t memory_type, const std::vector<long long>& expected,
                         const std::string& meaning = "") const {
    Hdf5Id dataset = OpenDataset(name);
    Hdf5Id file_type(H5Dget_type(dataset.get()), H5Tclose);
    if (!file_type.valid() || !IsStandardNumber(file_type.get())) Fail(name, "expected numbers (IEEE float or integer)");
    const std::vector<hsize_t> dims = CheckShape(dataset.get(), name, expected, meaning);
    const hsize_t count = Count(dims, name);
    PrepareRead(dataset.get(), name, count, H5Tget_size(file_type.get()), sizeof(T));
    std::vector<T> values(count);
    if (count > 0 && H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
      Fail(name, "read failed (damaged file?)");
    }
    VerifyChecksum(dataset.get(), name, NumbersCrc(values.data(), values.size()));
    return values;
  }

  // From now on every dataset read must carry the checksum Hdf5Writer stores, and match it (the
  // caches rpt writes; other files, e.g. Human3.6M's, have none).
  void RequireChecksums() { require_checksums_ = true; }

  // With RequireChecksums: throws InputError naming the object when its "crc32" attribute is
  // missing or differs from `crc` (the checksum of the `what` read: a dataset's values, a group's
  // attributes).
  void VerifyChecksum(hid_t object, const std::string& name, std::uint32_t crc, const std::string& what = "values") const {
    if (!require_checksums_) return;
    if (!HasAttribute(object, name, kChecksumAttribute)) {
      Fail(name, std::string("checksum attribute '") + kChecksumAttribute + "' missing (damaged?)");
    }
    const double stored = NumberAttribute(object, name, kChecksumAttribute);
    if (stored != static_cast<double>(crc)) {
      Fail(name, "checksum mismatch: the " + what + " differ from those rpt wrote (damaged file; write the cache again)");
    }
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
    Hdf5Id file_type(H5Dget_type(dataset.get()), H5Tclose);
    if (!file_type.valid() || H5Tget_class(file_type.get()) != H5T_STRING) Fail(name, "expected strings");
    const std::vector<hsize_t> dims = CheckShape(dataset.get(), name, {expected_count}, "");
    const size_t count = dims[0];
    std::vector<std::string> out;
    if (count == 0) return out;
    const htri_t variable = H5Tis_variable_str(file_type.get());
    if (variable < 0) Fail(name, "unreadable string type (damaged?)");
    if (variable > 0) {
      PrepareRead(dataset.get(), name, count, 0, sizeof(char*));  // 0: heap references, their size is HDF5's
      Hdf5Id memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(memory_type.get(), H5T_VARIABLE);
      H5Tset_cset(memory_type.get(), H5Tget_cset(file_type.get()));
      Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose);
      std::vector<char*> pointers(count, nullptr);
      const herr_t read = H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
      // Reclaim whatever was read, also when the read failed half-way.
      out.resize(count);
      size_t text_bytes = 0;
      for (size_t i = 0; i < count; ++i) {
        if (pointers[i]) {
          out[i] = std::string(pointers[i], strnlen(pointers[i], kMaxStringWidth));
          text_bytes += out[i].size();
        }
      }
      H5Dvlen_reclaim(memory_type.get(), space.get(), H5P_DEFAULT, pointers.data());
      if (read < 0) Fail(name, "read failed (damaged file?)");
      budget_.Reserve(text_bytes, source_ + ": " + name);
      VerifyChecksum(dataset.get(), name, StringsCrc(out));
      return out;
    }
    const size_t width = H5Tget_size(file_type.get());
    if (width == 0 || width > kMaxStringWidth) Fail(name, "string width " + std::to_string(width) + " is out of range");
    PrepareRead(dataset.get(), name, count, width, width);
    Hdf5Id memory_type(H5Tcopy(file_type.get()), H5Tclose);
    if (!memory_type.valid()) Fail(name, "unreadable string type (damaged?)");
    const H5T_str_t pad = H5Tget_strpad(file_type.get());
    std::vector<char> buffer(count * width);
    if (H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) Fail(name, "read failed");
    out.resize(count);
    for (size_t i = 0; i < count; ++i) {
      const char* begin = buffer.data() + i * width;
      out[i].assign(begin, strnlen(begin, width));
      // Space-padded strings (Fortran / MATLAB style).
      if (pad == H5T_STR_SPACEPAD) out[i].erase(out[i].find_last_not_of(' ') + 1);
    }
    VerifyChecksum(dataset.get(), name, StringsCrc(out));
    return out;
  }

  // Whether `object` has an attribute `name`: at most kMaxAttributes of them (counted from the
  // object header), then looked up by name; a damaged attribute list is an error naming `place`.
  // Not listed with H5Aiterate2: where an attribute message fails to decode, HDF5 1.10 frees the
  // uninitialised rest of the table it was building (H5A__attr_release_table), which crashed rpt
  // on a cache whose group attribute had a damaged name length (the walk in a child process, run
  // with other heap contents, had passed it).
  bool HasAttribute(hid_t object, const std::string& place, const std::string& name) const {
    H5O_info_t info;
#if H5_VERSION_GE(1, 12, 0)
    const herr_t got = H5Oget_info3(object, &info, H5O_INFO_NUM_ATTRS);
#else
    const herr_t got = H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS);
#endif
    if (got < 0) Fail(place, "cannot list the attributes (damaged?)");
    if (info.num_attrs > static_cast<hsize_t>(kMaxAttributes)) {
      Fail(place, "more than " + std::to_string(kMaxAttributes) + " attributes (damaged or not an rpt cache?)");
    }
    const htri_t exists = H5Aexists(object, name.c_str());
    if (exists < 0) Fail(place, "cannot list the attributes (damaged?)");
    return exists > 0;
  }

  // Opens attribute `name` of `object` and checks it holds one element.
  Hdf5Id OpenAttribute(hid_t object, const std::string& place, const std::string& name) const {
    if (!HasAttribute(object, place, name)) Fail(place, "attribute " + QuoteName(name) + " missing");
    Hdf5Id attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose);
    if (!attribute.valid()) Fail(place, "cannot open attribute " + QuoteName(name) + " (damaged?)");
    Hdf5Id space(H5Aget_space(attribute.get()), H5Sclose);
    const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
    if (points != 1) Fail(place, "attribute " + QuoteName(name) + " must hold one value, it holds " + std::to_string(points));
    return attribute;
  }

  std::string StringAttribute(hid_t object, const std::string& place, const std::string& name) const {
    Hdf5Id attribute = OpenAttribute(object, place, name);
    Hdf5Id type(H5Aget_type(attribute.get()), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) Fail(place, "attribute " + QuoteName(name) + " is not a string");
    const htri_t variable = H5Tis_variable_str(type.get());
    if (variable < 0) Fail(place, "attribute " + QuoteName(name) + ": unreadable string type (damaged?)");
    if (variable > 0) {
      Hdf5Id memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(memory_type.get(), H5T_VARIABLE);
      // The file's character set (h5py writes UTF-8): HDF5 converts no string between ASCII and
      // UTF-8, so an ASCII memory type made h5py's attributes unreadable.
      const H5T_cset_t cset = H5Tget_cset(type.get());
      if (cset == H5T_CSET_ASCII || cset == H5T_CSET_UTF8) H5Tset_cset(memory_type.get(), cset);
      char* text = nullptr;
      const herr_t read = H5Aread(attribute.get(), memory_type.get(), &text);
      std::string out = text ? std::string(text, strnlen(text, kMaxStringWidth)) : "";
      H5free_memory(text);
      if (read < 0) Fail(place, "cannot read attribute " + QuoteName(name));
      return out;
    }
    const size_t width = H5Tget_size(type.get());
    if (width == 0 || width > kMaxStringWidth) Fail(place, "attribute " + QuoteName(name) + " has string width " + std::to_string(width));
    std::vector<char> buffer(width + 1, '\0');
    if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) Fail(place, "cannot read attribute " + QuoteName(name));
    return std::string(buffer.data(), strnlen(buffer.data(), width));
  }

  double NumberAttribute(hid_t object, const std::string& place, const std::string& name) const {
    Hdf5Id attribute = OpenAttribute(object, place, name);
    Hdf5Id type(H5Aget_type(attribute.get()), H5Tclose);
    if (!type.valid() || !IsStandardNumber(type.get())) Fail(place, "attribute " + QuoteName(name) + " is not a number");
    double value = 0;
    if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) Fail(place, "cannot read attribute " + QuoteName(name));
    return value;
  }

  hid_t file() const { return file_.get(); }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::uintmax_t file_bytes_ = 0;
  mutable InflateBudget budget_{std::string(), 0};
  bool require_checksums_ = false;
  Hdf5Id file_;
};

}  // namespace rpt::io
