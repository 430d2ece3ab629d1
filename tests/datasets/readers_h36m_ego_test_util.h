// SPDX-License-Identifier: MIT
// Fixture writers for the Human3.6M / H3WB / EgoHumans reader tests: a small Python object tree
// emitted as pickle (dicts, lists, tuples, numpy arrays including structured dtypes), np.save-style
// object .npy files, HDF5 datasets and Human3.6M metadata.xml <w0> blocks. Everything is written at
// run time into temporary directories; nothing is derived from licensed data.
#pragma once

#include <gtest/gtest.h>
#include <hdf5.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "core/errors.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt::test {

// ---------------------------------------------------------------------------------------
// Python objects -> pickle

struct StructField {
  std::string name;
  std::string spec;                 // "f4", "f8", "i1", "i2", "i8"
  std::vector<std::int64_t> shape;  // empty = scalar
};

struct Obj {
  enum class Kind { kNone, kInt, kFloat, kStr, kList, kTuple, kDict, kArray, kStructArray };
  Kind kind = Kind::kNone;
  std::int64_t i = 0;
  double f = 0;
  std::string s;
  std::vector<Obj> items;  // list / tuple; dict: key, value, key, value, ...
  std::vector<std::int64_t> shape;
  std::string spec = "f8";
  ByteVec data;
  std::vector<StructField> fields;
};

inline std::size_t SpecSize(const std::string& spec) { return static_cast<std::size_t>(std::stoi(spec.substr(1))); }
inline std::string SpecOrder(const std::string& spec) { return SpecSize(spec) == 1 ? "|" : "<"; }

// Appends `value` converted to `spec` (little endian).
inline void AppendAs(ByteVec& out, const std::string& spec, double value) {
  if (spec == "f8") {
    Append(out, RawOf(std::vector<double>{value}));
  } else if (spec == "f4") {
    Append(out, RawOf(std::vector<float>{static_cast<float>(value)}));
  } else if (spec == "i8") {
    Append(out, RawOf(std::vector<std::int64_t>{static_cast<std::int64_t>(value)}));
  } else if (spec == "i4") {
    Append(out, RawOf(std::vector<std::int32_t>{static_cast<std::int32_t>(value)}));
  } else if (spec == "i2") {
    Append(out, RawOf(std::vector<std::int16_t>{static_cast<std::int16_t>(value)}));
  } else if (spec == "i1") {
    Append(out, RawOf(std::vector<std::int8_t>{static_cast<std::int8_t>(value)}));
  } else {
    ADD_FAILURE() << "unsupported spec " << spec;
  }
}

inline Obj PyNone() { return Obj{}; }
inline Obj PyInt(std::int64_t v) {
  Obj o;
  o.kind = Obj::Kind::kInt;
  o.i = v;
  return o;
}
inline Obj PyFloat(double v) {
  Obj o;
  o.kind = Obj::Kind::kFloat;
  o.f = v;
  return o;
}
inline Obj PyStr(std::string v) {
  Obj o;
  o.kind = Obj::Kind::kStr;
  o.s = std::move(v);
  return o;
}
inline Obj PyList(std::vector<Obj> items) {
  Obj o;
  o.kind = Obj::Kind::kList;
  o.items = std::move(items);
  return o;
}
inline Obj PyTuple(std::vector<Obj> items) {
  Obj o;
  o.kind = Obj::Kind::kTuple;
  o.items = std::move(items);
  return o;
}
inline Obj PyDict(std::vector<std::pair<Obj, Obj>> entries) {
  Obj o;
  o.kind = Obj::Kind::kDict;
  for (auto& [k, v] : entries) {
    o.items.push_back(std::move(k));
    o.items.push_back(std::move(v));
  }
  return o;
}
// A numpy array of `spec` with row-major `values`.
inline Obj PyArray(std::vector<std::int64_t> shape, const std::vector<double>& values, const std::string& spec = "f8") {
  Obj o;
  o.kind = Obj::Kind::kArray;
  o.shape = std::move(shape);
  o.spec = spec;
  for (double v : values) AppendAs(o.data, spec, v);
  return o;
}
// A structured array; `records` holds the packed record bytes (see AppendAs).
inline Obj PyStructArray(std::vector<std::int64_t> shape, std::vector<StructField> fields, ByteVec records) {
  Obj o;
  o.kind = Obj::Kind::kStructArray;
  o.shape = std::move(shape);
  o.fields = std::move(fields);
  o.data = std::move(records);
  return o;
}

inline std::size_t FieldBytes(const StructField& f) {
  std::size_t n = SpecSize(f.spec);
  for (auto d : f.shape) n *= static_cast<std::size_t>(d);
  return n;
}

inline void EmitStructDType(PickleWriter& w, const std::vector<StructField>& fields) {
  std::size_t item_size = 0;
  for (const auto& f : fields) item_size += FieldBytes(f);
  w.Global("numpy", "dtype").Str("V" + std::to_string(item_size)).Bool(false).Bool(true).Tuple3().Reduce();
  w.Mark().Int(3).Str("|").None();
  w.Mark();
  for (const auto& f : fields) w.Str(f.name);
  w.Tuple();
  w.EmptyDict().Mark();
  std::size_t offset = 0;
  for (const auto& f : fields) {
    w.Str(f.name);
    if (f.shape.empty()) {
      w.DType(f.spec, SpecOrder(f.spec));
    } else {
      const std::size_t bytes = FieldBytes(f);
      w.Global("numpy", "dtype").Str("V" + std::to_string(bytes)).Bool(false).Bool(true).Tuple3().Reduce();
      w.Mark().Int(3).Str("|");
      w.DType(f.spec, SpecOrder(f.spec)).ShapeTuple(f.shape).Tuple2();
      w.None().None().Int(static_cast<std::int64_t>(bytes)).Int(static_cast<std::int64_t>(SpecSize(f.spec))).Int(0).Tuple().Build();
    }
    w.Int(static_cast<std::int64_t>(offset)).Tuple2();
    offset += FieldBytes(f);
  }
  w.SetItems();
  w.Int(static_cast<std::int64_t>(item_size)).Int(1).Int(16).Tuple().Build();
}

inline void Emit(PickleWriter& w, const Obj& o) {
  switch (o.kind) {
    case Obj::Kind::kNone: w.None(); break;
    case Obj::Kind::kInt: w.Int(o.i); break;
    case Obj::Kind::kFloat: w.Float(o.f); break;
    case Obj::Kind::kStr: w.Str(o.s); break;
    case Obj::Kind::kList:
      w.EmptyList();
      if (!o.items.empty()) {
        w.Mark();
        for (const Obj& item : o.items) Emit(w, item);
        w.Appends();
      }
      break;
    case Obj::Kind::kTuple:
      w.Mark();
      for (const Obj& item : o.items) Emit(w, item);
      w.Tuple();
      break;
    case Obj::Kind::kDict:
      w.EmptyDict();
      if (!o.items.empty()) {
        w.Mark();
        for (const Obj& item : o.items) Emit(w, item);
        w.SetItems();
      }
      break;
    case Obj::Kind::kArray: w.Array(o.shape, o.spec, SpecOrder(o.spec), false, o.data); break;
    case Obj::Kind::kStructArray:
      w.ArrayBegin().ShapeTuple(o.shape);
      EmitStructDType(w, o.fields);
      w.Bool(false).Bytes(AsString(o.data)).ArrayEnd();
      break;
  }
}

// pickle.dump(obj, protocol=3)
inline ByteVec PickleOf(const Obj& o) {
  PickleWriter w;
  w.Proto(3);
  Emit(w, o);
  w.Stop();
  return w.bytes;
}

// np.save(path, obj) of a dict: a 0-d object array whose pickle holds the array itself.
inline ByteVec NpyOfObject(const Obj& o) {
  PickleWriter w;
  w.Proto(3).ArrayBegin().ShapeTuple({}).DType("O8", "|", -1, -1, 63).Bool(false).EmptyList().Mark();
  Emit(w, o);
  w.Appends().ArrayEnd().Stop();
  return NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (), }", w.bytes);
}

// np.save(path, list_of_dicts): a 1-d object array (an empty list becomes a float64 (0,) array).
inline ByteVec NpyOfObjectList(const std::vector<Obj>& items) {
  if (items.empty()) return NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (0,), }", {});
  PickleWriter w;
  w.Proto(3).ArrayBegin().ShapeTuple({static_cast<std::int64_t>(items.size())}).DType("O8", "|", -1, -1, 63).Bool(false).EmptyList().Mark();
  for (const Obj& item : items) Emit(w, item);
  w.Appends().ArrayEnd().Stop();
  return NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (" + std::to_string(items.size()) + ",), }", w.bytes);
}

// ---------------------------------------------------------------------------------------
// Files

inline void WriteBytes(const std::filesystem::path& path, const ByteVec& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string Num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

// `v` with `digits` significant digits.
inline std::string NumDigits(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

struct H5Item {
  std::string name;  // e.g. "pose/3d"
  std::vector<hsize_t> dims;
  std::vector<double> values;
  bool integer = false;  // stored as int64
};

inline void WriteH5(const std::filesystem::path& path, const std::vector<H5Item>& items) {
  std::filesystem::create_directories(path.parent_path());
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  for (const H5Item& item : items) {
    const hid_t space = H5Screate_simple(static_cast<int>(item.dims.size()), item.dims.data(), nullptr);
    const hid_t type = item.integer ? H5T_STD_I64LE : H5T_IEEE_F64LE;
    const hid_t dataset = H5Dcreate2(file, item.name.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
    if (item.integer) {
      std::vector<std::int64_t> ints(item.values.begin(), item.values.end());
      H5Dwrite(dataset, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, ints.data());
    } else {
      H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, item.values.data());
    }
    H5Dclose(dataset);
    H5Sclose(space);
  }
  H5Pclose(lcpl);
  H5Fclose(file);
}

// ---------------------------------------------------------------------------------------
// Human3.6M calibration helpers

// Angles (a, b, c) with R = Rx(a) Ry(b) Rz(c) (the metadata.xml convention).
inline Eigen::Vector3d AnglesXYZ(const Eigen::Matrix3d& R) {
  return Eigen::Vector3d(std::atan2(-R(1, 2), R(2, 2)), std::asin(std::clamp(R(0, 2), -1.0, 1.0)), std::atan2(-R(0, 1), R(0, 0)));
}

inline Eigen::Matrix3d RotationXYZ(const Eigen::Vector3d& a) {
  auto rx = [](double t) {
    Eigen::Matrix3d m;
    m << 1, 0, 0, 0, std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t);
    return m;
  };
  auto ry = [](double t) {
    Eigen::Matrix3d m;
    m << std::cos(t), 0, std::sin(t), 0, 1, 0, -std::sin(t), 0, std::cos(t);
    return m;
  };
  auto rz = [](double t) {
    Eigen::Matrix3d m;
    m << std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t), 0, 0, 0, 1;
    return m;
  };
  return rx(a.x()) * ry(a.y()) * rz(a.z());
}

// world->camera rotation of a camera at `center` looking at `target` (x right, y down, z forward;
// world z up).
inline Eigen::Matrix3d LookAt(const Eigen::Vector3d& center, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return R;
}

// One Human3.6M-like calibration entry as metadata.xml stores it.
struct H36mCalib {
  Eigen::Vector3d angles;     // rx ry rz
  Eigen::Vector3d center_mm;  // camera centre
  double fx, fy, cx, cy, k1, k2, k3, p1, p2;
  Eigen::Matrix3d R() const { return RotationXYZ(angles); }  // world -> camera
};

// Four cameras around the origin for `subject_number` (1..11), slightly different per subject.
inline std::vector<H36mCalib> SyntheticH36mCalibs(int subject_number) {
  std::vector<H36mCalib> out;
  const double s = 0.05 * subject_number;
  const Eigen::Vector3d centers[4] = {{1841.1 + 40 * subject_number, 4955.3, 1563.4}, {1761.3, -5078.0 - 30 * subject_number, 1606.3},
                                      {-1846.8, 5215.0, 1492.0 + 20 * subject_number}, {-1794.8, -3722.7 + 25 * subject_number, 1574.9}};
  for (int c = 0; c < 4; ++c) {
    H36mCalib k;
    k.center_mm = centers[c];
    k.angles = AnglesXYZ(LookAt(centers[c] / 1000.0, Eigen::Vector3d(0.1 * c, -0.05, 0.9 + s)));
    k.fx = 1145.0 + c;
    k.fy = 1143.8 + c;
    k.cx = 512.5 - c;
    k.cy = 515.5 + c;
    k.k1 = -0.2071 + 0.001 * c;
    k.k2 = 0.2478;
    k.k3 = -0.0031;
    k.p1 = -0.0014;
    k.p2 = -0.00098 + 0.0001 * c;
    out.push_back(k);
  }
  return out;
}

// The 300-number <w0> block from calibrations of subjects 1..11 (`calib(s)` = 4 entries) and the
// intrinsics of subject 1 (metadata.xml stores intrinsics per camera only).
inline std::vector<double> W0(const std::function<std::vector<H36mCalib>(int)>& calib) {
  std::vector<double> w0(300, 0.0);
  for (int s = 1; s <= 11; ++s) {
    const auto entries = calib(s);
    for (int c = 0; c < 4; ++c) {
      const H36mCalib& k = entries[static_cast<std::size_t>(c)];
      const std::size_t o = static_cast<std::size_t>(6 * (c * 11 + (s - 1)));
      for (int i = 0; i < 3; ++i) w0[o + static_cast<std::size_t>(i)] = k.angles[i];
      for (int i = 0; i < 3; ++i) w0[o + 3 + static_cast<std::size_t>(i)] = k.center_mm[i];
    }
  }
  const auto first = calib(1);
  for (int c = 0; c < 4; ++c) {
    const H36mCalib& k = first[static_cast<std::size_t>(c)];
    const double intr[9] = {k.fx, k.fy, k.cx, k.cy, k.k1, k.k2, k.k3, k.p1, k.p2};
    for (int i = 0; i < 9; ++i) w0[static_cast<std::size_t>(264 + 9 * c + i)] = intr[i];
  }
  return w0;
}

inline std::string MetadataXml(const std::vector<double>& w0) {
  std::string text = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<metadata>\n  <mapping><tr><td>x</td></tr></mapping>\n  <w0>[";
  for (std::size_t i = 0; i < w0.size(); ++i) {
    if (i) text += " ";
    text += Num(w0[i]);
  }
  text += "]</w0>\n</metadata>\n";
  return text;
}


}  // namespace rpt::test
