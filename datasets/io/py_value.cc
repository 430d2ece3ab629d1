// SPDX-License-Identifier: MIT
// PyValue helpers and PyView (datasets/io/py_value.h); dtypes and ndarrays are in py_ndarray.cc.
#include "datasets/io/py_value.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::io {
namespace {

constexpr std::size_t kMaxKeyDepth = 32;
constexpr std::size_t kMaxListShapeDepth = 32;

std::string DescribePyValue(const PyValue& v) {
  if (v.kind == PyKind::kNdArray && v.array) return v.array->Describe();
  return PyKindName(v.kind);
}

bool IsIdentifier(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

void ReprInto(const PyValue& v, std::string& out, std::size_t max_length, std::size_t depth) {
  if (out.size() > max_length) return;
  if (depth > 16) {
    out += "...";
    return;
  }
  auto quoted = [&](const std::string& s, bool bytes) {
    if (bytes) out += 'b';
    out += '\'';
    for (char c : s) {
      if (out.size() > max_length) return;
      const auto u = static_cast<unsigned char>(c);
      if (c == '\'' || c == '\\') {
        out += '\\';
        out += c;
      } else if (u < 0x20 || (bytes && u >= 0x7f)) {
        char buf[8];
        std::snprintf(buf, sizeof(buf), "\\x%02x", u);
        out += buf;
      } else {
        out += c;
      }
    }
    out += '\'';
  };
  switch (v.kind) {
    case PyKind::kNone: out += "None"; break;
    case PyKind::kBool: out += v.bool_value ? "True" : "False"; break;
    case PyKind::kInt: out += std::to_string(v.int_value); break;
    case PyKind::kFloat: {
      out += GeneralText(v.float_value, 17);
      break;
    }
    case PyKind::kStr: quoted(v.text, false); break;
    case PyKind::kBytes: quoted(v.text, true); break;
    case PyKind::kList:
    case PyKind::kTuple:
    case PyKind::kSet: {
      out += v.kind == PyKind::kList ? "[" : v.kind == PyKind::kTuple ? "(" : "{";
      for (std::size_t i = 0; i < v.items.size(); ++i) {
        if (out.size() > max_length) break;
        if (i) out += ", ";
        ReprInto(*v.items[i], out, max_length, depth + 1);
      }
      if (v.kind == PyKind::kTuple && v.items.size() == 1) out += ",";
      out += v.kind == PyKind::kList ? "]" : v.kind == PyKind::kTuple ? ")" : "}";
      break;
    }
    case PyKind::kDict: {
      out += "{";
      for (std::size_t i = 0; i < v.entries.size(); ++i) {
        if (out.size() > max_length) break;
        if (i) out += ", ";
        ReprInto(*v.entries[i].first, out, max_length, depth + 1);
        out += ": ";
        ReprInto(*v.entries[i].second, out, max_length, depth + 1);
      }
      out += "}";
      break;
    }
    case PyKind::kNdArray: out += v.array ? v.array->Describe() : "ndarray"; break;
    case PyKind::kDType: out += "dtype('" + (v.dtype ? v.dtype->Str() : std::string("?")) + "')"; break;
    case PyKind::kGlobal: out += "<" + v.text + ">"; break;
  }
}

std::optional<std::string> KeyStringImpl(const PyValue& v, std::size_t depth) {
  if (depth > kMaxKeyDepth) return std::nullopt;
  switch (v.kind) {
    case PyKind::kNone: return std::string("N");
    case PyKind::kBool: return std::string(v.bool_value ? "i1" : "i0");
    case PyKind::kInt: return "i" + std::to_string(v.int_value);
    case PyKind::kFloat: {
      const double d = v.float_value;
      // Python: 2.0 == 2 as dict keys.
      if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9.2e18) {
        return "i" + std::to_string(static_cast<std::int64_t>(d));
      }
      char buf[32];
      std::snprintf(buf, sizeof(buf), "f%016llx", static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(d)));
      return std::string(buf);
    }
    case PyKind::kStr: return "s" + std::to_string(v.text.size()) + ":" + v.text;
    case PyKind::kBytes: return "b" + std::to_string(v.text.size()) + ":" + v.text;
    case PyKind::kGlobal: return "g" + v.text;
    case PyKind::kTuple: {
      std::string s = "t" + std::to_string(v.items.size()) + "(";
      for (const auto& item : v.items) {
        auto k = KeyStringImpl(*item, depth + 1);
        if (!k) return std::nullopt;
        s += std::to_string(k->size());
        s += ':';
        s += *k;
      }
      return s + ")";
    }
    default: return std::nullopt;
  }
}

std::string StrKeyString(std::string_view key) { return "s" + std::to_string(key.size()) + ":" + std::string(key); }
std::string BytesKeyString(std::string_view key) { return "b" + std::to_string(key.size()) + ":" + std::string(key); }

}  // namespace

// ---------------------------------------------------------------------------------------
// Value helpers

const char* PyKindName(PyKind kind) {
  switch (kind) {
    case PyKind::kNone: return "None";
    case PyKind::kBool: return "bool";
    case PyKind::kInt: return "int";
    case PyKind::kFloat: return "float";
    case PyKind::kStr: return "str";
    case PyKind::kBytes: return "bytes";
    case PyKind::kList: return "list";
    case PyKind::kTuple: return "tuple";
    case PyKind::kDict: return "dict";
    case PyKind::kSet: return "set";
    case PyKind::kNdArray: return "ndarray";
    case PyKind::kDType: return "dtype";
    case PyKind::kGlobal: return "global";
  }
  return "?";
}

namespace {

// A new value of `kind` whose `field` holds `value`.
template <class T>
PyValuePtr MakeWith(PyKind kind, T PyValue::*field, T value) {
  auto v = std::make_shared<PyValue>();
  v->kind = kind;
  (*v).*field = std::move(value);
  return v;
}

}  // namespace

PyValuePtr MakeNone() { return std::make_shared<PyValue>(); }
PyValuePtr MakeBool(bool value) { return MakeWith(PyKind::kBool, &PyValue::bool_value, value); }
PyValuePtr MakeInt(std::int64_t value) { return MakeWith(PyKind::kInt, &PyValue::int_value, value); }
PyValuePtr MakeFloat(double value) { return MakeWith(PyKind::kFloat, &PyValue::float_value, value); }
PyValuePtr MakeStr(std::string value) { return MakeWith(PyKind::kStr, &PyValue::text, std::move(value)); }
PyValuePtr MakeBytes(std::string value) { return MakeWith(PyKind::kBytes, &PyValue::text, std::move(value)); }
PyValuePtr MakeTuple(std::vector<PyValuePtr> items) {
  return MakeWith(PyKind::kTuple, &PyValue::items, std::move(items));
}
PyValuePtr MakeStrTuple(std::initializer_list<std::string_view> items) {
  std::vector<PyValuePtr> values;
  for (auto s : items) values.push_back(MakeStr(std::string(s)));
  return MakeTuple(std::move(values));
}

std::string Repr(const PyValue& value, std::size_t max_length) {
  std::string out;
  ReprInto(value, out, max_length, 0);
  if (out.size() > max_length) {
    out.resize(max_length);
    out += "...";
  }
  return out;
}

std::optional<std::string> KeyString(const PyValue& value) { return KeyStringImpl(value, 0); }

bool DictSet(PyValue& dict, PyValuePtr key, PyValuePtr value) {
  auto k = KeyString(*key);
  if (!k) return false;
  auto it = dict.key_index.find(*k);
  if (it != dict.key_index.end()) {
    dict.entries[it->second].second = std::move(value);
  } else {
    dict.key_index.emplace(std::move(*k), dict.entries.size());
    dict.entries.emplace_back(std::move(key), std::move(value));
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// PyView

PyView::PyView(std::shared_ptr<const PyValue> node, std::string source, std::string path)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)) {
  if (!node_) node_ = MakeNone();
}

std::string PyView::Where() const { return source_ + ": " + (path_.empty() ? std::string("top level") : path_); }

void PyView::Fail(std::string_view what) const { throw InputError(Where() + ": " + std::string(what)); }

PyView PyView::Child(std::shared_ptr<const PyValue> node, std::string path) const {
  return PyView(std::move(node), source_, std::move(path));
}

std::string PyView::KeyPath(const PyValue& key) const {
  if (path_.empty()) return "key " + Repr(key, 80);
  if (key.kind == PyKind::kStr && IsIdentifier(key.text)) return path_ + "." + key.text;
  return path_ + "[" + Repr(key, 80) + "]";
}

bool PyView::IsNumber() const {
  switch (kind()) {
    case PyKind::kBool:
    case PyKind::kInt:
    case PyKind::kFloat: return true;
    case PyKind::kNdArray: return node_->array->dtype.IsRealNumeric() && node_->array->Size() == 1;
    default: return false;
  }
}

bool PyView::AsBool() const {
  if (kind() == PyKind::kBool) return node_->bool_value;
  if (kind() == PyKind::kInt) return node_->int_value != 0;
  if (kind() == PyKind::kNdArray && node_->array->dtype.kind == 'b' && node_->array->Size() == 1) {
    return node_->array->ElementAsDouble(0) != 0.0;
  }
  Fail("expected bool, got " + DescribePyValue(*node_));
}

std::int64_t PyView::AsInt() const {
  if (kind() == PyKind::kInt) return node_->int_value;
  if (kind() == PyKind::kBool) return node_->bool_value ? 1 : 0;
  if (kind() == PyKind::kNdArray && node_->array->Size() == 1) {
    const char k = node_->array->dtype.kind;
    if ((k == 'i' || k == 'u' || k == 'b') && node_->array->dtype.IsRealNumeric()) {
      try {
        return node_->array->ElementAsInt(0);
      } catch (const InputError& e) {
        Fail(e.what());
      }
    }
  }
  Fail("expected int, got " + DescribePyValue(*node_));
}

double PyView::AsDouble() const {
  switch (kind()) {
    case PyKind::kInt: return static_cast<double>(node_->int_value);
    case PyKind::kFloat: return node_->float_value;
    case PyKind::kBool: return node_->bool_value ? 1.0 : 0.0;
    case PyKind::kNdArray:
      if (IsNumber()) return node_->array->ElementAsDouble(0);
      break;
    default: break;
  }
  Fail("expected a number, got " + DescribePyValue(*node_));
}

const std::string& PyView::AsStr() const {
  if (kind() != PyKind::kStr) Fail("expected str, got " + DescribePyValue(*node_));
  return node_->text;
}

const std::string& PyView::AsBytes() const {
  if (kind() != PyKind::kBytes) Fail("expected bytes, got " + DescribePyValue(*node_));
  return node_->text;
}

const NdArray& PyView::AsArray() const {
  if (kind() != PyKind::kNdArray || !node_->array) Fail("expected ndarray, got " + DescribePyValue(*node_));
  return *node_->array;
}

std::size_t PyView::Size() const {
  switch (kind()) {
    case PyKind::kList:
    case PyKind::kTuple:
    case PyKind::kSet: return node_->items.size();
    case PyKind::kDict: return node_->entries.size();
    case PyKind::kNdArray: return node_->array->Size();
    default: break;
  }
  Fail("expected a container, got " + DescribePyValue(*node_));
}

PyView PyView::At(std::size_t index) const {
  const std::string child_path = path_ + "[" + std::to_string(index) + "]";
  switch (kind()) {
    case PyKind::kList:
    case PyKind::kTuple:
    case PyKind::kSet:
      if (index >= node_->items.size()) {
        Fail("index " + std::to_string(index) + " out of range (size " + std::to_string(node_->items.size()) + ")");
      }
      return Child(node_->items[index], child_path);
    case PyKind::kNdArray: {
      const NdArray& a = *node_->array;
      if (a.dtype.kind != 'O' || a.Ndim() != 1) Fail("expected a list or 1-d object array, got " + a.Describe());
      if (index >= a.Size()) Fail("index " + std::to_string(index) + " out of range (size " + std::to_string(a.Size()) + ")");
      return Child(a.objects.at(index), child_path);
    }
    default: break;
  }
  Fail("expected list or tuple, got " + DescribePyValue(*node_));
}

std::vector<PyView> PyView::Elements() const {
  const std::size_t n = Size();
  if (kind() == PyKind::kDict) Fail("expected list or tuple, got dict");
  std::vector<PyView> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(At(i));
  return out;
}

std::optional<PyView> PyView::Find(std::string_view key) const {
  if (kind() != PyKind::kDict) Fail("expected dict, got " + DescribePyValue(*node_));
  auto it = node_->key_index.find(StrKeyString(key));
  if (it == node_->key_index.end()) it = node_->key_index.find(BytesKeyString(key));
  if (it == node_->key_index.end()) return std::nullopt;
  const auto& entry = node_->entries[it->second];
  return Child(entry.second, KeyPath(*entry.first));
}

bool PyView::Has(std::string_view key) const { return Find(key).has_value(); }

PyView PyView::Key(std::string_view key) const {
  if (auto found = Find(key)) return *found;
  Key(*MakeStr(std::string(key)));  // throws with the list of keys
  Fail("missing key");
}

std::optional<PyView> PyView::Find(const PyValue& key) const {
  if (kind() != PyKind::kDict) Fail("expected dict, got " + DescribePyValue(*node_));
  auto k = KeyString(key);
  if (!k) Fail("unhashable key " + Repr(key));
  auto it = node_->key_index.find(*k);
  if (it == node_->key_index.end()) return std::nullopt;
  const auto& entry = node_->entries[it->second];
  return Child(entry.second, KeyPath(*entry.first));
}

PyView PyView::Key(const PyValue& key) const {
  if (auto found = Find(key)) return *found;
  std::string keys;
  for (std::size_t i = 0; i < node_->entries.size() && i < 8; ++i) {
    if (i) keys += ", ";
    keys += Repr(*node_->entries[i].first, 60);
  }
  if (node_->entries.size() > 8) keys += ", ...";
  Fail("missing key " + Repr(key, 80) + " (" + std::to_string(node_->entries.size()) + " keys: " + keys + ")");
}

std::vector<std::pair<PyView, PyView>> PyView::Items() const {
  if (kind() != PyKind::kDict) Fail("expected dict, got " + DescribePyValue(*node_));
  std::vector<std::pair<PyView, PyView>> out;
  out.reserve(node_->entries.size());
  for (const auto& [k, v] : node_->entries) {
    const std::string p = KeyPath(*k);
    out.emplace_back(Child(k, p + " (the key)"), Child(v, p));
  }
  return out;
}

namespace {

// Shape of a rectangular nested list/tuple of numbers (leaves may be numeric ndarrays).
std::optional<std::vector<std::int64_t>> NestedShape(const PyValue& v, std::size_t depth) {
  if (depth > kMaxListShapeDepth) return std::nullopt;
  switch (v.kind) {
    case PyKind::kBool:
    case PyKind::kInt:
    case PyKind::kFloat: return std::vector<std::int64_t>{};
    case PyKind::kNdArray:
      if (v.array->dtype.IsRealNumeric()) return v.array->shape;
      return std::nullopt;
    case PyKind::kList:
    case PyKind::kTuple: {
      std::optional<std::vector<std::int64_t>> inner;
      for (const auto& item : v.items) {
        auto s = NestedShape(*item, depth + 1);
        if (!s) return std::nullopt;
        if (inner && *inner != *s) return std::nullopt;
        inner = std::move(s);
      }
      std::vector<std::int64_t> shape{static_cast<std::int64_t>(v.items.size())};
      if (inner) shape.insert(shape.end(), inner->begin(), inner->end());
      return shape;
    }
    default: return std::nullopt;
  }
}

void FlattenNested(const PyValue& v, std::vector<double>& out) {
  switch (v.kind) {
    case PyKind::kBool: out.push_back(v.bool_value ? 1.0 : 0.0); break;
    case PyKind::kInt: out.push_back(static_cast<double>(v.int_value)); break;
    case PyKind::kFloat: out.push_back(v.float_value); break;
    case PyKind::kNdArray: {
      auto values = v.array->ToDoubles();
      out.insert(out.end(), values.begin(), values.end());
      break;
    }
    default:
      for (const auto& item : v.items) FlattenNested(*item, out);
      break;
  }
}

}  // namespace

std::vector<std::int64_t> PyView::Shape() const {
  if (kind() == PyKind::kNdArray) return node_->array->shape;
  auto s = NestedShape(*node_, 0);
  if (!s) Fail("expected an array of numbers, got " + DescribePyValue(*node_) + " (not a rectangular nest of numbers)");
  return *s;
}

std::vector<double> PyView::ToDoubles(std::initializer_list<std::int64_t> expected_shape) const {
  return ToDoubles(std::span<const std::int64_t>(expected_shape.begin(), expected_shape.size()));
}

std::vector<double> PyView::ToDoubles(std::span<const std::int64_t> expected) const {
  std::vector<std::int64_t> shape;
  if (kind() == PyKind::kNdArray) {
    const NdArray& a = *node_->array;
    if (!a.dtype.IsRealNumeric() && a.dtype.kind != 'O') Fail("expected a numeric array, got " + a.Describe());
    shape = a.shape;
  } else {
    shape = Shape();
  }
  if (!expected.empty()) {
    bool ok = expected.size() == shape.size();
    for (std::size_t i = 0; ok && i < shape.size(); ++i) ok = expected[i] < 0 || expected[i] == shape[i];
    if (!ok)
      Fail("expected shape " + ShapeToString(expected) + ", got " + DescribePyValue(*node_) + " of shape " +
           ShapeToString(shape));
  }
  try {
    if (kind() == PyKind::kNdArray) return node_->array->ToDoubles();
    std::vector<double> out;
    FlattenNested(*node_, out);
    return out;
  } catch (const InputError& e) {
    Fail(e.what());
  }
}

PyView PyView::Field(std::string_view name) const {
  const NdArray& a = AsArray();
  if (!a.dtype.IsStructured()) Fail("expected a structured array, got " + a.Describe());
  if (!a.dtype.FindField(name)) {
    std::string names;
    for (const auto& f : a.dtype.fields) {
      if (!names.empty()) names += ", ";
      names += f.name;
    }
    Fail("structured array has no field " + QuoteName(std::string(name)) + " (fields: " + names + ")");
  }
  auto node = std::make_shared<PyValue>();
  node->kind = PyKind::kNdArray;
  try {
    node->array = std::make_shared<NdArray>(a.Field(name));
  } catch (const InputError& e) {
    Fail(e.what());
  }
  return Child(node, path_ + "." + std::string(name));
}

}  // namespace rpt::io
