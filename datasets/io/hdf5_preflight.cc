// SPDX-License-Identifier: MIT
#include "datasets/io/hdf5_preflight.h"

#include <hdf5.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/errors.h"
#include "datasets/io/child_process.h"
#include "datasets/io/hdf5_file.h"

namespace rpt::io {
namespace {

// The child's exit codes that let the reader go on: the walk reached every object, or the library
// (or the walk itself, out of memory say) reported an error, which the reader will report with
// the object's path. Any other ending is a crash, a sanitizer report or a kill.
constexpr int kWalked = 0;
constexpr int kReportedError = 3;
constexpr int kWalkFailed = 4;

// More objects than any rpt cache holds; a file with more is walked only this far.
constexpr std::size_t kMaxObjects = 100000;
constexpr std::size_t kMaxAttributeElements = std::size_t{1} << 16;

std::atomic<bool> preflight_enabled{true};

struct Walk {
  std::uint64_t inflate_limit = 0;
  std::size_t objects = 0;
  bool clean = true;
};

// Reads `count` elements of `type` through `read` into a buffer and gives back what variable-length
// data the library allocated. Returns false when the library reported an error; reads nothing
// when the buffer would exceed `max_bytes` (a damaged size; the reader refuses it before reading).
template <typename Read>
bool ReadAndReclaim(hid_t type, hid_t space, hsize_t count, std::uint64_t max_bytes, Read read) {
  const htri_t variable_string = H5Tis_variable_str(type);
  const htri_t variable = H5Tdetect_class(type, H5T_VLEN);
  if (variable_string < 0 || variable < 0) return false;
  Hdf5Id memory_type(variable_string > 0 ? H5Tcopy(H5T_C_S1) : H5Tcopy(type), H5Tclose);
  if (!memory_type.valid()) return false;
  if (variable_string > 0 && H5Tset_size(memory_type.get(), H5T_VARIABLE) < 0) return false;
  if (variable_string > 0 && H5Tset_cset(memory_type.get(), H5Tget_cset(type)) < 0) return false;  // h5py: UTF-8
  const std::size_t element = H5Tget_size(memory_type.get());
  if (element == 0) return false;
  hsize_t bytes = 0;
  if (__builtin_mul_overflow(count, element, &bytes) || bytes > max_bytes) return true;
  std::vector<unsigned char> buffer(bytes + 1, 0);
  const bool ok = read(memory_type.get(), buffer.data()) >= 0;
  if (variable_string > 0 || variable > 0) H5Dvlen_reclaim(memory_type.get(), space, H5P_DEFAULT, buffer.data());
  return ok;
}

herr_t VisitAttribute(hid_t object, const char* name, const H5A_info_t*, void* data) {
  auto* walk = static_cast<Walk*>(data);
  Hdf5Id attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  Hdf5Id type(attribute.valid() ? H5Aget_type(attribute.get()) : H5I_INVALID_HID, H5Tclose);
  Hdf5Id space(attribute.valid() ? H5Aget_space(attribute.get()) : H5I_INVALID_HID, H5Sclose);
  const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (!type.valid() || points < 0) {
    walk->clean = false;
    return 0;
  }
  if (points == 0 || static_cast<std::size_t>(points) > kMaxAttributeElements) return 0;
  const hid_t attribute_id = attribute.get();
  if (!ReadAndReclaim(
          type.get(), space.get(), static_cast<hsize_t>(points), walk->inflate_limit,
          [attribute_id](hid_t memory_type, void* buffer) { return H5Aread(attribute_id, memory_type, buffer); })) {
    walk->clean = false;
  }
  return 0;
}

// The data of a dataset whose reading goes through more of the library than one bounded copy from
// the file: chunked or compact layouts, filters, variable-length types.
void VisitDataset(hid_t dataset, Walk* walk) {
  Hdf5Id type(H5Dget_type(dataset), H5Tclose);
  Hdf5Id space(H5Dget_space(dataset), H5Sclose);
  Hdf5Id create(H5Dget_create_plist(dataset), H5Pclose);
  if (!type.valid() || !space.valid() || !create.valid()) {
    walk->clean = false;
    return;
  }
  const H5D_layout_t layout = H5Pget_layout(create.get());
  const htri_t variable = H5Tdetect_class(type.get(), H5T_VLEN);
  const htri_t variable_string = H5Tis_variable_str(type.get());
  if (layout < 0 || variable < 0 || variable_string < 0) {
    walk->clean = false;
    return;
  }
  H5Dget_storage_size(dataset);
  if (layout == H5D_CONTIGUOUS && variable == 0 && variable_string == 0) return;
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  const std::size_t element = variable_string > 0 ? sizeof(char*) : H5Tget_size(type.get());
  hsize_t bytes = 0;
  if (points <= 0 || element == 0 || __builtin_mul_overflow(static_cast<hsize_t>(points), element, &bytes) ||
      bytes > walk->inflate_limit) {
    return;  // empty, or more than the reader would accept: it refuses before reading
  }
  if (!ReadAndReclaim(type.get(), space.get(), static_cast<hsize_t>(points), walk->inflate_limit,
                      [dataset](hid_t memory_type, void* buffer) {
                        return H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer);
                      })) {
    walk->clean = false;
  }
}

herr_t VisitObject(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* walk = static_cast<Walk*>(data);
  if (++walk->objects > kMaxObjects) return 1;
  // Look the object up by name too: the readers reach objects that way (H5G__stab_lookup), the
  // visit by iterating the groups.
  if (std::strcmp(name, ".") != 0 && H5Lexists(root, name, H5P_DEFAULT) <= 0) walk->clean = false;
  Hdf5Id object(H5Oopen(root, name, H5P_DEFAULT), H5Oclose);
  if (!object.valid()) {
    walk->clean = false;
    return 0;
  }
  hsize_t index = 0;
  if (info->num_attrs > 0 &&
      H5Aiterate2(object.get(), H5_INDEX_NAME, H5_ITER_NATIVE, &index, VisitAttribute, walk) < 0) {
    walk->clean = false;
  }
  if (info->type == H5O_TYPE_DATASET) VisitDataset(object.get(), walk);
  return 0;
}

// Files that passed, remembered by their bytes (small files only): the readers open a cache up to
// three times (probe, labels, detections) and a fuzzer reads thousands of small files, while a
// larger file's walk costs little beside reading it. The bytes, not the name and time stamp: a
// file rewritten within the same clock tick keeps its size and time stamp.
constexpr std::uintmax_t kRememberedFileBytes = std::uintmax_t{1} << 20;
constexpr std::size_t kRememberedFiles = 4096;

struct Passed {
  std::mutex mutex;
  std::set<std::tuple<std::size_t, std::uintmax_t, std::uint64_t>> files;  // hash, size, inflate limit
};
Passed& PassedFiles() {
  static Passed passed;
  return passed;
}

// The key of a small file's bytes and the walk's limit; nullopt for larger or unreadable files.
std::optional<std::tuple<std::size_t, std::uintmax_t, std::uint64_t>> PassKey(const std::filesystem::path& path,
                                                                              std::uint64_t inflate_limit) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kRememberedFileBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size)) || in.peek() != std::ifstream::traits_type::eof()) {
    return std::nullopt;  // shorter or longer than its size a moment ago: being written
  }
  return std::make_tuple(std::hash<std::string>{}(bytes), size, inflate_limit);
}

std::string LibraryVersion() {
  unsigned major = 0, minor = 0, release = 0;
  H5get_libversion(&major, &minor, &release);
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

}  // namespace

void SetHdf5Preflight(bool enabled) { preflight_enabled = enabled; }

void ForgetPassedHdf5Files() {
  const std::lock_guard<std::mutex> lock(PassedFiles().mutex);
  PassedFiles().files.clear();
}
bool Hdf5PreflightEnabled() { return preflight_enabled; }

bool WalkHdf5Metadata(const std::filesystem::path& path, std::uint64_t inflate_limit) {
  const Hdf5Quiet quiet;
  Hdf5Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.valid() || H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG) < 0) return false;
  if (H5Fis_hdf5(path.c_str()) <= 0) return false;
  Hdf5Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose);
  if (!file.valid()) return false;
  Walk walk;
  walk.inflate_limit = inflate_limit;
#if H5_VERSION_GE(1, 12, 0)
  const herr_t visited =
      H5Ovisit3(file.get(), H5_INDEX_NAME, H5_ITER_NATIVE, VisitObject, &walk, H5O_INFO_BASIC | H5O_INFO_NUM_ATTRS);
#else
  const herr_t visited =
      H5Ovisit2(file.get(), H5_INDEX_NAME, H5_ITER_NATIVE, VisitObject, &walk, H5O_INFO_BASIC | H5O_INFO_NUM_ATTRS);
#endif
  if (visited < 0) {
    return false;
  }
  return walk.clean;
}

void PreflightHdf5(const std::string& source, const std::filesystem::path& path, std::uint64_t inflate_limit,
                   std::chrono::milliseconds limit) {
  if (!preflight_enabled) return;
  const auto key = PassKey(path, inflate_limit);
  if (key) {
    const std::lock_guard<std::mutex> lock(PassedFiles().mutex);
    if (PassedFiles().files.count(*key)) return;
  }
  const ChildOutcome outcome = RunInChild(
      [&] {
        try {
          return WalkHdf5Metadata(path, inflate_limit) ? kWalked : kReportedError;
        } catch (...) {
          return kWalkFailed;
        }
      },
      limit);
  switch (outcome.kind) {
    case ChildOutcome::Kind::kNotRun:
      return;  // no child to walk in (process or descriptor limit, memory): read without the walk
    case ChildOutcome::Kind::kTimedOut:
      throw InputError(source + ": the HDF5 library did not finish walking the file's metadata within " +
                       LimitText(limit) +
                       ": the file is damaged (a loop in its structures?) or on a stalled disk; rpt did not read it");
    case ChildOutcome::Kind::kExited:
      if (outcome.exit_code == kWalked || outcome.exit_code == kReportedError || outcome.exit_code == kWalkFailed) {
        if (key) {
          const std::lock_guard<std::mutex> lock(PassedFiles().mutex);
          if (PassedFiles().files.size() >= kRememberedFiles) PassedFiles().files.clear();
          PassedFiles().files.insert(*key);
        }
        return;
      }
      break;
    case ChildOutcome::Kind::kSignaled:
      break;
  }
  const std::string how = outcome.kind == ChildOutcome::Kind::kSignaled
                              ? "crashed (" + SignalName(outcome.signal) + ")"
                              : "failed (exit code " + std::to_string(outcome.exit_code) + ")";
  throw InputError(source + ": the HDF5 library (" + LibraryVersion() + ") " + how +
                   " walking the file's groups and attributes: the file is damaged; rpt did not read it");
}

}  // namespace rpt::io
