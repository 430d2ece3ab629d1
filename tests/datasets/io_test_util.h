// SPDX-License-Identifier: MIT
// Writers used by the datasets/io tests to make their own fixtures at run time: pickle
// opcodes (including numpy's array/dtype patterns), NPY files, ZIP archives and MAT v5
// files. Nothing here is derived from the licensed files in shared/data.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace rpt::test {

using ByteVec = std::vector<std::uint8_t>;

inline void Append(ByteVec& out, const ByteVec& more) { out.insert(out.end(), more.begin(), more.end()); }
inline void AppendStr(ByteVec& out, const std::string& s) { out.insert(out.end(), s.begin(), s.end()); }
inline void AppendLE(ByteVec& out, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
template <typename T>
ByteVec RawOf(const std::vector<T>& values) {
  ByteVec out(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(out.data(), values.data(), out.size());
  return out;
}
inline std::string AsString(const ByteVec& b) { return std::string(b.begin(), b.end()); }

// A fresh directory under the system temp dir, removed at destruction.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("rpt_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path Write(const std::string& name, const ByteVec& bytes) const {
    const auto p = path_ / name;
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return p;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Emits pickle opcodes. Methods return *this for chaining.
class PickleWriter {
 public:
  ByteVec bytes;

  PickleWriter& Op(std::uint8_t op) {
    bytes.push_back(op);
    return *this;
  }
  PickleWriter& Raw(const ByteVec& b) {
    ::rpt::test::Append(bytes, b);
    return *this;
  }
  PickleWriter& Proto(int v) {
    protocol_ = v;
    Op(0x80);
    return Op(static_cast<std::uint8_t>(v));
  }
  PickleWriter& Str(const std::string& s) {
    if (protocol_ >= 4 && s.size() < 256) {
      Op(0x8c);
      Op(static_cast<std::uint8_t>(s.size()));
    } else {
      Op('X');
      AppendLE(bytes, s.size(), 4);
    }
    AppendStr(bytes, s);
    return *this;
  }
  PickleWriter& Bytes(const std::string& s) {
    if (s.size() < 256) {
      Op('C');
      Op(static_cast<std::uint8_t>(s.size()));
    } else {
      Op('B');
      AppendLE(bytes, s.size(), 4);
    }
    AppendStr(bytes, s);
    return *this;
  }
  PickleWriter& Int(std::int64_t v) {
    if (v >= 0 && v < 256) {
      Op('K');
      return Op(static_cast<std::uint8_t>(v));
    }
    if (v >= 0 && v < 65536) {
      Op('M');
      AppendLE(bytes, static_cast<std::uint64_t>(v), 2);
      return *this;
    }
    if (v >= INT32_MIN && v <= INT32_MAX) {
      Op('J');
      AppendLE(bytes, static_cast<std::uint64_t>(v), 4);
      return *this;
    }
    // LONG1 with the minimal two's complement length.
    ByteVec le;
    std::int64_t x = v;
    while (true) {
      le.push_back(static_cast<std::uint8_t>(x & 0xff));
      const std::int64_t rest = x >> 8;
      const bool sign = (le.back() & 0x80) != 0;
      if ((rest == 0 && !sign) || (rest == -1 && sign)) break;
      x = rest;
    }
    Op(0x8a);
    Op(static_cast<std::uint8_t>(le.size()));
    return Raw(le);
  }
  PickleWriter& Float(double d) {
    Op('G');
    const auto bits = std::bit_cast<std::uint64_t>(d);
    for (int i = 7; i >= 0; --i) bytes.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
    return *this;
  }
  PickleWriter& None() { return Op('N'); }
  PickleWriter& Bool(bool b) { return Op(b ? 0x88 : 0x89); }
  PickleWriter& Global(const std::string& module, const std::string& name) {
    Op('c');
    AppendStr(bytes, module + "\n" + name + "\n");
    return *this;
  }
  PickleWriter& Mark() { return Op('('); }
  PickleWriter& Tuple() { return Op('t'); }
  PickleWriter& Tuple1() { return Op(0x85); }
  PickleWriter& Tuple2() { return Op(0x86); }
  PickleWriter& Tuple3() { return Op(0x87); }
  PickleWriter& EmptyTuple() { return Op(')'); }
  PickleWriter& EmptyList() { return Op(']'); }
  PickleWriter& Append() { return Op('a'); }
  PickleWriter& Appends() { return Op('e'); }
  PickleWriter& EmptyDict() { return Op('}'); }
  PickleWriter& SetItem() { return Op('s'); }
  PickleWriter& SetItems() { return Op('u'); }
  PickleWriter& Reduce() { return Op('R'); }
  PickleWriter& Build() { return Op('b'); }
  PickleWriter& Stop() { return Op('.'); }
  PickleWriter& Pop() { return Op('0'); }
  PickleWriter& Put(std::uint32_t i) {
    if (i < 256) {
      Op('q');
      return Op(static_cast<std::uint8_t>(i));
    }
    Op('r');
    AppendLE(bytes, i, 4);
    return *this;
  }
  PickleWriter& Get(std::uint32_t i) {
    if (i < 256) {
      Op('h');
      return Op(static_cast<std::uint8_t>(i));
    }
    Op('j');
    AppendLE(bytes, i, 4);
    return *this;
  }

  // numpy.dtype(spec, False, True) with BUILD state (3, order, None, None, None, elsize, align, flags).
  PickleWriter& DType(const std::string& spec, const std::string& order, std::int64_t elsize = -1,
                      std::int64_t align = -1, std::int64_t flags = 0) {
    Global("numpy", "dtype").Str(spec).Bool(false).Bool(true).Tuple3().Reduce();
    Mark().Int(3).Str(order).None().None().None().Int(elsize).Int(align).Int(flags).Tuple();
    return Build();
  }
  // _reconstruct(ndarray, (0,), b'b'), then MARK 1 — the caller writes shape, dtype,
  // fortran flag and data, then ArrayEnd().
  PickleWriter& ArrayBegin() {
    Global("numpy.core.multiarray", "_reconstruct").Global("numpy", "ndarray").Int(0).Tuple1().Bytes("b").Tuple3().Reduce();
    return Mark().Int(1);
  }
  PickleWriter& ArrayEnd() { return Tuple().Build(); }
  PickleWriter& ShapeTuple(const std::vector<std::int64_t>& shape) {
    Mark();
    for (auto d : shape) Int(d);
    return Tuple();
  }
  // A complete ndarray of a simple dtype.
  PickleWriter& Array(const std::vector<std::int64_t>& shape, const std::string& spec, const std::string& order,
                      bool fortran, const ByteVec& data) {
    ArrayBegin().ShapeTuple(shape).DType(spec, order).Bool(fortran).Bytes(AsString(data));
    return ArrayEnd();
  }

 private:
  int protocol_ = 3;
};

// NPY bytes: magic, version, header padded with spaces to a multiple of 64, data.
inline ByteVec NpyBytes(const std::string& header_dict, const ByteVec& data, int major = 1) {
  ByteVec out = {0x93, 'N', 'U', 'M', 'P', 'Y', static_cast<std::uint8_t>(major), 0};
  const std::size_t prefix = major == 1 ? 10 : 12;
  std::string header = header_dict;
  while ((prefix + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  AppendLE(out, header.size(), major == 1 ? 2 : 4);
  AppendStr(out, header);
  Append(out, data);
  return out;
}

inline ByteVec RawDeflate(const ByteVec& in) {
  z_stream s{};
  deflateInit2(&s, Z_BEST_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  ByteVec out(deflateBound(&s, in.size()) + 16);
  s.next_in = const_cast<Bytef*>(in.data());
  s.avail_in = static_cast<uInt>(in.size());
  s.next_out = out.data();
  s.avail_out = static_cast<uInt>(out.size());
  deflate(&s, Z_FINISH);
  out.resize(s.total_out);
  deflateEnd(&s);
  return out;
}

inline ByteVec ZlibCompress(const ByteVec& in) {
  uLongf n = compressBound(in.size());
  ByteVec out(n);
  compress2(out.data(), &n, in.data(), in.size(), 6);
  out.resize(n);
  return out;
}

struct ZipMember {
  std::string name;
  ByteVec data;
  bool deflate = false;
  bool zip64_local_extra = false;  // what numpy's savez writes into local headers
};

inline ByteVec ZipBytes(const std::vector<ZipMember>& members) {
  ByteVec out, central;
  for (const auto& m : members) {
    const ByteVec payload = m.deflate ? RawDeflate(m.data) : m.data;
    const auto crc = static_cast<std::uint32_t>(crc32(0L, m.data.data(), static_cast<uInt>(m.data.size())));
    const std::size_t local_offset = out.size();
    ByteVec extra;
    if (m.zip64_local_extra) {
      AppendLE(extra, 1, 2);
      AppendLE(extra, 16, 2);
      AppendLE(extra, m.data.size(), 8);
      AppendLE(extra, payload.size(), 8);
    }
    AppendLE(out, 0x04034b50, 4);
    AppendLE(out, m.zip64_local_extra ? 45 : 20, 2);
    AppendLE(out, 0, 2);
    AppendLE(out, m.deflate ? 8 : 0, 2);
    AppendLE(out, 0, 4);  // time, date
    AppendLE(out, crc, 4);
    AppendLE(out, payload.size(), 4);
    AppendLE(out, m.data.size(), 4);
    AppendLE(out, m.name.size(), 2);
    AppendLE(out, extra.size(), 2);
    AppendStr(out, m.name);
    Append(out, extra);
    Append(out, payload);

    AppendLE(central, 0x02014b50, 4);
    AppendLE(central, 20, 2);
    AppendLE(central, 20, 2);
    AppendLE(central, 0, 2);
    AppendLE(central, m.deflate ? 8 : 0, 2);
    AppendLE(central, 0, 4);
    AppendLE(central, crc, 4);
    AppendLE(central, payload.size(), 4);
    AppendLE(central, m.data.size(), 4);
    AppendLE(central, m.name.size(), 2);
    AppendLE(central, 0, 2);  // extra
    AppendLE(central, 0, 2);  // comment
    AppendLE(central, 0, 2);  // disk
    AppendLE(central, 0, 2);  // internal attributes
    AppendLE(central, 0, 4);  // external attributes
    AppendLE(central, local_offset, 4);
    AppendStr(central, m.name);
  }
  const std::size_t cd_offset = out.size();
  Append(out, central);
  AppendLE(out, 0x06054b50, 4);
  AppendLE(out, 0, 2);
  AppendLE(out, 0, 2);
  AppendLE(out, members.size(), 2);
  AppendLE(out, members.size(), 2);
  AppendLE(out, central.size(), 4);
  AppendLE(out, cd_offset, 4);
  AppendLE(out, 0, 2);
  return out;
}

// MAT v5 building blocks.
namespace mat {

enum : std::uint32_t { kInt8 = 1, kUInt8 = 2, kInt16 = 3, kUInt16 = 4, kInt32 = 5, kUInt32 = 6, kDouble = 9, kMatrix = 14, kCompressed = 15, kUtf16 = 17 };
enum : std::uint32_t { kCellClass = 1, kStructClass = 2, kCharClass = 4, kDoubleClass = 6, kUInt8Class = 9, kInt16Class = 10, kUInt16Class = 11 };

inline ByteVec Header(const std::string& text = "MATLAB 5.0 MAT-file, written by the rpt io tests") {
  ByteVec h(128, ' ');
  std::memcpy(h.data(), text.data(), std::min<std::size_t>(text.size(), 116));
  std::fill(h.begin() + 116, h.begin() + 124, 0);
  h[124] = 0x00;
  h[125] = 0x01;
  h[126] = 'I';
  h[127] = 'M';
  return h;
}

// A data element, padded to 8 bytes (small format when requested and data fits in 4 bytes).
inline ByteVec Element(std::uint32_t type, const ByteVec& data, bool small = false) {
  ByteVec out;
  if (small && data.size() <= 4) {
    AppendLE(out, (static_cast<std::uint64_t>(data.size()) << 16) | type, 4);
    Append(out, data);
    out.resize(8, 0);
    return out;
  }
  AppendLE(out, type, 4);
  AppendLE(out, data.size(), 4);
  Append(out, data);
  while (out.size() % 8) out.push_back(0);
  return out;
}

inline ByteVec Matrix(std::uint32_t mat_class, const std::vector<std::int32_t>& dims, const std::string& name,
                      const ByteVec& body, std::uint32_t flag_bits = 0) {
  ByteVec content;
  ByteVec flags;
  AppendLE(flags, mat_class | flag_bits, 4);
  AppendLE(flags, 0, 4);
  Append(content, Element(kUInt32, flags));
  ByteVec d;
  for (auto x : dims) AppendLE(d, static_cast<std::uint32_t>(x), 4);
  Append(content, Element(kInt32, d));
  Append(content, Element(kInt8, ByteVec(name.begin(), name.end()), /*small=*/true));
  Append(content, body);
  return Element(kMatrix, content);
}

inline ByteVec Compressed(const ByteVec& matrix_element) {
  const ByteVec z = ZlibCompress(matrix_element);
  ByteVec out;
  AppendLE(out, kCompressed, 4);
  AppendLE(out, z.size(), 4);
  Append(out, z);
  return out;
}

inline ByteVec Doubles(const std::vector<double>& v) { return Element(kDouble, RawOf(v)); }

}  // namespace mat

}  // namespace rpt::test
