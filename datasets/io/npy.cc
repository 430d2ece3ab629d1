// SPDX-License-Identifier: MIT
#include "datasets/io/npy.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <unordered_set>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/io/binary.h"
#include "datasets/io/pickle.h"
#include "core/printable_text.h"

namespace rpt::io {
namespace {

using detail::Bytes;
using detail::LoadU16;
using detail::LoadU32;

constexpr std::size_t kMaxLiteralDepth = 32;
constexpr std::size_t kMaxDescrDepth = 8;

// ---------------------------------------------------------------------------------------
// Python literal parser (NPY headers)

class LiteralParser {
 public:
  LiteralParser(std::string_view text, const std::string& where) : text_(text), where_(where) {}

  PyValuePtr ParseAll() {
    PyValuePtr v = Parse(0);
    SkipSpace();
    if (pos_ != text_.size()) Fail("unexpected text after the value");
    return v;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw InputError(where_ + ": " + what + " at character " + std::to_string(pos_));
  }
  void SkipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  char Peek() {
    SkipSpace();
    if (pos_ >= text_.size()) Fail("unexpected end of text");
    return text_[pos_];
  }
  void Expect(char c) {
    if (Peek() != c) Fail(std::string("expected '") + c + "'");
    ++pos_;
  }

  PyValuePtr Parse(std::size_t depth) {
    if (depth > kMaxLiteralDepth) Fail("literal nests too deeply");
    const char c = Peek();
    if (c == '{') return ParseDict(depth);
    if (c == '[' || c == '(') return ParseSequence(depth);
    if (c == '\'' || c == '"') return MakeStr(ParseString());
    if ((c == 'u' || c == 'b' || c == 'U' || c == 'B') && pos_ + 1 < text_.size() &&
        (text_[pos_ + 1] == '\'' || text_[pos_ + 1] == '"')) {
      const bool bytes = c == 'b' || c == 'B';
      ++pos_;
      std::string s = ParseString();
      return bytes ? MakeBytes(std::move(s)) : MakeStr(std::move(s));
    }
    if (c == '-' || c == '+' || std::isdigit(static_cast<unsigned char>(c)) || c == '.') return ParseNumber();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
      const std::string_view word = text_.substr(start, pos_ - start);
      if (word == "True") return MakeBool(true);
      if (word == "False") return MakeBool(false);
      if (word == "None") return MakeNone();
      pos_ = start;
      Fail("unknown name " + QuoteName(std::string(word.substr(0, 40))));
    }
    Fail(std::string("unexpected character '") + c + "'");
  }

  PyValuePtr ParseDict(std::size_t depth) {
    Expect('{');
    auto dict = std::make_shared<PyValue>();
    dict->kind = PyKind::kDict;
    while (Peek() != '}') {
      PyValuePtr key = Parse(depth + 1);
      Expect(':');
      PyValuePtr value = Parse(depth + 1);
      if (!DictSet(*dict, key, value)) Fail("unhashable dict key");
      if (Peek() == ',') {
        ++pos_;
      } else if (Peek() != '}') {
        Fail("expected ',' or '}'");
      }
    }
    ++pos_;
    return dict;
  }

  PyValuePtr ParseSequence(std::size_t depth) {
    const char open = Peek();
    const char close = open == '[' ? ']' : ')';
    ++pos_;
    std::vector<PyValuePtr> items;
    bool saw_comma = false;
    while (Peek() != close) {
      items.push_back(Parse(depth + 1));
      if (Peek() == ',') {
        ++pos_;
        saw_comma = true;
      } else if (Peek() != close) {
        Fail(std::string("expected ',' or '") + close + "'");
      }
    }
    ++pos_;
    // "(3)" is just 3 in Python; "(3,)" is a tuple.
    if (open == '(' && items.size() == 1 && !saw_comma) return items[0];
    auto v = std::make_shared<PyValue>();
    v->kind = open == '[' ? PyKind::kList : PyKind::kTuple;
    v->items = std::move(items);
    return v;
  }

  std::string ParseString() {
    const char quote = text_[pos_++];
    std::string out;
    while (true) {
      if (pos_ >= text_.size()) Fail("unterminated string");
      const char c = text_[pos_++];
      if (c == quote) break;
      if (c != '\\') {
        out.push_back(c);
        continue;
      }
      if (pos_ >= text_.size()) Fail("unterminated string");
      const char e = text_[pos_++];
      switch (e) {
        case 'n': out.push_back('\n'); break;
        case 't': out.push_back('\t'); break;
        case 'r': out.push_back('\r'); break;
        case '0': out.push_back('\0'); break;
        case 'x': {
          if (pos_ + 2 > text_.size()) Fail("bad \\x escape");
          const std::string hex(text_.substr(pos_, 2));
          if (!std::isxdigit(static_cast<unsigned char>(hex[0])) || !std::isxdigit(static_cast<unsigned char>(hex[1]))) Fail("bad \\x escape");
          out.push_back(static_cast<char>(std::stoi(hex, nullptr, 16)));
          pos_ += 2;
          break;
        }
        default: out.push_back(e); break;  // \\ \' \" and anything else literally
      }
    }
    return out;
  }

  PyValuePtr ParseNumber() {
    const std::size_t start = pos_;
    if (text_[pos_] == '-' || text_[pos_] == '+') ++pos_;
    bool is_float = false;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (std::isdigit(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (c == '.' || c == 'e' || c == 'E' || ((c == '-' || c == '+') && (text_[pos_ - 1] == 'e' || text_[pos_ - 1] == 'E'))) {
        is_float = true;
        ++pos_;
      } else {
        break;
      }
    }
    const std::string token(text_.substr(start, pos_ - start));
    if (pos_ < text_.size() && (text_[pos_] == 'L' || text_[pos_] == 'l')) ++pos_;  // Python 2 long
    if (token.empty() || token == "-" || token == "+") Fail("bad number");
    const std::string problem = "bad number " + QuoteName(token.substr(0, 40)) + " (malformed or out of range)";
    if (is_float) {
      double d = 0;
      if (!io::ParseNumber(token, &d)) Fail(problem);
      return MakeFloat(d);
    }
    long long v = 0;
    if (!io::ParseInteger(token, &v)) Fail(problem);
    return MakeInt(v);
  }

  std::string_view text_;
  const std::string& where_;
  std::size_t pos_ = 0;
};

DType DescrImpl(const PyValue& descr, const std::string& where, std::size_t depth) {
  if (depth > kMaxDescrDepth) throw InputError(where + ": descr nests too deeply");
  if (descr.kind == PyKind::kStr) {
    auto t = ParseTypeStr(descr.text);
    if (!t) throw InputError(where + ": unsupported dtype descr " + QuoteName(descr.text.substr(0, 40)));
    return *t;
  }
  if (descr.kind != PyKind::kList) {
    throw InputError(where + ": descr must be a type string or a list of fields, got " + PyKindName(descr.kind));
  }
  DType record;
  record.kind = 'V';
  record.byte_order = '|';
  std::size_t offset = 0;
  std::unordered_set<std::string> names;
  for (const auto& item : descr.items) {
    if (item->kind != PyKind::kTuple || item->items.size() < 2 || item->items.size() > 3) {
      throw InputError(where + ": each structured descr entry must be (name, type[, shape])");
    }
    const PyValue* name = item->items[0].get();
    // (title, name) pairs name the field by their second element.
    if (name->kind == PyKind::kTuple && name->items.size() == 2) name = name->items[1].get();
    if (name->kind != PyKind::kStr) throw InputError(where + ": field name must be a str");
    DTypeField field;
    field.name = name->text;
    field.dtype = DescrImpl(*item->items[1], where, depth + 1);
    if (field.dtype.kind == 'O') throw InputError(where + ": structured dtypes with object fields are not supported");
    if (item->items.size() == 3) {
      const PyValue& shape = *item->items[2];
      if (shape.kind == PyKind::kInt) {
        field.shape.push_back(shape.int_value);
      } else if (shape.kind == PyKind::kTuple) {
        for (const auto& d : shape.items) {
          if (d->kind != PyKind::kInt) throw InputError(where + ": field shape must hold ints");
          field.shape.push_back(d->int_value);
        }
      } else {
        throw InputError(where + ": field shape must be an int or a tuple");
      }
    }
    std::size_t count = 1;
    for (auto d : field.shape) {
      if (d < 0 || !detail::CheckedMul(count, static_cast<std::size_t>(d), &count)) {
        throw InputError(where + ": field " + QuoteName(field.name) + " has a bad or overflowing shape");
      }
    }
    std::size_t size = 0;
    if (!detail::CheckedMul(count, field.dtype.item_size, &size) || !detail::CheckedAdd(offset, size, &size)) {
      throw InputError(where + ": structured dtype size overflows");
    }
    field.offset = offset;
    offset = size;
    // Empty names are numpy's padding entries ('', '|V4').
    if (field.name.empty()) continue;
    if (!names.insert(field.name).second) throw InputError(where + ": duplicate field name " + QuoteName(field.name));
    record.fields.push_back(std::move(field));
  }
  record.item_size = offset;
  return record;
}

PyView ParseNpyImpl(Bytes bytes, const std::string& source) {
  static const std::uint8_t kMagic[6] = {0x93, 'N', 'U', 'M', 'P', 'Y'};
  if (bytes.size() < 10) throw InputError(source + ": too short for an NPY file (" + std::to_string(bytes.size()) + " bytes)");
  if (std::memcmp(bytes.data(), kMagic, 6) != 0) throw InputError(source + ": not an NPY file (bad magic)");
  const int major = bytes[6];
  const int minor = bytes[7];
  std::size_t header_len = 0;
  std::size_t start = 0;
  if (major == 1) {
    header_len = LoadU16(bytes.data() + 8);
    start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw InputError(source + ": truncated NPY header");
    header_len = LoadU32(bytes.data() + 8);
    start = 12;
  } else {
    throw InputError(source + ": unsupported NPY version " + std::to_string(major) + "." + std::to_string(minor));
  }
  if (header_len > bytes.size() - start) {
    throw InputError(source + ": truncated NPY header (needs " + std::to_string(header_len) + " bytes at byte " +
                     std::to_string(start) + ", only " + std::to_string(bytes.size() - start) + " left)");
  }
  const std::string where = source + ": NPY header";
  const std::string_view text(reinterpret_cast<const char*>(bytes.data() + start), header_len);
  PyValuePtr header = ParsePythonLiteral(text, where);
  if (header->kind != PyKind::kDict) throw InputError(where + ": expected a dict");
  PyView h(header, where);
  for (const char* key : {"descr", "fortran_order", "shape"}) {
    if (!h.Has(key)) throw InputError(where + ": missing key " + QuoteName(key));
  }
  DType dtype = DTypeFromDescr(h.Key("descr").value(), where);
  const bool fortran = h.Key("fortran_order").AsBool();
  const PyView shape_view = h.Key("shape");
  if (!shape_view.IsTuple()) shape_view.Fail("expected a tuple");
  std::vector<std::int64_t> shape;
  std::size_t count = 1;
  if (shape_view.Size() > 64) shape_view.Fail("more than 64 dimensions");
  for (const auto& d : shape_view.Elements()) {
    const std::int64_t extent = d.AsInt();
    if (extent < 0) d.Fail("negative dimension");
    if (!detail::CheckedMul(count, static_cast<std::size_t>(extent), &count)) shape_view.Fail("shape overflows the element count");
    shape.push_back(extent);
  }
  const std::size_t data_offset = start + header_len;

  if (dtype.kind == 'O') {
    // The payload is a pickle of the whole array (numpy's write_array for object dtypes).
    PyView payload = ParsePickle(bytes.subspan(data_offset), source, data_offset);
    if (!payload.IsArray()) return payload;
    const NdArray& a = payload.AsArray();
    if (a.shape != shape) {
      throw InputError(source + ": pickled object array has shape " + a.ShapeStr() + ", the NPY header says another");
    }
    if (a.dtype.kind == 'O' && a.Ndim() == 0 && a.objects.size() == 1) return PyView(a.objects[0], source);
    return payload;
  }

  std::size_t need = 0;
  if (!detail::CheckedMul(count, dtype.item_size, &need)) throw InputError(source + ": array byte size overflows");
  const std::size_t left = bytes.size() - data_offset;
  if (need > left) {
    throw InputError(source + ": truncated NPY data: " + std::to_string(need) + " bytes needed after the header at byte " +
                     std::to_string(data_offset) + ", only " + std::to_string(left) + " left");
  }
  if (dtype.item_size == 0 && count > (std::size_t{1} << 24)) throw InputError(source + ": too many zero-size elements");
  auto node = std::make_shared<PyValue>();
  node->kind = PyKind::kNdArray;
  node->array = std::make_shared<NdArray>();
  node->array->dtype = std::move(dtype);
  node->array->shape = std::move(shape);
  node->array->fortran_order = fortran;
  // numpy ignores bytes after the array, so do we.
  node->array->data.assign(bytes.begin() + static_cast<std::ptrdiff_t>(data_offset),
                           bytes.begin() + static_cast<std::ptrdiff_t>(data_offset + need));
  return PyView(node, source);
}

// ---------------------------------------------------------------------------------------
// ZIP

struct ZipEntry {
  std::string name;
  std::uint16_t method = 0;
  std::uint32_t crc = 0;
  std::size_t compressed_size = 0;
  std::size_t uncompressed_size = 0;
  std::size_t data_offset = 0;
};

std::vector<ZipEntry> ListZip(Bytes z, const std::string& source) {
  constexpr std::uint32_t kEocd = 0x06054b50, kCentral = 0x02014b50, kLocal = 0x04034b50, kZip64Locator = 0x07064b50;
  if (z.size() < 22) throw InputError(source + ": too short for a ZIP archive (" + std::to_string(z.size()) + " bytes)");
  // The end-of-central-directory record sits in the last 22 + 65535 bytes.
  std::size_t eocd = std::string::npos;
  const std::size_t lowest = z.size() > 22 + 65535 ? z.size() - 22 - 65535 : 0;
  for (std::size_t p = z.size() - 22 + 1; p-- > lowest;) {
    if (LoadU32(z.data() + p) == kEocd && p + 22 + LoadU16(z.data() + p + 20) <= z.size()) {
      eocd = p;
      break;
    }
  }
  if (eocd == std::string::npos) {
    throw InputError(source + ": not a ZIP archive or truncated (no end-of-central-directory record)");
  }
  const std::uint8_t* e = z.data() + eocd;
  const std::uint16_t disk = LoadU16(e + 4), cd_disk = LoadU16(e + 6);
  const std::uint16_t entries_here = LoadU16(e + 8), entries = LoadU16(e + 10);
  const std::uint32_t cd_size = LoadU32(e + 12), cd_offset = LoadU32(e + 16);
  if ((eocd >= 20 && LoadU32(z.data() + eocd - 20) == kZip64Locator) || entries == 0xFFFF || cd_size == 0xFFFFFFFFu ||
      cd_offset == 0xFFFFFFFFu) {
    throw InputError(source + ": zip64 archives are not supported");
  }
  if (disk != 0 || cd_disk != 0 || entries_here != entries) throw InputError(source + ": multi-disk ZIP archives are not supported");
  if (static_cast<std::size_t>(cd_offset) + cd_size > eocd) {
    throw InputError(source + ": ZIP central directory at byte " + std::to_string(cd_offset) + " lies outside the file (truncated?)");
  }
  std::vector<ZipEntry> out;
  std::size_t p = cd_offset;
  const std::size_t cd_end = static_cast<std::size_t>(cd_offset) + cd_size;
  for (std::size_t i = 0; i < entries; ++i) {
    const std::string at = " (central directory entry " + std::to_string(i) + " at byte " + std::to_string(p) + ")";
    if (cd_end - p < 46 || LoadU32(z.data() + p) != kCentral) throw InputError(source + ": corrupt ZIP central directory" + at);
    const std::uint8_t* c = z.data() + p;
    const std::uint16_t flags = LoadU16(c + 8), method = LoadU16(c + 10);
    const std::uint32_t crc = LoadU32(c + 16), csize = LoadU32(c + 20), usize = LoadU32(c + 24);
    const std::size_t name_len = LoadU16(c + 28), extra_len = LoadU16(c + 30), comment_len = LoadU16(c + 32);
    const std::uint32_t local = LoadU32(c + 42);
    if (cd_end - p - 46 < name_len + extra_len + comment_len) throw InputError(source + ": corrupt ZIP central directory" + at);
    ZipEntry entry;
    entry.name.assign(reinterpret_cast<const char*>(c + 46), name_len);
    p += 46 + name_len + extra_len + comment_len;
    const std::string member = source + ": member " + QuoteName(entry.name);
    if (csize == 0xFFFFFFFFu || usize == 0xFFFFFFFFu || local == 0xFFFFFFFFu) throw InputError(member + ": zip64 entries are not supported");
    if (flags & 1) throw InputError(member + ": encrypted ZIP members are not supported");
    if (method != 0 && method != 8) {
      throw InputError(member + ": compression method " + std::to_string(method) + " is not supported (only stored and deflate)");
    }
    if (z.size() < 30 || local > z.size() - 30 || LoadU32(z.data() + local) != kLocal) {
      throw InputError(member + ": bad local header at byte " + std::to_string(local));
    }
    const std::size_t data_offset = static_cast<std::size_t>(local) + 30 + LoadU16(z.data() + local + 26) + LoadU16(z.data() + local + 28);
    if (data_offset > z.size() || csize > z.size() - data_offset) {
      throw InputError(member + ": data at byte " + std::to_string(data_offset) + " runs past the end of the file (truncated?)");
    }
    // Deflate cannot expand more than ~1032:1; a larger claim is corrupt or hostile.
    if (method == 8 && usize / 1032 > csize + 1) {
      throw InputError(member + ": implausible uncompressed size " + std::to_string(usize));
    }
    entry.method = method;
    entry.crc = crc;
    entry.compressed_size = csize;
    entry.uncompressed_size = usize;
    entry.data_offset = data_offset;
    out.push_back(std::move(entry));
  }
  return out;
}

std::vector<std::uint8_t> ExtractZip(Bytes z, const ZipEntry& entry, const std::string& source,
                                     InflateBudget* budget) {
  const std::string member = source + ": member " + QuoteName(entry.name);
  const Bytes raw = z.subspan(entry.data_offset, entry.compressed_size);
  std::vector<std::uint8_t> out;
  if (entry.method == 0) {
    if (entry.compressed_size != entry.uncompressed_size) throw InputError(member + ": stored member with differing sizes");
    out.assign(raw.begin(), raw.end());
  } else {
    out = detail::InflateUpTo(raw, true, entry.uncompressed_size, budget, member);
    if (out.size() != entry.uncompressed_size) {
      throw InputError(member + ": inflated to " + std::to_string(out.size()) + " bytes, the directory says " +
                       std::to_string(entry.uncompressed_size));
    }
  }
  uLong crc = crc32(0L, Z_NULL, 0);
  for (std::size_t k = 0; k < out.size(); k += 1u << 30) {
    const std::size_t n = std::min<std::size_t>(out.size() - k, 1u << 30);
    crc = crc32(crc, out.data() + k, static_cast<uInt>(n));
  }
  if (static_cast<std::uint32_t>(crc) != entry.crc) throw InputError(member + ": CRC-32 mismatch (corrupt data)");
  return out;
}

}  // namespace

PyValuePtr ParsePythonLiteral(std::string_view text, const std::string& where) {
  LiteralParser parser(text, where);
  return parser.ParseAll();
}

DType DTypeFromDescr(const PyValue& descr, const std::string& where) { return DescrImpl(descr, where, 0); }

PyView ParseNpy(std::span<const std::uint8_t> bytes, const std::string& source) { return ParseNpyImpl(bytes, source); }

PyView ReadNpy(const std::filesystem::path& path) {
  const auto bytes = detail::ReadFileBytes(path);
  return ParseNpyImpl(bytes, detail::SourceName(path));
}

std::map<std::string, PyView> ParseNpz(std::span<const std::uint8_t> bytes, const std::string& source,
                                       const std::vector<std::string>& required) {
  const std::vector<ZipEntry> entries = ListZip(bytes, source);
  // Everything the directory promises is known before a byte is inflated: a missing member or
  // a total beyond the budget fails here, not after gigabytes of other members.
  for (const std::string& name : required) {
    const bool present = std::any_of(entries.begin(), entries.end(), [&](const ZipEntry& e) {
      return e.name == name + ".npy" || e.name == name;
    });
    if (!present) {
      std::string names;
      for (const ZipEntry& e : entries) names += (names.empty() ? "" : ", ") + e.name;
      throw InputError(source + ": no member '" + name + ".npy' (members: " + (names.empty() ? "none" : names) + ")");
    }
  }
  InflateBudget budget(source, bytes.size());
  std::uint64_t declared = 0;
  for (const ZipEntry& entry : entries) {
    if (entry.method != 0) declared += entry.uncompressed_size;
  }
  budget.Reserve(declared, source + ": deflated members");
  budget.Release(declared);
  std::map<std::string, PyView> out;
  for (const ZipEntry& entry : entries) {
    if (!entry.name.empty() && entry.name.back() == '/') continue;  // directory
    auto data = ExtractZip(bytes, entry, source, &budget);
    const std::string member_source = source + "[" + entry.name + "]";
    constexpr std::string_view kSuffix = ".npy";
    if (entry.name.size() > kSuffix.size() && entry.name.compare(entry.name.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0) {
      out.insert_or_assign(entry.name.substr(0, entry.name.size() - kSuffix.size()), ParseNpyImpl(data, member_source));
    } else {
      out.insert_or_assign(entry.name, PyView(MakeBytes(std::string(data.begin(), data.end())), member_source));
    }
  }
  return out;
}

std::map<std::string, PyView> ReadNpz(const std::filesystem::path& path, const std::vector<std::string>& required) {
  const auto bytes = detail::ReadFileBytes(path);
  return ParseNpz(bytes, detail::SourceName(path), required);
}

}  // namespace rpt::io
