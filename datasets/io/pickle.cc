// SPDX-License-Identifier: MIT
// Over 500 lines on purpose: the pickle virtual machine is one cohesive state machine (stack,
// memo, mark, one case per opcode of protocols 0-5, the allow-list of reconstructable globals);
// splitting the opcode switch would spread one loop's invariants over several files.
#include "datasets/io/pickle.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <iterator>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/binary.h"

namespace rpt::io {
namespace {

using detail::Bytes;
using detail::LoadU16;
using detail::LoadU32;
using detail::LoadU64;

constexpr std::size_t kMaxDTypeDepth = 8;
constexpr std::size_t kMaxNdim = 64;

const char* OpcodeName(std::uint8_t op) {
  switch (op) {
    case '(': return "MARK";
    case '.': return "STOP";
    case '0': return "POP";
    case '1': return "POP_MARK";
    case '2': return "DUP";
    case 'F': return "FLOAT";
    case 'I': return "INT";
    case 'J': return "BININT";
    case 'K': return "BININT1";
    case 'L': return "LONG";
    case 'M': return "BININT2";
    case 'N': return "NONE";
    case 'P': return "PERSID";
    case 'Q': return "BINPERSID";
    case 'R': return "REDUCE";
    case 'S': return "STRING";
    case 'T': return "BINSTRING";
    case 'U': return "SHORT_BINSTRING";
    case 'V': return "UNICODE";
    case 'X': return "BINUNICODE";
    case 'a': return "APPEND";
    case 'b': return "BUILD";
    case 'c': return "GLOBAL";
    case 'd': return "DICT";
    case '}': return "EMPTY_DICT";
    case 'e': return "APPENDS";
    case 'g': return "GET";
    case 'h': return "BINGET";
    case 'i': return "INST";
    case 'j': return "LONG_BINGET";
    case 'l': return "LIST";
    case ']': return "EMPTY_LIST";
    case 'o': return "OBJ";
    case 'p': return "PUT";
    case 'q': return "BINPUT";
    case 'r': return "LONG_BINPUT";
    case 's': return "SETITEM";
    case 't': return "TUPLE";
    case ')': return "EMPTY_TUPLE";
    case 'u': return "SETITEMS";
    case 'G': return "BINFLOAT";
    case 'B': return "BINBYTES";
    case 'C': return "SHORT_BINBYTES";
    case 0x80: return "PROTO";
    case 0x81: return "NEWOBJ";
    case 0x82: return "EXT1";
    case 0x83: return "EXT2";
    case 0x84: return "EXT4";
    case 0x85: return "TUPLE1";
    case 0x86: return "TUPLE2";
    case 0x87: return "TUPLE3";
    case 0x88: return "NEWTRUE";
    case 0x89: return "NEWFALSE";
    case 0x8a: return "LONG1";
    case 0x8b: return "LONG4";
    case 0x8c: return "SHORT_BINUNICODE";
    case 0x8d: return "BINUNICODE8";
    case 0x8e: return "BINBYTES8";
    case 0x8f: return "EMPTY_SET";
    case 0x90: return "ADDITEMS";
    case 0x91: return "FROZENSET";
    case 0x92: return "NEWOBJ_EX";
    case 0x93: return "STACK_GLOBAL";
    case 0x94: return "MEMOIZE";
    case 0x95: return "FRAME";
    case 0x96: return "BYTEARRAY8";
    case 0x97: return "NEXT_BUFFER";
    case 0x98: return "READONLY_BUFFER";
    default: return nullptr;
  }
}

// Canonical spelling of an allow-listed global, or empty when it is not allowed.
// Python 2 and numpy 2 spell some modules differently; map them to one name.
std::string CanonicalGlobal(std::string module, const std::string& name) {
  if (module == "__builtin__") module = "builtins";
  if (module == "numpy._core.multiarray") module = "numpy.core.multiarray";
  if (module == "numpy._core.numeric") module = "numpy.core.numeric";
  const std::string full = module + "." + name;
  static const std::unordered_set<std::string> kAllowed = {
      "numpy.core.multiarray._reconstruct",
      "numpy.core.multiarray.scalar",
      "numpy.core.numeric._frombuffer",
      "numpy.ndarray",
      "numpy.dtype",
      "collections.defaultdict",
      "collections.OrderedDict",
      "builtins.list",
      "builtins.dict",
      "builtins.tuple",
      "builtins.set",
      "builtins.frozenset",
      "builtins.bytes",
      "builtins.bytearray",
      "_codecs.encode",
  };
  return kAllowed.count(full) ? full : std::string();
}

// Decodes UTF-8 and re-encodes as Latin-1 (what protocol 2 does for bytes objects).
std::optional<std::string> Utf8ToLatin1(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      out.push_back(static_cast<char>(c));
      ++i;
    } else if ((c & 0xE0) == 0xC0 && i + 1 < s.size()) {
      const auto c2 = static_cast<unsigned char>(s[i + 1]);
      if ((c2 & 0xC0) != 0x80) return std::nullopt;
      const unsigned cp = ((c & 0x1Fu) << 6) | (c2 & 0x3Fu);
      if (cp > 0xFF) return std::nullopt;
      out.push_back(static_cast<char>(cp));
      i += 2;
    } else {
      return std::nullopt;  // code point above U+00FF or malformed
    }
  }
  return out;
}

std::size_t DTypeCost(const DType& t, std::size_t depth = 0) {
  if (depth > kMaxDTypeDepth) return 1;
  std::size_t cost = 1;
  for (const auto& f : t.fields) cost += 1 + DTypeCost(f.dtype, depth + 1);
  if (t.subarray_base) cost += DTypeCost(*t.subarray_base, depth + 1);
  return cost;
}

std::size_t DTypeDepth(const DType& t) {
  std::size_t d = 0;
  for (const auto& f : t.fields) d = std::max(d, 1 + DTypeDepth(f.dtype));
  if (t.subarray_base) d = std::max(d, 1 + DTypeDepth(*t.subarray_base));
  return d;
}

bool DTypeHasObjects(const DType& t) {
  if (t.kind == 'O') return true;
  for (const auto& f : t.fields) {
    if (DTypeHasObjects(f.dtype)) return true;
  }
  return t.subarray_base && DTypeHasObjects(*t.subarray_base);
}

class Vm {
 public:
  Vm(Bytes data, std::string source, std::size_t base)
      : data_(data), source_(std::move(source)), base_(base), budget_(64 * data.size() + (std::size_t{1} << 20)) {
    none_ = MakeNone();
    true_ = MakeBool(true);
    false_ = MakeBool(false);
  }

  Vm(const Vm&) = delete;
  Vm& operator=(const Vm&) = delete;

  // Breaks every container not reachable from the validated result (all of them after a
  // failure) before anything is freed. The registry holds a reference to every container,
  // so each detach only drops counts and frees scalars: no recursive destruction of a
  // hostile deep chain or cycle can happen.
  ~Vm() {
    for (auto& c : containers_) {
      if (reachable_.count(c.get())) continue;
      auto items = std::move(c->items);
      auto entries = std::move(c->entries);
      c->key_index.clear();
      if (c->array) {
        auto objects = std::move(c->array->objects);
      }
    }
  }

  PyValuePtr Run() {
    for (;;) {
      if (pos_ >= data_.size()) {
        throw InputError(source_ + ": truncated pickle: no STOP opcode before the end of the data (byte " +
                         std::to_string(base_ + pos_) + ")");
      }
      op_pos_ = pos_;
      op_ = data_[pos_++];
      if (Step()) break;
    }
    PyValuePtr result = std::move(result_);
    Validate(result);
    return result;
  }

 private:
  // ---- errors and input ------------------------------------------------------------
  std::string OpLabel() const {
    const char* name = OpcodeName(op_);
    return std::string("pickle opcode ") + (name ? name : "?") + " (" + detail::HexByte(op_) + ") at byte " +
           std::to_string(base_ + op_pos_);
  }
  [[noreturn]] void Fail(const std::string& what) const { throw InputError(source_ + ": " + OpLabel() + ": " + what); }

  const std::uint8_t* Take(std::uint64_t n) {
    const std::size_t left = data_.size() - pos_;
    if (n > left) {
      throw InputError(source_ + ": truncated pickle: " + OpLabel() + " needs " + std::to_string(n) +
                       " more bytes, only " + std::to_string(left) + " left");
    }
    const std::uint8_t* p = data_.data() + pos_;
    pos_ += static_cast<std::size_t>(n);
    return p;
  }

  std::string TakeString(std::uint64_t n) {
    const std::uint8_t* p = Take(n);
    return std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n));
  }

  std::string ReadLine() {
    const std::uint8_t* begin = data_.data() + pos_;
    const std::uint8_t* end = data_.data() + data_.size();
    const std::uint8_t* nl = std::find(begin, end, static_cast<std::uint8_t>('\n'));
    if (nl == end) throw InputError(source_ + ": truncated pickle: " + OpLabel() + ": missing newline");
    pos_ += static_cast<std::size_t>(nl - begin) + 1;
    return std::string(reinterpret_cast<const char*>(begin), static_cast<std::size_t>(nl - begin));
  }

  // Charges bytes allocated by copies against the budget (64 x input size + 1 MiB).
  void Charge(std::size_t units) {
    if (units > budget_) Fail("the pickle asks for more work than its size justifies (resource limit; hostile input?)");
    budget_ -= units;
  }

  // ---- stack ----------------------------------------------------------------------
  std::size_t Floor() const { return marks_.empty() ? 0 : marks_.back(); }
  PyValuePtr Pop() {
    if (stack_.size() <= Floor()) Fail("stack underflow");
    PyValuePtr v = std::move(stack_.back());
    stack_.pop_back();
    return v;
  }
  const PyValuePtr& Top() {
    if (stack_.size() <= Floor()) Fail("stack underflow");
    return stack_.back();
  }
  std::vector<PyValuePtr> PopMark() {
    if (marks_.empty()) Fail("no MARK on the stack");
    const std::size_t m = marks_.back();
    marks_.pop_back();
    std::vector<PyValuePtr> items(std::make_move_iterator(stack_.begin() + static_cast<std::ptrdiff_t>(m)),
                                  std::make_move_iterator(stack_.end()));
    stack_.resize(m);
    return items;
  }
  void Push(PyValuePtr v) { stack_.push_back(std::move(v)); }

  PyValuePtr NewContainer(PyKind kind) {
    auto v = std::make_shared<PyValue>();
    v->kind = kind;
    containers_.push_back(v);
    return v;
  }
  PyValuePtr NewArrayNode() {
    auto v = NewContainer(PyKind::kNdArray);
    v->array = std::make_shared<NdArray>();
    return v;
  }

  void Memoize(std::uint64_t index) { memo_[index] = Top(); }
  void PushMemo(std::uint64_t index) {
    auto it = memo_.find(index);
    if (it == memo_.end()) Fail("memo entry " + std::to_string(index) + " was never stored");
    Push(it->second);
  }

  void SetItem(PyValue& dict, PyValuePtr key, PyValuePtr value) {
    const std::optional<std::string> k = KeyString(*key);
    if (!k) Fail(std::string("unhashable dict key of type ") + PyKindName(key->kind));
    Charge(k->size());
    DictSet(dict, std::move(key), std::move(value));
  }

  std::int64_t DecodeLong(const std::uint8_t* p, std::size_t n) {
    if (n == 0) return 0;
    const bool negative = (p[n - 1] & 0x80) != 0;
    if (n > 8) {
      for (std::size_t k = 8; k < n; ++k) {
        if (p[k] != (negative ? 0xFF : 0x00)) Fail("integer does not fit in 64 bits");
      }
      if (((p[7] & 0x80) != 0) != negative) Fail("integer does not fit in 64 bits");
      n = 8;
    }
    std::uint64_t v = negative ? ~std::uint64_t{0} : 0;
    for (std::size_t k = n; k-- > 0;) v = (v << 8) | p[k];
    if (n < 8 && !negative) v &= (std::uint64_t{1} << (8 * n)) - 1;
    return static_cast<std::int64_t>(v);
  }

  // ---- helpers for the callables ---------------------------------------------------
  std::int64_t IntArg(const PyValue& v, const char* what) {
    if (v.kind == PyKind::kInt) return v.int_value;
    if (v.kind == PyKind::kBool) return v.bool_value;
    Fail(std::string(what) + ": expected int, got " + PyKindName(v.kind));
  }

  std::vector<std::int64_t> ShapeArg(const PyValue& v, std::size_t* count) {
    std::vector<std::int64_t> shape;
    if (v.kind == PyKind::kInt) {
      shape.push_back(v.int_value);
    } else if (v.kind == PyKind::kTuple || v.kind == PyKind::kList) {
      if (v.items.size() > kMaxNdim) Fail("array has more than 64 dimensions");
      for (const auto& d : v.items) shape.push_back(IntArg(*d, "array shape"));
    } else {
      Fail(std::string("array shape: expected tuple, got ") + PyKindName(v.kind));
    }
    std::size_t n = 1;
    for (auto d : shape) {
      if (d < 0) Fail("negative array dimension " + std::to_string(d));
      if (!detail::CheckedMul(n, static_cast<std::size_t>(d), &n)) Fail("array shape overflows the element count");
    }
    *count = n;
    return shape;
  }

  const std::string* RawBytes(const PyValue& v) {
    // Python 2 byte strings arrive as str with raw content; protocol 3+ as bytes.
    if (v.kind == PyKind::kBytes || v.kind == PyKind::kStr) return &v.text;
    return nullptr;
  }

  const DType& DTypeArg(const PyValue& v, const char* what) {
    if (v.kind != PyKind::kDType || !v.dtype) Fail(std::string(what) + ": expected a numpy dtype, got " + PyKindName(v.kind));
    return *v.dtype;
  }

  std::string EncodeText(const PyValue& text, const PyValue* encoding) {
    if (text.kind != PyKind::kStr) Fail(std::string("encode: expected str, got ") + PyKindName(text.kind));
    std::string enc = "utf-8";
    if (encoding) {
      if (encoding->kind != PyKind::kStr) Fail("encode: encoding must be a str");
      enc = encoding->text;
      std::transform(enc.begin(), enc.end(), enc.begin(), [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    }
    Charge(text.text.size());
    if (enc == "utf-8" || enc == "utf8") return text.text;
    if (enc == "latin1" || enc == "latin-1" || enc == "iso-8859-1" || enc == "iso8859-1" || enc == "l1") {
      auto out = Utf8ToLatin1(text.text);
      if (!out) Fail("encode: text is not representable in latin-1");
      return *out;
    }
    Fail("encode: unsupported encoding " + QuoteName(enc));
  }

  // Items of an iterable argument (list, tuple, set; a dict yields its keys).
  std::vector<PyValuePtr> IterableArg(const PyValue& v, const char* what) {
    if (v.kind == PyKind::kList || v.kind == PyKind::kTuple || v.kind == PyKind::kSet) {
      Charge(v.items.size() * sizeof(PyValuePtr));
      return v.items;
    }
    if (v.kind == PyKind::kDict) {
      Charge(v.entries.size() * sizeof(PyValuePtr));
      std::vector<PyValuePtr> keys;
      for (const auto& e : v.entries) keys.push_back(e.first);
      return keys;
    }
    Fail(std::string(what) + ": expected an iterable, got " + PyKindName(v.kind));
  }

  void FillDict(PyValue& dict, const PyValue& init, const char* what) {
    if (init.kind == PyKind::kDict) {
      Charge(init.entries.size() * 2 * sizeof(PyValuePtr));
      for (const auto& e : init.entries) SetItem(dict, e.first, e.second);
      return;
    }
    for (const auto& pair : IterableArg(init, what)) {
      if ((pair->kind != PyKind::kTuple && pair->kind != PyKind::kList) || pair->items.size() != 2) {
        Fail(std::string(what) + ": expected (key, value) pairs");
      }
      SetItem(dict, pair->items[0], pair->items[1]);
    }
  }

  PyValuePtr ScalarFromBytes(const DType& dtype, const std::string& raw) {
    if (raw.size() != dtype.item_size) {
      Fail("numpy scalar of dtype " + dtype.Str() + " needs " + std::to_string(dtype.item_size) + " bytes, got " +
           std::to_string(raw.size()));
    }
    NdArray a;
    a.dtype = dtype;
    a.data.assign(raw.begin(), raw.end());
    if (dtype.IsRealNumeric()) {
      if (dtype.kind == 'b') return a.ElementAsDouble(0) != 0.0 ? true_ : false_;
      if (dtype.kind == 'f') return MakeFloat(a.ElementAsDouble(0));
      try {
        return MakeInt(a.ElementAsInt(0));
      } catch (const InputError&) {
        // uint64 above INT64_MAX: kept as a 0-d array below.
      }
    }
    if (DTypeHasObjects(dtype)) Fail("numpy scalar with object fields is not supported");
    auto node = NewArrayNode();
    *node->array = std::move(a);
    return node;
  }

  // REDUCE / NEWOBJ of an allow-listed callable.
  PyValuePtr Call(const PyValue& callable, const PyValue& args_value) {
    if (callable.kind != PyKind::kGlobal) {
      Fail(std::string("can only call allow-listed globals, got ") + PyKindName(callable.kind));
    }
    if (args_value.kind != PyKind::kTuple) Fail(std::string("arguments must be a tuple, got ") + PyKindName(args_value.kind));
    const std::string& f = callable.text;
    const auto& a = args_value.items;
    auto want_args = [&](std::size_t lo, std::size_t hi) {
      if (a.size() < lo || a.size() > hi) {
        Fail(f + " called with " + std::to_string(a.size()) + " arguments, expected " + std::to_string(lo) +
             (hi != lo ? "-" + std::to_string(hi) : std::string()));
      }
    };

    if (f == "numpy.core.multiarray._reconstruct") {
      want_args(3, 3);
      if (a[0]->kind != PyKind::kGlobal || a[0]->text != "numpy.ndarray") {
        Fail("_reconstruct: only numpy.ndarray can be reconstructed, got " + Repr(*a[0]));
      }
      // numpy always passes shape (0,) and dtype code b'b': the real shape, dtype and data
      // arrive with BUILD. Validate the argument, but start from an empty array regardless.
      std::size_t count = 0;
      ShapeArg(*a[1], &count);
      auto node = NewArrayNode();
      node->array->shape = {0};
      return node;
    }
    if (f == "numpy.dtype") {
      want_args(1, 3);
      if (a[0]->kind != PyKind::kStr) Fail(std::string("dtype: expected a type string, got ") + PyKindName(a[0]->kind));
      auto parsed = ParseTypeStr(a[0]->text);
      if (!parsed) Fail("dtype: unsupported type string " + QuoteName(a[0]->text.substr(0, 40)));
      auto node = std::make_shared<PyValue>();
      node->kind = PyKind::kDType;
      node->dtype = std::make_shared<DType>(*parsed);
      return node;
    }
    if (f == "numpy.core.multiarray.scalar") {
      want_args(1, 2);
      const DType& dtype = DTypeArg(*a[0], "scalar");
      if (dtype.kind == 'O') return a.size() == 2 ? a[1] : none_;
      if (a.size() != 2) Fail("scalar: missing data");
      const std::string* raw = RawBytes(*a[1]);
      if (!raw) Fail(std::string("scalar: expected bytes, got ") + PyKindName(a[1]->kind));
      return ScalarFromBytes(dtype, *raw);
    }
    if (f == "numpy.core.numeric._frombuffer") {
      want_args(4, 4);
      const std::string* raw = RawBytes(*a[0]);
      if (!raw) Fail(std::string("_frombuffer: expected bytes, got ") + PyKindName(a[0]->kind));
      const DType& dtype = DTypeArg(*a[1], "_frombuffer");
      if (DTypeHasObjects(dtype)) Fail("_frombuffer: object dtypes cannot come from a buffer");
      std::size_t count = 0;
      auto shape = ShapeArg(*a[2], &count);
      if (a[3]->kind != PyKind::kStr || (a[3]->text != "C" && a[3]->text != "F" && a[3]->text != "A" && a[3]->text != "K")) {
        Fail("_frombuffer: order must be 'C' or 'F'");
      }
      std::size_t bytes = 0;
      if (!detail::CheckedMul(count, dtype.item_size, &bytes)) Fail("_frombuffer: array size overflows");
      if (bytes != raw->size()) {
        Fail("_frombuffer: buffer has " + std::to_string(raw->size()) + " bytes, shape and dtype need " + std::to_string(bytes));
      }
      Charge(raw->size() + sizeof(DTypeField) * DTypeCost(dtype));
      auto node = NewArrayNode();
      node->array->dtype = dtype;
      node->array->shape = std::move(shape);
      node->array->fortran_order = a[3]->text == "F";
      node->array->data.assign(raw->begin(), raw->end());
      return node;
    }
    if (f == "collections.defaultdict" || f == "collections.OrderedDict" || f == "builtins.dict") {
      const bool is_default = f == "collections.defaultdict";
      want_args(0, is_default ? 2 : 1);
      auto node = NewContainer(PyKind::kDict);
      node->is_defaultdict = is_default;
      // defaultdict's first argument is the factory (None, builtins.list, ...): dropped.
      const std::size_t init_index = is_default ? 1 : 0;
      if (a.size() > init_index) FillDict(*node, *a[init_index], f.c_str());
      return node;
    }
    if (f == "builtins.list" || f == "builtins.tuple" || f == "builtins.set" || f == "builtins.frozenset") {
      want_args(0, 1);
      const PyKind kind = f == "builtins.list" ? PyKind::kList : f == "builtins.tuple" ? PyKind::kTuple : PyKind::kSet;
      auto node = NewContainer(kind);
      if (!a.empty()) node->items = IterableArg(*a[0], f.c_str());
      return node;
    }
    if (f == "builtins.bytes" || f == "builtins.bytearray") {
      want_args(0, 3);
      if (a.empty()) return MakeBytes({});
      if (a[0]->kind == PyKind::kStr && a.size() >= 2) return MakeBytes(EncodeText(*a[0], a[1].get()));
      if (a[0]->kind == PyKind::kBytes) {
        Charge(a[0]->text.size());
        return MakeBytes(a[0]->text);
      }
      if (a[0]->kind == PyKind::kList || a[0]->kind == PyKind::kTuple) {
        Charge(a[0]->items.size());
        std::string out;
        for (const auto& b : a[0]->items) {
          const std::int64_t v = IntArg(*b, "bytes");
          if (v < 0 || v > 255) Fail("bytes: value out of range");
          out.push_back(static_cast<char>(v));
        }
        return MakeBytes(std::move(out));
      }
      Fail(std::string("bytes: unsupported argument of type ") + PyKindName(a[0]->kind));
    }
    if (f == "_codecs.encode") {
      want_args(1, 3);
      return MakeBytes(EncodeText(*a[0], a.size() >= 2 ? a[1].get() : nullptr));
    }
    Fail("calling " + f + " is not supported");
  }

  void SetDTypeState(DType& dtype, const PyValue& state) {
    if (state.kind != PyKind::kTuple || (state.items.size() != 8 && state.items.size() != 9)) {
      Fail("dtype state: expected an 8- or 9-tuple (numpy pickle version 3/4)");
    }
    const auto& s = state.items;
    const std::int64_t version = IntArg(*s[0], "dtype state version");
    if (version != 3 && version != 4) Fail("dtype state: unsupported version " + std::to_string(version));
    if (s[1]->kind != PyKind::kStr || s[1]->text.size() != 1) Fail("dtype state: bad byte order");
    const char order = s[1]->text[0];
    if (order != '<' && order != '>' && order != '|' && order != '=') Fail("dtype state: bad byte order");
    const std::int64_t elsize = IntArg(*s[5], "dtype state elsize");
    if (dtype.kind == 'U' || dtype.kind == 'S' || dtype.kind == 'V') {
      if (elsize >= 0) {
        if (elsize > (std::int64_t{1} << 32)) Fail("dtype state: item size too large");
        if (dtype.kind == 'U' && elsize % 4 != 0) Fail("dtype state: UTF-32 item size not a multiple of 4");
        dtype.item_size = static_cast<std::size_t>(elsize);
      }
    }
    if (dtype.item_size > 1 && dtype.kind != 'S' && dtype.kind != 'V' && dtype.kind != 'O' && dtype.kind != 'b') {
      dtype.byte_order = order == '>' ? '>' : '<';
    }
    // Sub-array: (base dtype, shape).
    if (s[2]->kind != PyKind::kNone) {
      if (s[2]->kind != PyKind::kTuple || s[2]->items.size() != 2) Fail("dtype state: bad sub-array description");
      const DType& base = DTypeArg(*s[2]->items[0], "dtype sub-array");
      std::size_t count = 0;
      auto shape = ShapeArg(*s[2]->items[1], &count);
      std::size_t bytes = 0;
      if (!detail::CheckedMul(count, base.item_size, &bytes) || bytes != dtype.item_size) {
        Fail("dtype state: sub-array size does not match the item size");
      }
      if (DTypeDepth(base) >= kMaxDTypeDepth) Fail("dtype nesting too deep");
      Charge(sizeof(DTypeField) * DTypeCost(base));
      dtype.subarray_base = std::make_shared<const DType>(base);
      dtype.subarray_shape = std::move(shape);
    }
    // Structured: names tuple and fields dict name -> (dtype, offset[, title]).
    if (s[3]->kind != PyKind::kNone) {
      if (s[3]->kind != PyKind::kTuple) Fail("dtype state: field names must be a tuple");
      if (s[4]->kind != PyKind::kDict) Fail("dtype state: fields must be a dict");
      std::vector<DTypeField> fields;
      for (const auto& name : s[3]->items) {
        if (name->kind != PyKind::kStr) Fail("dtype state: field name must be a str");
        auto k = KeyString(*name);
        auto it = s[4]->key_index.find(*k);
        if (it == s[4]->key_index.end()) Fail("dtype state: no description for field " + QuoteName(name->text));
        const PyValue& desc = *s[4]->entries[it->second].second;
        if (desc.kind != PyKind::kTuple || desc.items.size() < 2) Fail("dtype state: bad field description");
        const DType& ft = DTypeArg(*desc.items[0], "dtype field");
        const std::int64_t offset = IntArg(*desc.items[1], "dtype field offset");
        if (DTypeDepth(ft) >= kMaxDTypeDepth) Fail("dtype nesting too deep");
        Charge(sizeof(DTypeField) * DTypeCost(ft));
        DTypeField field;
        field.name = name->text;
        if (ft.subarray_base) {
          field.dtype = *ft.subarray_base;
          field.shape = ft.subarray_shape;
        } else {
          field.dtype = ft;
        }
        const std::size_t size = ft.item_size;
        if (offset < 0 || static_cast<std::size_t>(offset) > dtype.item_size || size > dtype.item_size - static_cast<std::size_t>(offset)) {
          Fail("dtype state: field " + QuoteName(field.name) + " lies outside the record");
        }
        field.offset = static_cast<std::size_t>(offset);
        fields.push_back(std::move(field));
      }
      dtype.fields = std::move(fields);
    }
  }

  void SetArrayState(NdArray& array, const PyValue& state) {
    if (state.kind != PyKind::kTuple || (state.items.size() != 5 && state.items.size() != 4)) {
      Fail("ndarray state: expected (version, shape, dtype, is_fortran, data)");
    }
    const std::size_t o = state.items.size() == 5 ? 1 : 0;
    const auto& s = state.items;
    std::size_t count = 0;
    auto shape = ShapeArg(*s[o], &count);
    const DType& dtype = DTypeArg(*s[o + 1], "ndarray state");
    if (dtype.subarray_base) Fail("ndarray state: a sub-array dtype at the top level is not supported");
    if (dtype.IsStructured() && DTypeHasObjects(dtype)) Fail("structured dtypes with object fields are not supported");
    const bool fortran = IntArg(*s[o + 2], "ndarray state is_fortran") != 0;
    const PyValue& data = *s[o + 3];
    Charge(sizeof(DTypeField) * DTypeCost(dtype));
    if (dtype.kind == 'O') {
      if (data.kind != PyKind::kList) Fail(std::string("object array data: expected list, got ") + PyKindName(data.kind));
      if (data.items.size() != count) {
        Fail("object array has " + std::to_string(data.items.size()) + " items, shape needs " + std::to_string(count));
      }
      Charge(count * sizeof(PyValuePtr));
      array.objects = data.items;
      array.data.clear();
    } else {
      const std::string* raw = RawBytes(data);
      if (!raw) Fail(std::string("ndarray data: expected bytes, got ") + PyKindName(data.kind));
      std::size_t bytes = 0;
      if (!detail::CheckedMul(count, dtype.item_size, &bytes)) Fail("ndarray shape overflows the byte count");
      if (bytes != raw->size()) {
        Fail("ndarray data has " + std::to_string(raw->size()) + " bytes, shape and dtype " + dtype.Str() + " need " +
             std::to_string(bytes));
      }
      if (dtype.item_size == 0 && count > (std::size_t{1} << 24)) Fail("too many zero-size elements");
      Charge(raw->size());
      array.data.assign(raw->begin(), raw->end());
      array.objects.clear();
    }
    array.dtype = dtype;
    array.shape = std::move(shape);
    array.fortran_order = fortran;
  }

  void Build(PyValue& obj, const PyValue& state) {
    switch (obj.kind) {
      case PyKind::kNdArray: SetArrayState(*obj.array, state); return;
      case PyKind::kDType: SetDTypeState(*obj.dtype, state); return;
      case PyKind::kDict:
        // OrderedDict / defaultdict carry no instance state in practice.
        if (state.kind == PyKind::kNone || (state.kind == PyKind::kDict && state.entries.empty())) return;
        Fail("BUILD with instance state on a dict is not supported");
      default: Fail(std::string("BUILD on ") + PyKindName(obj.kind) + " is not supported");
    }
  }

  PyValuePtr Global(const std::string& module, const std::string& name) {
    std::string canonical = CanonicalGlobal(module, name);
    if (canonical.empty()) {
      std::string shown = module + "." + name;
      if (shown.size() > 200) shown = shown.substr(0, 200) + "...";
      Fail("global " + QuoteName(shown) + " is not allowed (only numpy arrays/dtypes/scalars, collections.defaultdict/"
           "OrderedDict and builtin containers may be loaded)");
    }
    auto node = std::make_shared<PyValue>();
    node->kind = PyKind::kGlobal;
    node->text = std::move(canonical);
    return node;
  }

  // ---- the interpreter ------------------------------------------------------------
  // Executes the opcode in op_; returns true at STOP.
  bool Step() {
    switch (op_) {
      case 0x80: {  // PROTO
        const std::uint8_t v = *Take(1);
        if (v > 5) Fail("unsupported pickle protocol " + std::to_string(v));
        return false;
      }
      case 0x95: {  // FRAME: framing is only an I/O hint; check the length and go on.
        const std::uint64_t n = LoadU64(Take(8));
        if (n > data_.size() - pos_) {
          throw InputError(source_ + ": truncated pickle: " + OpLabel() + " announces " + std::to_string(n) +
                           " bytes, only " + std::to_string(data_.size() - pos_) + " left");
        }
        return false;
      }
      case '.':  // STOP
        result_ = Pop();
        return true;
      case 'N': Push(none_); return false;
      case 0x88: Push(true_); return false;
      case 0x89: Push(false_); return false;
      case 'J': Push(MakeInt(static_cast<std::int32_t>(LoadU32(Take(4))))); return false;
      case 'K': Push(MakeInt(*Take(1))); return false;
      case 'M': Push(MakeInt(LoadU16(Take(2)))); return false;
      case 0x8a: {  // LONG1
        const std::size_t n = *Take(1);
        Push(MakeInt(DecodeLong(Take(n), n)));
        return false;
      }
      case 0x8b: {  // LONG4
        const std::int32_t n = static_cast<std::int32_t>(LoadU32(Take(4)));
        if (n < 0) Fail("negative length");
        Push(MakeInt(DecodeLong(Take(static_cast<std::uint64_t>(n)), static_cast<std::size_t>(n))));
        return false;
      }
      case 'G': {  // BINFLOAT, big endian
        const std::uint8_t* p = Take(8);
        std::uint64_t bits = 0;
        for (int k = 0; k < 8; ++k) bits = (bits << 8) | p[k];
        Push(MakeFloat(std::bit_cast<double>(bits)));
        return false;
      }
      case 0x8c: Push(MakeStr(TakeString(*Take(1)))); return false;
      case 'X': Push(MakeStr(TakeString(LoadU32(Take(4))))); return false;
      case 0x8d: Push(MakeStr(TakeString(LoadU64(Take(8))))); return false;
      case 'C': Push(MakeBytes(TakeString(*Take(1)))); return false;
      case 'B': Push(MakeBytes(TakeString(LoadU32(Take(4))))); return false;
      case 0x8e:
      case 0x96: Push(MakeBytes(TakeString(LoadU64(Take(8))))); return false;
      case 'U': Push(MakeStr(TakeString(*Take(1)))); return false;  // Python 2 str: raw bytes
      case 'T': {
        const std::int32_t n = static_cast<std::int32_t>(LoadU32(Take(4)));
        if (n < 0) Fail("negative length");
        Push(MakeStr(TakeString(static_cast<std::uint64_t>(n))));
        return false;
      }
      case ')': Push(NewContainer(PyKind::kTuple)); return false;
      case 't': {
        auto node = NewContainer(PyKind::kTuple);
        node->items = PopMark();
        Push(node);
        return false;
      }
      case 0x85:
      case 0x86:
      case 0x87: {
        const std::size_t n = static_cast<std::size_t>(op_ - 0x84);
        std::vector<PyValuePtr> items(n);
        for (std::size_t k = n; k-- > 0;) items[k] = Pop();
        auto node = NewContainer(PyKind::kTuple);
        node->items = std::move(items);
        Push(node);
        return false;
      }
      case ']': Push(NewContainer(PyKind::kList)); return false;
      case 'l': {
        auto node = NewContainer(PyKind::kList);
        node->items = PopMark();
        Push(node);
        return false;
      }
      case 'a': {
        PyValuePtr v = Pop();
        const PyValuePtr& list = Top();
        if (list->kind != PyKind::kList) Fail(std::string("APPEND to ") + PyKindName(list->kind));
        list->items.push_back(std::move(v));
        return false;
      }
      case 'e': {
        auto items = PopMark();
        const PyValuePtr& list = Top();
        if (list->kind != PyKind::kList) Fail(std::string("APPENDS to ") + PyKindName(list->kind));
        list->items.insert(list->items.end(), std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
        return false;
      }
      case '}': Push(NewContainer(PyKind::kDict)); return false;
      case 'd': {
        auto items = PopMark();
        if (items.size() % 2) Fail("odd number of items for a dict");
        auto node = NewContainer(PyKind::kDict);
        for (std::size_t k = 0; k < items.size(); k += 2) SetItem(*node, items[k], items[k + 1]);
        Push(node);
        return false;
      }
      case 's': {
        PyValuePtr v = Pop();
        PyValuePtr k = Pop();
        const PyValuePtr& dict = Top();
        if (dict->kind != PyKind::kDict) Fail(std::string("SETITEM on ") + PyKindName(dict->kind));
        SetItem(*dict, std::move(k), std::move(v));
        return false;
      }
      case 'u': {
        auto items = PopMark();
        if (items.size() % 2) Fail("odd number of items for SETITEMS");
        const PyValuePtr& dict = Top();
        if (dict->kind != PyKind::kDict) Fail(std::string("SETITEMS on ") + PyKindName(dict->kind));
        for (std::size_t k = 0; k < items.size(); k += 2) SetItem(*dict, items[k], items[k + 1]);
        return false;
      }
      case 0x8f: Push(NewContainer(PyKind::kSet)); return false;
      case 0x90: {
        auto items = PopMark();
        const PyValuePtr& set = Top();
        if (set->kind != PyKind::kSet) Fail(std::string("ADDITEMS on ") + PyKindName(set->kind));
        set->items.insert(set->items.end(), std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
        return false;
      }
      case 0x91: {
        auto node = NewContainer(PyKind::kSet);
        node->items = PopMark();
        Push(node);
        return false;
      }
      case '(': marks_.push_back(stack_.size()); return false;
      case '0':  // POP: like Python, an empty frame pops its mark instead
        if (stack_.size() > Floor()) {
          stack_.pop_back();
        } else {
          PopMark();
        }
        return false;
      case '1': PopMark(); return false;
      case '2': Push(Top()); return false;
      case 'q': Memoize(*Take(1)); return false;
      case 'r': Memoize(LoadU32(Take(4))); return false;
      case 0x94: Memoize(memo_.size()); return false;
      case 'h': PushMemo(*Take(1)); return false;
      case 'j': PushMemo(LoadU32(Take(4))); return false;
      case 'c': {
        std::string module = ReadLine();
        std::string name = ReadLine();
        Push(Global(module, name));
        return false;
      }
      case 0x93: {
        PyValuePtr name = Pop();
        PyValuePtr module = Pop();
        if (name->kind != PyKind::kStr || module->kind != PyKind::kStr) Fail("STACK_GLOBAL needs two str");
        Push(Global(module->text, name->text));
        return false;
      }
      case 'R': {
        PyValuePtr args = Pop();
        PyValuePtr callable = Pop();
        Push(Call(*callable, *args));
        return false;
      }
      case 0x81: {
        PyValuePtr args = Pop();
        PyValuePtr cls = Pop();
        Push(Call(*cls, *args));
        return false;
      }
      case 0x92: {
        PyValuePtr kwargs = Pop();
        PyValuePtr args = Pop();
        PyValuePtr cls = Pop();
        if (kwargs->kind != PyKind::kDict || !kwargs->entries.empty()) Fail("keyword arguments are not supported");
        Push(Call(*cls, *args));
        return false;
      }
      case 'b': {
        PyValuePtr state = Pop();
        const PyValuePtr& obj = Top();
        Build(*obj, *state);
        return false;
      }
      case 0x98:  // READONLY_BUFFER: in-band buffers are plain bytes already
        if (Top()->kind != PyKind::kBytes) Fail("READONLY_BUFFER on a non-buffer");
        return false;
      case 0x97: Fail("out-of-band buffers are not supported");
      case 'P':
      case 'Q': Fail("persistent ids are not supported");
      case 0x82:
      case 0x83:
      case 0x84: Fail("extension registry codes are not supported");
      case 'i':
      case 'o': Fail("protocol 0/1 class instantiation is not supported");
      case 'I':
      case 'L':
      case 'F':
      case 'S':
      case 'V':
      case 'g':
      case 'p': Fail("text (protocol 0/1) opcodes are not supported; only protocols 2-5");
      default:
        throw InputError(source_ + ": unknown pickle opcode " + detail::HexByte(op_) + " at byte " +
                         std::to_string(base_ + op_pos_));
    }
  }

  // ---- validation of the result ----------------------------------------------------
  // Depth-first walk with a depth cap and cycle detection; marks everything reachable.
  void Validate(const PyValuePtr& root) {
    std::unordered_map<const PyValue*, bool> done;  // false while on the current path
    Visit(root.get(), 0, done);
    for (const auto& [node, finished] : done) reachable_.insert(node);
  }

  void Visit(const PyValue* v, std::size_t depth, std::unordered_map<const PyValue*, bool>& done) {
    auto [it, inserted] = done.emplace(v, false);
    if (!inserted) {
      if (!it->second) throw InputError(source_ + ": pickle contains a reference cycle (refused)");
      return;
    }
    if (depth > kPickleMaxDepth) {
      throw InputError(source_ + ": pickle nests deeper than " + std::to_string(kPickleMaxDepth) + " levels (refused)");
    }
    for (const auto& c : v->items) Visit(c.get(), depth + 1, done);
    for (const auto& [k, val] : v->entries) {
      Visit(k.get(), depth + 1, done);
      Visit(val.get(), depth + 1, done);
    }
    if (v->array) {
      for (const auto& c : v->array->objects) Visit(c.get(), depth + 1, done);
    }
    done[v] = true;
  }

  Bytes data_;
  std::string source_;
  std::size_t base_;
  std::size_t pos_ = 0;
  std::size_t op_pos_ = 0;
  std::uint8_t op_ = 0;
  std::size_t budget_;
  PyValuePtr none_, true_, false_;
  std::vector<PyValuePtr> containers_;  // every node that can hold children (see ~Vm)
  std::vector<PyValuePtr> stack_;
  std::vector<std::size_t> marks_;
  std::unordered_map<std::uint64_t, PyValuePtr> memo_;
  PyValuePtr result_;
  std::unordered_set<const PyValue*> reachable_;
};

}  // namespace

PyView ParsePickle(std::span<const std::uint8_t> bytes, const std::string& source, std::size_t base_offset) {
  PyValuePtr root;
  {
    Vm vm(bytes, source, base_offset);
    root = vm.Run();
  }
  return PyView(std::move(root), source);
}

PyView ReadPickle(const std::filesystem::path& path) {
  const auto bytes = detail::ReadFileBytes(path);
  return ParsePickle(bytes, detail::SourceName(path));
}

}  // namespace rpt::io
