// SPDX-License-Identifier: MIT
#include "datasets/io/hdf5_array_writer.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "datasets/io/hdf5_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/staged_output.h"

namespace rpt::io {
namespace {

struct Types {
  hid_t file;
  hid_t memory;
};

Types TypesOf(Hdf5ArrayWriter::Type type) {
  switch (type) {
    case Hdf5ArrayWriter::Type::kFloat64:
      return {H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE};
    case Hdf5ArrayWriter::Type::kInt32:
      return {H5T_STD_I32LE, H5T_NATIVE_INT32};
    case Hdf5ArrayWriter::Type::kInt64:
      return {H5T_STD_I64LE, H5T_NATIVE_INT64};
    case Hdf5ArrayWriter::Type::kUInt8:
      return {H5T_STD_U8LE, H5T_NATIVE_UINT8};
    case Hdf5ArrayWriter::Type::kString:
      break;
  }
  throw std::logic_error("Hdf5ArrayWriter: no number type for strings");
}

bool DeflateAvailable() {
  unsigned int config = 0;
  return H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0 && H5Zget_filter_info(H5Z_FILTER_DEFLATE, &config) >= 0 &&
         (config & H5Z_FILTER_CONFIG_ENCODE_ENABLED) != 0;
}

}  // namespace

struct Hdf5ArrayWriter::Impl {
  struct Dataset {
    Hdf5Id id;
    Hdf5Id string_type;  // strings only: file and memory type
    hid_t memory_type = H5I_INVALID_HID;
    std::vector<hsize_t> dims;
    std::size_t string_width = 0;
  };
  explicit Impl(const std::filesystem::path& target)
      : staged(target, NamedBy::kRpt), writer(staged.path(), /*add_to_existing=*/false) {}

  [[noreturn]] void Fail(const std::string& place, const std::string& what) const {
    throw InputError(staged.target().string() + ": " + place + ": " + what);
  }

  StagedFile staged;  // first: removed after the file is closed
  Hdf5Quiet quiet;
  Hdf5Writer writer;
  std::map<std::string, Dataset> datasets;
};

Hdf5ArrayWriter::Hdf5ArrayWriter(const std::filesystem::path& target) {
  try {
    impl_ = std::make_unique<Impl>(target);
  } catch (const InputError&) {
    throw InputError(target.string() + ": cannot create the HDF5 file");
  }
}

Hdf5ArrayWriter::~Hdf5ArrayWriter() = default;

void Hdf5ArrayWriter::Create(const std::string& name, Type type, const std::vector<std::uint64_t>& dims,
                             std::uint64_t rows_per_chunk, std::size_t string_width) {
  Impl& impl = *impl_;
  if (dims.empty()) throw std::logic_error("Hdf5ArrayWriter: " + name + " needs at least one dimension");
  Impl::Dataset dataset;
  dataset.dims.assign(dims.begin(), dims.end());
  hid_t file_type = H5I_INVALID_HID;
  if (type == Type::kString) {
    dataset.string_width = std::max<std::size_t>(1, string_width);
    dataset.string_type = Hdf5Id(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!dataset.string_type.valid() || H5Tset_size(dataset.string_type.get(), dataset.string_width) < 0 ||
        H5Tset_strpad(dataset.string_type.get(), H5T_STR_NULLPAD) < 0 ||
        H5Tset_cset(dataset.string_type.get(), H5T_CSET_UTF8) < 0) {
      impl.Fail(name, "cannot make a string type of width " + std::to_string(dataset.string_width));
    }
    file_type = dataset.memory_type = dataset.string_type.get();
  } else {
    const Types types = TypesOf(type);
    file_type = types.file;
    dataset.memory_type = types.memory;
  }
  const std::vector<hsize_t> max_dims(dims.size(), H5S_UNLIMITED);
  Hdf5Id space(H5Screate_simple(static_cast<int>(dims.size()), dataset.dims.data(), max_dims.data()), H5Sclose);
  if (!space.valid()) impl.Fail(name, "cannot create dataspace " + ShapeText(dataset.dims));
  std::vector<hsize_t> chunk(dims.size());
  chunk[0] = std::max<hsize_t>(1, rows_per_chunk);
  for (size_t i = 1; i < dims.size(); ++i) chunk[i] = std::max<hsize_t>(1, dims[i]);
  Hdf5Id create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!create.valid() || H5Pset_chunk(create.get(), static_cast<int>(chunk.size()), chunk.data()) < 0) {
    impl.Fail(name, "cannot set chunks " + ShapeText(chunk));
  }
  static const bool deflate = DeflateAvailable();
  if (deflate && (H5Pset_shuffle(create.get()) < 0 || H5Pset_deflate(create.get(), 4) < 0)) {
    impl.Fail(name, "cannot set compression");
  }
  dataset.id = Hdf5Id(
      H5Dcreate2(impl.writer.file(), name.c_str(), file_type, space.get(), H5P_DEFAULT, create.get(), H5P_DEFAULT),
      H5Dclose);
  if (!dataset.id.valid()) impl.Fail(name, "cannot create dataset");
  impl.datasets[name] = std::move(dataset);
}

void Hdf5ArrayWriter::WriteRows(const std::string& name, std::uint64_t first_row, std::uint64_t rows,
                                const void* data) {
  Impl& impl = *impl_;
  const auto it = impl.datasets.find(name);
  if (it == impl.datasets.end()) throw std::logic_error("Hdf5ArrayWriter: no dataset " + name);
  Impl::Dataset& dataset = it->second;
  if (first_row + rows > dataset.dims[0]) {
    throw std::logic_error("Hdf5ArrayWriter: " + name + ": rows past " + std::to_string(dataset.dims[0]));
  }
  if (rows == 0) return;
  bool empty = false;
  for (size_t i = 1; i < dataset.dims.size(); ++i) empty |= dataset.dims[i] == 0;
  if (empty) return;
  Hdf5Id file_space(H5Dget_space(dataset.id.get()), H5Sclose);
  std::vector<hsize_t> start(dataset.dims.size(), 0), count = dataset.dims;
  start[0] = first_row;
  count[0] = rows;
  Hdf5Id memory_space(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), H5Sclose);
  if (!file_space.valid() || !memory_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0 ||
      H5Dwrite(dataset.id.get(), dataset.memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, data) < 0) {
    impl.Fail(name,
              "write of rows " + std::to_string(first_row) + " to " + std::to_string(first_row + rows) + " failed");
  }
}

void Hdf5ArrayWriter::Doubles(const std::string& name, const std::vector<std::uint64_t>& dims,
                              const std::vector<double>& values) {
  Create(name, Type::kFloat64, dims, dims[0]);
  WriteRows(name, 0, dims[0], values.data());
}

void Hdf5ArrayWriter::Int64s(const std::string& name, const std::vector<std::int64_t>& values) {
  Create(name, Type::kInt64, {values.size()}, values.size());
  WriteRows(name, 0, values.size(), values.data());
}

void Hdf5ArrayWriter::Strings(const std::string& name, const std::vector<std::string>& values) {
  std::vector<std::string> valid;
  std::size_t width = 1;
  for (const std::string& value : values) {
    valid.push_back(ValidUtf8(value));
    width = std::max(width, valid.back().size());
  }
  std::vector<char> buffer(values.size() * width, '\0');
  for (size_t i = 0; i < valid.size(); ++i) std::copy(valid[i].begin(), valid[i].end(), buffer.begin() + i * width);
  Create(name, Type::kString, {values.size()}, values.size(), width);
  WriteRows(name, 0, values.size(), buffer.data());
}

void Hdf5ArrayWriter::StringAttribute(const std::string& name, const std::string& value) {
  try {
    impl_->writer.StringAttribute(impl_->writer.file(), "/", name, ValidUtf8(value));
  } catch (const InputError&) {
    impl_->Fail("/", "cannot write attribute " + name);
  }
}

void Hdf5ArrayWriter::Commit() {
  Impl& impl = *impl_;
  impl.datasets.clear();  // closes them
  try {
    impl.writer.Close();
  } catch (const InputError&) {
    impl.Fail("/", "cannot close the file (disk full?)");
  }
  impl.staged.Commit();
}

}  // namespace rpt::io
