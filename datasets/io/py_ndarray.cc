// SPDX-License-Identifier: MIT
// numpy dtypes and ndarrays of io::PyValue (datasets/io/py_value.h): parsing dtype descriptions,
// element access with byte order, structured-array fields.
#include "datasets/io/py_value.h"

#include "datasets/io/binary.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::io {
namespace {

// IEEE half -> double (numpy float16).
double HalfToDouble(std::uint16_t h) {
  const int sign = (h >> 15) & 1;
  const int exponent = (h >> 10) & 0x1f;
  const int mantissa = h & 0x3ff;
  double value;
  if (exponent == 0) {
    value = std::ldexp(static_cast<double>(mantissa), -24);
  } else if (exponent == 31) {
    value = mantissa == 0 ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
  } else {
    value = std::ldexp(static_cast<double>(mantissa + 1024), exponent - 25);
  }
  return sign ? -value : value;
}

// Loads an n-byte unsigned integer honouring the dtype's byte order.
std::uint64_t LoadUnsigned(const std::uint8_t* p, std::size_t n, bool big_endian) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = big_endian ? i : n - 1 - i;
    v = (v << 8) | p[k];
  }
  return v;
}


std::size_t ShapeProduct(std::span<const std::int64_t> shape) {
  std::size_t n = 1;
  for (auto d : shape) {
    std::size_t out;
    if (d < 0 || __builtin_mul_overflow(n, static_cast<std::size_t>(d), &out)) return std::numeric_limits<std::size_t>::max();
    n = out;
  }
  return n;
}

}  // namespace

std::string ShapeToString(std::span<const std::int64_t> shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    if (i) s += ", ";
    s += shape[i] < 0 ? std::string("N") : std::to_string(shape[i]);
  }
  if (shape.size() == 1) s += ",";
  return s + ")";
}

// ---------------------------------------------------------------------------------------
// DType

bool DType::IsStructured() const { return !fields.empty(); }

bool DType::IsRealNumeric() const {
  if (IsStructured() || subarray_base) return false;
  switch (kind) {
    case 'b': return item_size == 1;
    case 'i':
    case 'u': return item_size == 1 || item_size == 2 || item_size == 4 || item_size == 8;
    case 'f': return item_size == 2 || item_size == 4 || item_size == 8;
    default: return false;
  }
}

std::string DType::Str() const {
  if (kind == 'O') return "|O";
  std::string s(1, byte_order);
  s += kind;
  s += std::to_string(kind == 'U' ? item_size / 4 : item_size);
  return s;
}

const DTypeField* DType::FindField(std::string_view name) const {
  for (const auto& f : fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::size_t DTypeField::ElementCount() const { return ShapeProduct(shape); }

std::optional<DType> ParseTypeStr(std::string_view s) {
  if (s.empty()) return std::nullopt;
  char order = '=';
  if (s[0] == '<' || s[0] == '>' || s[0] == '|' || s[0] == '=') {
    order = s[0];
    s.remove_prefix(1);
  }
  if (s.empty()) return std::nullopt;
  const char code = s[0];
  s.remove_prefix(1);
  bool has_size = false;
  std::size_t n = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    has_size = true;
    n = n * 10 + static_cast<std::size_t>(c - '0');
    if (n > (std::size_t{1} << 40)) return std::nullopt;
  }
  DType t;
  switch (code) {
    case '?':
      if (has_size && n != 1) return std::nullopt;
      t.kind = 'b';
      t.item_size = 1;
      break;
    case 'b':
      // 'b1' is bool; a bare 'b' would be numpy's int8 typecode: refuse the ambiguity.
      if (!has_size || n != 1) return std::nullopt;
      t.kind = 'b';
      t.item_size = 1;
      break;
    case 'i':
    case 'u':
      if (!has_size || (n != 1 && n != 2 && n != 4 && n != 8)) return std::nullopt;
      t.kind = code;
      t.item_size = n;
      break;
    case 'f':
      if (!has_size || (n != 2 && n != 4 && n != 8 && n != 16)) return std::nullopt;
      t.kind = 'f';
      t.item_size = n;
      break;
    case 'c':
      if (!has_size || (n != 8 && n != 16 && n != 32)) return std::nullopt;
      t.kind = 'c';
      t.item_size = n;
      break;
    case 'O':
      if (has_size && n != 8 && n != 4) return std::nullopt;
      t.kind = 'O';
      t.item_size = 8;
      break;
    case 'U':
      t.kind = 'U';
      t.item_size = n * 4;
      break;
    case 'S':
    case 'a':
      t.kind = 'S';
      t.item_size = n;
      break;
    case 'V':
      t.kind = 'V';
      t.item_size = n;
      break;
    default: return std::nullopt;
  }
  const bool order_free = t.item_size <= 1 || t.kind == 'S' || t.kind == 'V' || t.kind == 'O' || t.kind == 'b';
  if (order_free) {
    t.byte_order = '|';
  } else {
    // '=' and '|' mean native; this project only targets little-endian hosts.
    t.byte_order = order == '>' ? '>' : '<';
  }
  return t;
}

// ---------------------------------------------------------------------------------------
// NdArray

std::size_t NdArray::Size() const { return ShapeProduct(shape); }

std::string NdArray::ShapeStr() const { return ShapeToString(shape); }

std::string NdArray::Describe() const { return "ndarray " + dtype.Str() + " " + ShapeStr(); }

std::size_t NdArray::StorageIndex(std::size_t c_index) const {
  if (!fortran_order || shape.size() <= 1) return c_index;
  // Decompose the row-major index, then recompose with column-major strides.
  std::size_t rest = c_index;
  std::size_t index = 0;
  std::size_t stride_f = 1;
  std::vector<std::size_t> multi(shape.size());
  for (std::size_t k = shape.size(); k-- > 0;) {
    const auto extent = static_cast<std::size_t>(shape[k]);
    multi[k] = extent ? rest % extent : 0;
    rest = extent ? rest / extent : 0;
  }
  for (std::size_t k = 0; k < shape.size(); ++k) {
    index += multi[k] * stride_f;
    stride_f *= static_cast<std::size_t>(shape[k]);
  }
  return index;
}

double NdArray::ElementAsDouble(std::size_t i) const {
  if (i >= Size()) throw InputError(Describe() + ": element " + std::to_string(i) + " out of range");
  if (dtype.kind == 'O') {
    const PyValue& v = *objects.at(i);
    if (v.kind == PyKind::kFloat) return v.float_value;
    if (v.kind == PyKind::kInt) return static_cast<double>(v.int_value);
    if (v.kind == PyKind::kBool) return v.bool_value ? 1.0 : 0.0;
    throw InputError(Describe() + ": object element " + std::to_string(i) + " is " + PyKindName(v.kind) + ", not a number");
  }
  if (!dtype.IsRealNumeric()) throw InputError(Describe() + ": dtype " + dtype.Str() + " is not a real numeric type");
  const std::size_t n = dtype.item_size;
  if ((i + 1) * n > data.size()) throw InputError(Describe() + ": data buffer too short");
  const std::uint8_t* p = data.data() + i * n;
  const bool big = dtype.byte_order == '>';
  const std::uint64_t bits = LoadUnsigned(p, n, big);
  switch (dtype.kind) {
    case 'b': return bits ? 1.0 : 0.0;
    case 'u': return static_cast<double>(bits);
    case 'i': {
      const unsigned shift = static_cast<unsigned>(64 - 8 * n);
      return static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
    }
    case 'f':
      if (n == 2) return HalfToDouble(static_cast<std::uint16_t>(bits));
      if (n == 4) return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
      return std::bit_cast<double>(bits);
    default: break;
  }
  throw InputError(Describe() + ": unsupported dtype");
}

std::int64_t NdArray::ElementAsInt(std::size_t i) const {
  if (i >= Size()) throw InputError(Describe() + ": element " + std::to_string(i) + " out of range");
  if (dtype.kind == 'O') {
    const PyValue& v = *objects.at(i);
    if (v.kind == PyKind::kInt) return v.int_value;
    if (v.kind == PyKind::kBool) return v.bool_value;
    throw InputError(Describe() + ": object element " + std::to_string(i) + " is " + PyKindName(v.kind) + ", not an integer");
  }
  if (!(dtype.kind == 'i' || dtype.kind == 'u' || dtype.kind == 'b') || !dtype.IsRealNumeric()) {
    throw InputError(Describe() + ": dtype " + dtype.Str() + " is not an integer type");
  }
  const std::size_t n = dtype.item_size;
  if ((i + 1) * n > data.size()) throw InputError(Describe() + ": data buffer too short");
  const std::uint64_t bits = LoadUnsigned(data.data() + i * n, n, dtype.byte_order == '>');
  if (dtype.kind == 'i') {
    const unsigned shift = static_cast<unsigned>(64 - 8 * n);
    return static_cast<std::int64_t>(bits << shift) >> shift;
  }
  if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    throw InputError(Describe() + ": element " + std::to_string(i) + " does not fit in int64");
  }
  return static_cast<std::int64_t>(bits);
}

std::string NdArray::ElementAsString(std::size_t i) const {
  if (i >= Size()) throw InputError(Describe() + ": element " + std::to_string(i) + " out of range");
  if (dtype.kind == 'O') {
    const PyValue& v = *objects.at(i);
    if (v.kind == PyKind::kStr || v.kind == PyKind::kBytes) return v.text;
    throw InputError(Describe() + ": object element " + std::to_string(i) + " is " + PyKindName(v.kind) + ", not a string");
  }
  const std::size_t n = dtype.item_size;
  if ((dtype.kind != 'U' && dtype.kind != 'S') || dtype.IsStructured()) {
    throw InputError(Describe() + ": dtype " + dtype.Str() + " is not a string type");
  }
  if ((i + 1) * n > data.size()) throw InputError(Describe() + ": data buffer too short");
  const std::uint8_t* p = data.data() + i * n;
  std::string out;
  if (dtype.kind == 'S') {
    out.assign(reinterpret_cast<const char*>(p), n);
  } else {
    for (std::size_t k = 0; k + 4 <= n; k += 4) {
      detail::AppendUtf8(out, static_cast<std::uint32_t>(LoadUnsigned(p + k, 4, dtype.byte_order == '>')));
    }
  }
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

std::vector<double> NdArray::ToDoubles() const {
  const std::size_t n = Size();
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(ElementAsDouble(StorageIndex(i)));
  return out;
}

NdArray NdArray::Field(std::string_view name) const {
  const DTypeField* field = dtype.FindField(name);
  if (!field) throw InputError(Describe() + ": no field " + QuoteName(std::string(name)));
  NdArray out;
  out.dtype = field->dtype;
  out.shape = shape;
  out.shape.insert(out.shape.end(), field->shape.begin(), field->shape.end());
  const std::size_t records = Size();
  const std::size_t field_bytes = field->dtype.item_size * field->ElementCount();
  if (field->offset + field_bytes > dtype.item_size || records * dtype.item_size > data.size()) {
    throw InputError(Describe() + ": field " + QuoteName(std::string(name)) + " lies outside the record");
  }
  out.data.resize(records * field_bytes);
  for (std::size_t r = 0; r < records; ++r) {
    const std::size_t s = StorageIndex(r);
    std::memcpy(out.data.data() + r * field_bytes, data.data() + s * dtype.item_size + field->offset, field_bytes);
  }
  return out;
}


}  // namespace rpt::io
