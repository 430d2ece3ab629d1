// SPDX-License-Identifier: MIT
// Slightly over 500 lines on purpose: one MAT v5 parser (tags, compressed elements, numeric,
// char, cell and struct arrays, and the MatValue accessors whose errors name the element path).
#include "datasets/io/mat.h"

#include <bit>
#include <cstring>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/binary.h"

namespace rpt::io {
namespace {

using detail::Bytes;
using detail::LoadU16;
using detail::LoadU32;
using detail::LoadU64;

constexpr std::size_t kMaxMatDepth = 64;

enum MiType : std::uint32_t {
  miINT8 = 1,
  miUINT8 = 2,
  miINT16 = 3,
  miUINT16 = 4,
  miINT32 = 5,
  miUINT32 = 6,
  miSINGLE = 7,
  miDOUBLE = 9,
  miINT64 = 12,
  miUINT64 = 13,
  miMATRIX = 14,
  miCOMPRESSED = 15,
  miUTF8 = 16,
  miUTF16 = 17,
  miUTF32 = 18,
};

std::size_t MiSize(std::uint32_t type) {
  switch (type) {
    case miINT8:
    case miUINT8:
    case miUTF8: return 1;
    case miINT16:
    case miUINT16:
    case miUTF16: return 2;
    case miINT32:
    case miUINT32:
    case miSINGLE:
    case miUTF32: return 4;
    case miDOUBLE:
    case miINT64:
    case miUINT64: return 8;
    default: return 0;
  }
}

double MiValue(std::uint32_t type, const std::uint8_t* p) {
  switch (type) {
    case miINT8: return static_cast<std::int8_t>(p[0]);
    case miUINT8: return p[0];
    case miINT16: return static_cast<std::int16_t>(LoadU16(p));
    case miUINT16: return LoadU16(p);
    case miINT32: return static_cast<std::int32_t>(LoadU32(p));
    case miUINT32: return LoadU32(p);
    case miSINGLE: return std::bit_cast<float>(LoadU32(p));
    case miDOUBLE: return std::bit_cast<double>(LoadU64(p));
    case miINT64: return static_cast<double>(static_cast<std::int64_t>(LoadU64(p)));
    case miUINT64: return static_cast<double>(LoadU64(p));
    default: return 0.0;
  }
}

struct Element {
  std::uint32_t type = 0;
  Bytes data;
  std::size_t next = 0;  // offset of the following element in the same buffer
};

// A buffer being parsed: either a slice of the file or an inflated variable.
struct Buffer {
  Bytes bytes;
  std::string source;
  std::size_t file_offset = 0;  // offset of bytes[0] in the file (uncompressed buffers)
  bool inflated = false;

  std::string At(std::size_t pos) const {
    if (inflated) return "byte " + std::to_string(pos) + " of the inflated variable";
    return "byte " + std::to_string(file_offset + pos);
  }
};

class MatParser {
 public:
  explicit MatParser(std::string source) : source_(std::move(source)) {}

  // Reads the data element starting at `pos` of `buf` (bounds-checked).
  Element ReadElement(const Buffer& buf, std::size_t pos, const std::string& where) const {
    const Bytes b = buf.bytes;
    if (pos > b.size() || b.size() - pos < 8) {
      throw InputError(where + ": truncated data element tag at " + buf.At(pos));
    }
    const std::uint32_t w0 = LoadU32(b.data() + pos);
    Element e;
    if (w0 >> 16) {
      // Small data element: type and size share the first word, data in the second.
      e.type = w0 & 0xFFFF;
      const std::size_t size = w0 >> 16;
      if (size > 4) throw InputError(where + ": corrupt small data element at " + buf.At(pos));
      e.data = b.subspan(pos + 4, size);
      e.next = pos + 8;
      return e;
    }
    e.type = w0;
    const std::size_t size = LoadU32(b.data() + pos + 4);
    if (size > b.size() - pos - 8) {
      throw InputError(where + ": truncated data element at " + buf.At(pos) + " (needs " + std::to_string(size) +
                       " bytes, only " + std::to_string(b.size() - pos - 8) + " left)");
    }
    e.data = b.subspan(pos + 8, size);
    // Sub-elements are padded to 8 bytes; tolerate a missing final pad.
    const std::size_t padded = (size + 7) / 8 * 8;
    e.next = std::min(b.size(), pos + 8 + padded);
    return e;
  }

  // Parses the content of a miMATRIX element. `where` is empty for a top-level variable
  // (then named after the array name stored in it).
  MatValue ParseMatrix(const Buffer& buf, std::size_t begin, std::size_t end, std::string where, std::size_t depth) const {
    const std::string provisional = where.empty() ? source_ + ": variable at " + buf.At(begin) : where;
    if (depth > kMaxMatDepth) throw InputError(provisional + ": cells/structs nest deeper than " + std::to_string(kMaxMatDepth) + " levels");
    MatValue v;
    v.where = provisional;
    if (begin == end) {  // an empty miMATRIX element is an empty 0x0 double
      v.dims = {0, 0};
      return v;
    }
    Buffer sub{buf.bytes.first(end), buf.source, buf.file_offset, buf.inflated};
    std::size_t pos = begin;

    const Element flags = ReadElement(sub, pos, provisional);
    if (flags.type != miUINT32 || flags.data.size() != 8) throw InputError(provisional + ": bad array flags at " + buf.At(pos));
    const std::uint32_t f = LoadU32(flags.data.data());
    v.mat_class = static_cast<MatClass>(f & 0xFF);
    v.complex = (f & 0x0800) != 0;
    v.logical = (f & 0x0200) != 0;
    pos = flags.next;

    const Element dims = ReadElement(sub, pos, provisional);
    if (dims.type != miINT32 || dims.data.size() % 4 != 0 || dims.data.size() < 8) {
      throw InputError(provisional + ": bad dimensions element at " + buf.At(pos));
    }
    std::size_t count = 1;
    for (std::size_t k = 0; k < dims.data.size(); k += 4) {
      const std::int32_t d = static_cast<std::int32_t>(LoadU32(dims.data.data() + k));
      if (d < 0) throw InputError(provisional + ": negative dimension");
      if (!detail::CheckedMul(count, static_cast<std::size_t>(d), &count)) throw InputError(provisional + ": dimensions overflow");
      v.dims.push_back(static_cast<std::size_t>(d));
    }
    pos = dims.next;

    const Element name = ReadElement(sub, pos, provisional);
    if (name.type != miINT8 && name.type != miUINT8) throw InputError(provisional + ": bad array name element at " + buf.At(pos));
    v.name.assign(reinterpret_cast<const char*>(name.data.data()), name.data.size());
    pos = name.next;
    if (where.empty()) where = source_ + ": " + (v.name.empty() ? std::string("<unnamed variable>") : v.name);
    v.where = where;

    switch (v.mat_class) {
      case MatClass::kDouble:
      case MatClass::kSingle:
      case MatClass::kInt8:
      case MatClass::kUInt8:
      case MatClass::kInt16:
      case MatClass::kUInt16:
      case MatClass::kInt32:
      case MatClass::kUInt32:
      case MatClass::kInt64:
      case MatClass::kUInt64: {
        if (pos >= end && count == 0) return v;  // some writers omit the data of empties
        const Element re = ReadElement(sub, pos, where);
        v.real = Numbers(re, count, where, buf.At(pos));
        pos = re.next;
        if (v.complex) {
          const Element im = ReadElement(sub, pos, where);
          v.imag = Numbers(im, count, where, buf.At(pos));
        }
        return v;
      }
      case MatClass::kChar: {
        if (pos >= end && count == 0) return v;
        const Element data = ReadElement(sub, pos, where);
        v.text = Text(data, count, where);
        return v;
      }
      case MatClass::kCell: {
        if (count > (end - std::min(pos, end)) / 8) {
          throw InputError(where + ": cell array of " + std::to_string(count) + " elements does not fit in its data (truncated?)");
        }
        v.cells.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
          const Element child = ReadElement(sub, pos, where);
          if (child.type != miMATRIX) throw InputError(where + ": cell element " + std::to_string(i + 1) + " is not a matrix");
          const std::size_t child_begin = static_cast<std::size_t>(child.data.data() - sub.bytes.data());
          v.cells.push_back(ParseMatrix(sub, child_begin, child_begin + child.data.size(), where + CellSuffix(v.dims, i), depth + 1));
          pos = child.next;
        }
        return v;
      }
      case MatClass::kStruct:
      case MatClass::kObject: {
        if (v.mat_class == MatClass::kObject) {
          const Element cls = ReadElement(sub, pos, where);
          v.text.assign(reinterpret_cast<const char*>(cls.data.data()), cls.data.size());
          pos = cls.next;
        }
        const Element len = ReadElement(sub, pos, where);
        if (len.type != miINT32 || len.data.size() != 4) throw InputError(where + ": bad struct field-name length");
        const std::size_t name_len = LoadU32(len.data.data());
        pos = len.next;
        const Element names = ReadElement(sub, pos, where);
        if (names.type != miINT8 && names.type != miUINT8) throw InputError(where + ": bad struct field names");
        if (name_len == 0 ? !names.data.empty() : names.data.size() % name_len != 0) {
          throw InputError(where + ": struct field names do not match their length");
        }
        const std::size_t num_fields = name_len ? names.data.size() / name_len : 0;
        for (std::size_t k = 0; k < num_fields; ++k) {
          const char* s = reinterpret_cast<const char*>(names.data.data() + k * name_len);
          v.field_names.emplace_back(s, strnlen(s, name_len));
        }
        pos = names.next;
        std::size_t total = 0;
        if (!detail::CheckedMul(count, num_fields, &total) || total > (end - std::min(pos, end)) / 8) {
          throw InputError(where + ": struct of " + std::to_string(count) + " elements does not fit in its data (truncated?)");
        }
        v.field_values.reserve(total);
        for (std::size_t e = 0; e < count; ++e) {
          for (std::size_t k = 0; k < num_fields; ++k) {
            const Element child = ReadElement(sub, pos, where);
            if (child.type != miMATRIX) throw InputError(where + ": struct field value is not a matrix");
            const std::size_t child_begin = static_cast<std::size_t>(child.data.data() - sub.bytes.data());
            const std::string child_where = where + (count == 1 ? std::string() : "(" + std::to_string(e + 1) + ")") + "." + v.field_names[k];
            v.field_values.push_back(ParseMatrix(sub, child_begin, child_begin + child.data.size(), child_where, depth + 1));
            pos = child.next;
          }
        }
        return v;
      }
      default:
        v.unsupported = std::string("MAT class ") + MatClassName(v.mat_class) + " (" +
                        std::to_string(static_cast<int>(v.mat_class)) + ") is not supported";
        return v;
    }
  }

  const std::string& source() const { return source_; }

 private:
  static std::string CellSuffix(const std::vector<std::size_t>& dims, std::size_t linear) {
    if (dims.size() == 2 && dims[0] > 0) {
      return "{" + std::to_string(linear % dims[0] + 1) + "," + std::to_string(linear / dims[0] + 1) + "}";
    }
    return "{" + std::to_string(linear + 1) + "}";
  }

  static std::vector<double> Numbers(const Element& e, std::size_t count, const std::string& where, const std::string& at) {
    const std::size_t size = MiSize(e.type);
    if (size == 0 || e.type == miUTF8 || e.type == miUTF16 || e.type == miUTF32) {
      throw InputError(where + ": numeric data of unsupported storage type " + std::to_string(e.type) + " at " + at);
    }
    if (e.data.size() % size != 0 || e.data.size() / size != count) {
      throw InputError(where + ": numeric data holds " + std::to_string(e.data.size() / size) + " values, dimensions need " +
                       std::to_string(count) + " (" + at + ")");
    }
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = MiValue(e.type, e.data.data() + i * size);
    return out;
  }

  static std::string Text(const Element& e, std::size_t count, const std::string& where) {
    std::string out;
    switch (e.type) {
      case miUTF8: out.assign(reinterpret_cast<const char*>(e.data.data()), e.data.size()); return out;
      case miINT8:
      case miUINT8:
        for (auto c : e.data) detail::AppendUtf8(out, c);
        break;
      case miUTF16:
      case miUINT16:
      case miINT16: {
        if (e.data.size() % 2) throw InputError(where + ": odd-sized UTF-16 text");
        const std::size_t n = e.data.size() / 2;
        for (std::size_t i = 0; i < n; ++i) {
          std::uint32_t cp = LoadU16(e.data.data() + 2 * i);
          if (cp >= 0xD800 && cp < 0xDC00 && i + 1 < n) {
            const std::uint32_t lo = LoadU16(e.data.data() + 2 * (i + 1));
            if (lo >= 0xDC00 && lo < 0xE000) {
              cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
              ++i;
            }
          }
          detail::AppendUtf8(out, cp);
        }
        if (e.type != miUTF16 && n != count) throw InputError(where + ": char data holds " + std::to_string(n) + " characters, dimensions need " + std::to_string(count));
        return out;
      }
      case miUTF32:
      case miUINT32:
      case miINT32:
        if (e.data.size() % 4) throw InputError(where + ": bad UTF-32 text");
        for (std::size_t i = 0; i < e.data.size(); i += 4) detail::AppendUtf8(out, LoadU32(e.data.data() + i));
        break;
      default: throw InputError(where + ": char data of unsupported storage type " + std::to_string(e.type));
    }
    return out;
  }

  std::string source_;
};

}  // namespace

const char* MatClassName(MatClass c) {
  switch (c) {
    case MatClass::kCell: return "cell";
    case MatClass::kStruct: return "struct";
    case MatClass::kObject: return "object";
    case MatClass::kChar: return "char";
    case MatClass::kSparse: return "sparse";
    case MatClass::kDouble: return "double";
    case MatClass::kSingle: return "single";
    case MatClass::kInt8: return "int8";
    case MatClass::kUInt8: return "uint8";
    case MatClass::kInt16: return "int16";
    case MatClass::kUInt16: return "uint16";
    case MatClass::kInt32: return "int32";
    case MatClass::kUInt32: return "uint32";
    case MatClass::kInt64: return "int64";
    case MatClass::kUInt64: return "uint64";
    case MatClass::kFunction: return "function_handle";
    case MatClass::kOpaque: return "opaque";
    default: return "unknown";
  }
}

std::size_t MatValue::NumElements() const {
  if (dims.empty()) return 0;
  std::size_t n = 1;
  for (auto d : dims) n *= d;  // validated against overflow while parsing
  return n;
}

bool MatValue::IsNumeric() const {
  const auto c = static_cast<int>(mat_class);
  return unsupported.empty() && c >= static_cast<int>(MatClass::kDouble) && c <= static_cast<int>(MatClass::kUInt64);
}

std::size_t MatValue::Cols() const {
  if (dims.size() < 2) return dims.empty() ? 0 : 1;
  std::size_t n = 1;
  for (std::size_t k = 1; k < dims.size(); ++k) n *= dims[k];
  return n;
}

std::string MatValue::Describe() const {
  std::string s;
  for (std::size_t k = 0; k < dims.size(); ++k) {
    if (k) s += 'x';
    s += std::to_string(dims[k]);
  }
  s += " ";
  if (logical) return s + "logical";
  s += MatClassName(mat_class);
  if (complex) s += " complex";
  return s;
}

void MatValue::Fail(const std::string& what) const { throw InputError(where + ": " + what); }

const std::vector<double>& MatValue::Numeric() const {
  if (!unsupported.empty()) Fail(unsupported);
  if (!IsNumeric()) Fail("expected a numeric array, got " + Describe());
  return real;
}

double MatValue::At(std::size_t row, std::size_t col) const {
  const auto& values = Numeric();
  if (row >= Rows() || col >= Cols()) {
    Fail("index (" + std::to_string(row + 1) + "," + std::to_string(col + 1) + ") out of range for " + Describe());
  }
  return values[col * Rows() + row];
}

std::vector<double> MatValue::RowMajor(std::size_t rows, std::size_t cols) const {
  if (!unsupported.empty()) Fail(unsupported);
  if (!IsNumeric() || dims.size() != 2 || dims[0] != rows || dims[1] != cols) {
    Fail("expected a " + std::to_string(rows) + "x" + std::to_string(cols) + " numeric matrix, got " + Describe());
  }
  std::vector<double> out(rows * cols);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) out[r * cols + c] = real[c * rows + r];
  }
  return out;
}

const MatValue& MatValue::Cell(std::size_t linear_index) const {
  if (!IsCell()) Fail("expected a cell array, got " + Describe());
  if (linear_index >= cells.size()) {
    Fail("cell index " + std::to_string(linear_index + 1) + " out of range for " + Describe());
  }
  return cells[linear_index];
}

const MatValue& MatValue::Cell(std::size_t row, std::size_t col) const {
  if (!IsCell()) Fail("expected a cell array, got " + Describe());
  if (row >= Rows() || col >= Cols()) {
    Fail("cell index {" + std::to_string(row + 1) + "," + std::to_string(col + 1) + "} out of range for " + Describe());
  }
  return cells[col * Rows() + row];
}

const std::string& MatValue::Text() const {
  if (!IsChar()) Fail("expected a char array, got " + Describe());
  return text;
}

bool MatValue::HasField(const std::string& field) const {
  if (!IsStruct()) return false;
  for (const auto& n : field_names) {
    if (n == field) return true;
  }
  return false;
}

const MatValue& MatValue::Field(const std::string& field, std::size_t element) const {
  if (!IsStruct()) Fail("expected a struct, got " + Describe());
  const std::size_t n = NumElements();
  if (element >= n) Fail("struct element " + std::to_string(element + 1) + " out of range for " + Describe());
  for (std::size_t k = 0; k < field_names.size(); ++k) {
    if (field_names[k] == field) return field_values[element * field_names.size() + k];
  }
  std::string names;
  for (const auto& s : field_names) {
    if (!names.empty()) names += ", ";
    names += s;
  }
  Fail("struct has no field " + QuoteName(field) + " (fields: " + names + ")");
}

const MatValue& MatFile::Get(const std::string& name) const {
  auto it = variables.find(name);
  if (it != variables.end()) return it->second;
  std::string names;
  for (const auto& [n, v] : variables) {
    if (!names.empty()) names += ", ";
    names += n;
  }
  throw InputError(source + ": variable " + QuoteName(name) + " not found (variables: " + names + ")");
}

MatFile ParseMat(std::span<const std::uint8_t> bytes, const std::string& source) {
  MatFile file;
  file.source = source;
  if (bytes.size() >= 19 && std::memcmp(bytes.data(), "MATLAB 7.3 MAT-file", 19) == 0) {
    throw InputError(source + ": MAT v7.3 files are HDF5 containers and not supported by this reader (re-save with -v7)");
  }
  if (bytes.size() < 128) throw InputError(source + ": too short for a MAT-file v5 header (" + std::to_string(bytes.size()) + " bytes)");
  const std::uint8_t* h = bytes.data();
  if (h[126] == 'M' && h[127] == 'I') throw InputError(source + ": big-endian MAT files are not supported");
  if (!(h[126] == 'I' && h[127] == 'M') || LoadU16(h + 124) != 0x0100) {
    throw InputError(source + ": not a MAT-file version 5 (bad header; MAT v4 files are not supported)");
  }
  std::size_t text_end = 116;
  while (text_end > 0 && (h[text_end - 1] == ' ' || h[text_end - 1] == '\0')) --text_end;
  file.header_text.assign(reinterpret_cast<const char*>(h), text_end);

  MatParser parser(source);
  InflateBudget budget(source, bytes.size());
  const Buffer whole{bytes, source, 0, false};
  std::size_t pos = 128;
  while (pos < bytes.size()) {
    if (bytes.size() - pos < 8) throw InputError(source + ": truncated data element tag at byte " + std::to_string(pos));
    const std::uint32_t type = LoadU32(bytes.data() + pos);
    const std::size_t size = LoadU32(bytes.data() + pos + 4);
    if (size > bytes.size() - pos - 8) {
      throw InputError(source + ": truncated variable at byte " + std::to_string(pos) + " (needs " + std::to_string(size) +
                       " bytes, only " + std::to_string(bytes.size() - pos - 8) + " left)");
    }
    const Bytes data = bytes.subspan(pos + 8, size);
    if (type == miMATRIX) {
      MatValue v = parser.ParseMatrix(whole, pos + 8, pos + 8 + size, {}, 0);
      std::string name = v.name;
      file.variables.insert_or_assign(std::move(name), std::move(v));
    } else if (type == miCOMPRESSED) {
      const std::string what = source + ": compressed variable at byte " + std::to_string(pos);
      // First the inner tag, to learn the size; then exactly that much.
      const auto head = detail::InflateUpTo(data, false, 8, &budget, what);
      if (head.size() < 8) throw InputError(what + ": inflated data too short");
      const std::uint32_t inner_type = LoadU32(head.data());
      const std::size_t inner_size = LoadU32(head.data() + 4);
      if (inner_type == miMATRIX) {
        const auto body = detail::InflateUpTo(data, false, 8 + inner_size, &budget, what);
        if (body.size() < 8 + inner_size) {
          throw InputError(what + ": inflated to " + std::to_string(body.size()) + " bytes, its element needs " + std::to_string(8 + inner_size));
        }
        const Buffer inflated{Bytes(body), source, 0, true};
        MatValue v = parser.ParseMatrix(inflated, 8, 8 + inner_size, {}, 0);
        std::string name = v.name;
        file.variables.insert_or_assign(std::move(name), std::move(v));
      }
    }
    // Other top-level element types carry nothing we read; skip them.
    // Top-level elements are not padded (scipy and matio agree): miMATRIX sizes are
    // multiples of 8 anyway, compressed ones are followed immediately.
    pos += 8 + size;
  }
  return file;
}

MatFile ReadMat(const std::filesystem::path& path) {
  const auto bytes = detail::ReadFileBytes(path);
  return ParseMat(bytes, detail::SourceName(path));
}

}  // namespace rpt::io
