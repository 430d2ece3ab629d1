// SPDX-License-Identifier: MIT
// A tree of Python values as produced by the safe pickle VM (pickle.h) and the NPY/NPZ
// readers (npy.h): None, bool, int, float, str, bytes, list, tuple, dict, set, numpy
// ndarray (including structured and object dtypes) and numpy dtype.
//
// PyValue is the plain node; PyView is the way readers walk it: every accessor checks the
// type and throws rpt::InputError naming the file and a path-like location, e.g.
//   "cameras.pkl: key ('S1', '54138969').R: expected ndarray, got list".
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rpt::io {

struct PyValue;
using PyValuePtr = std::shared_ptr<PyValue>;

// ---------------------------------------------------------------------------------------
// numpy dtype

struct DTypeField;

struct DType {
  // numpy kind: 'b' bool, 'i' signed, 'u' unsigned, 'f' float, 'c' complex, 'U' UTF-32
  // text, 'S' bytes, 'V' void/structured, 'O' Python object.
  char kind = 'u';
  // '<' little endian, '>' big endian, '|' not applicable (1-byte, bytes, void, object).
  char byte_order = '|';
  std::size_t item_size = 1;  // bytes per element (object: 8, the pointer size numpy uses)
  // Structured dtypes: the named fields in declaration order (padding is not listed).
  std::vector<DTypeField> fields;
  // Sub-array dtype such as ('<f4', (3, 3)); only seen as the type of a structured field
  // while reading pickles, where it is folded into DTypeField::shape.
  std::shared_ptr<const DType> subarray_base;
  std::vector<std::int64_t> subarray_shape;

  bool IsStructured() const;
  bool IsObject() const { return kind == 'O'; }
  // Kinds ElementAsDouble can read: bool, integers, float16/32/64.
  bool IsRealNumeric() const;
  // numpy's type string: "<f8", "|u1", "|b1", "<U7", "|V104", "|O".
  std::string Str() const;
  const DTypeField* FindField(std::string_view name) const;
};

struct DTypeField {
  std::string name;
  DType dtype;                      // element type (scalar, or a nested structured type)
  std::vector<std::int64_t> shape;  // sub-array shape, empty for a scalar field
  std::size_t offset = 0;           // byte offset inside the record
  std::size_t ElementCount() const;  // product of shape (1 for scalars)
};

// Parses a numpy type string ("<f8", "f8", "|b1", "<U12", "|S4", "|V16", "|O", "O8").
// Returns std::nullopt for anything else (datetimes, typecodes without sizes, ...).
std::optional<DType> ParseTypeStr(std::string_view text);

// ---------------------------------------------------------------------------------------
// numpy ndarray

struct NdArray {
  DType dtype;
  std::vector<std::int64_t> shape;  // empty for a 0-d array
  bool fortran_order = false;       // storage order of data / objects
  std::vector<std::uint8_t> data;   // raw elements in storage order (not for object arrays)
  std::vector<PyValuePtr> objects;  // object arrays only, in storage order

  std::size_t Size() const;  // number of elements (1 for 0-d)
  std::size_t Ndim() const { return shape.size(); }
  std::string ShapeStr() const;  // "(17, 3)", "()", "(5,)"
  std::string Describe() const;  // "ndarray <f8 (17, 3)"
  // Storage position of the element at row-major (C-order) position c_index.
  std::size_t StorageIndex(std::size_t c_index) const;
  // Element at storage position i converted to double (bool, int, uint, float16/32/64;
  // byte order honoured). Throws InputError for other dtypes or out-of-range i.
  double ElementAsDouble(std::size_t storage_index) const;
  // Element at storage position i of an integer/bool array as int64 (uint64 > INT64_MAX throws).
  std::int64_t ElementAsInt(std::size_t storage_index) const;
  // Text of element i of a 'U' (decoded to UTF-8) or 'S' array, trailing NULs removed.
  std::string ElementAsString(std::size_t storage_index) const;
  // All elements as doubles in row-major order, whatever the storage order.
  std::vector<double> ToDoubles() const;
  // A structured array's field as its own array: shape = shape + field shape, C order.
  NdArray Field(std::string_view name) const;
};

// ---------------------------------------------------------------------------------------
// Value tree

enum class PyKind {
  kNone,
  kBool,
  kInt,
  kFloat,
  kStr,
  kBytes,
  kList,
  kTuple,
  kDict,
  kSet,  // set and frozenset
  kNdArray,
  kDType,
  kGlobal,  // an allow-listed class or function referenced but not called (e.g. a defaultdict's factory)
};

const char* PyKindName(PyKind kind);
// "(3, 17)" / "(5,)" / "()": a shape as Python prints it.
std::string ShapeToString(std::span<const std::int64_t> shape);

struct PyValue {
  PyKind kind = PyKind::kNone;
  bool bool_value = false;
  std::int64_t int_value = 0;
  double float_value = 0.0;
  // str (UTF-8; Python 2 byte strings keep their raw bytes), bytes (raw), or the
  // "module.name" of a kGlobal.
  std::string text;
  std::vector<PyValuePtr> items;                            // list, tuple, set
  std::vector<std::pair<PyValuePtr, PyValuePtr>> entries;   // dict, insertion order
  std::unordered_map<std::string, std::size_t> key_index;   // dict: KeyString(key) -> entry
  bool is_defaultdict = false;  // dict built by collections.defaultdict (treated as dict)
  std::shared_ptr<NdArray> array;  // kNdArray
  std::shared_ptr<DType> dtype;    // kDType
};

// Constructors for building keys and test values.
PyValuePtr MakeNone();
PyValuePtr MakeBool(bool value);
PyValuePtr MakeInt(std::int64_t value);
PyValuePtr MakeFloat(double value);
PyValuePtr MakeStr(std::string value);
PyValuePtr MakeBytes(std::string value);
PyValuePtr MakeTuple(std::vector<PyValuePtr> items);
PyValuePtr MakeStrTuple(std::initializer_list<std::string_view> items);

// Python-like short representation, cut at max_length characters: "('S1', '54138969')".
std::string Repr(const PyValue& value, std::size_t max_length = 120);

// Hash key used by dicts: equal for values Python considers equal keys (1, 1.0 and True
// coincide; str and bytes differ). Returns std::nullopt for unhashable values (list, dict,
// ndarray, ...) or nesting deeper than 32.
std::optional<std::string> KeyString(const PyValue& value);

// Inserts or replaces a dict entry (Python semantics: a repeated key keeps its first
// position and takes the new value). Returns false if the key is unhashable.
bool DictSet(PyValue& dict, PyValuePtr key, PyValuePtr value);

// ---------------------------------------------------------------------------------------
// PyView: a checked, path-tracking handle on a node. Cheap to copy; keeps its node alive.

class PyView {
 public:
  PyView() = default;
  PyView(std::shared_ptr<const PyValue> node, std::string source, std::string path = {});

  const PyValue& value() const { return *node_; }
  const std::shared_ptr<const PyValue>& ptr() const { return node_; }
  const std::string& source() const { return source_; }
  const std::string& path() const { return path_; }
  // "source: path" (or "source: top level") for messages.
  std::string Where() const;
  // Throws InputError("<source>: <path>: <what>").
  [[noreturn]] void Fail(std::string_view what) const;

  PyKind kind() const { return node_->kind; }
  bool IsNone() const { return kind() == PyKind::kNone; }
  bool IsDict() const { return kind() == PyKind::kDict; }
  bool IsList() const { return kind() == PyKind::kList; }
  bool IsTuple() const { return kind() == PyKind::kTuple; }
  bool IsArray() const { return kind() == PyKind::kNdArray; }
  bool IsStr() const { return kind() == PyKind::kStr; }
  // A Python int/float/bool or a numeric ndarray with exactly one element.
  bool IsNumber() const;

  bool AsBool() const;
  std::int64_t AsInt() const;   // int, bool, or a one-element integer ndarray
  double AsDouble() const;      // int, float, bool, or a one-element numeric ndarray
  const std::string& AsStr() const;
  const std::string& AsBytes() const;
  const NdArray& AsArray() const;

  // list / tuple / set / dict / object ndarray: number of elements.
  std::size_t Size() const;
  // Element i of a list, tuple, set or 1-d object ndarray.
  PyView At(std::size_t index) const;
  std::vector<PyView> Elements() const;

  // Dict lookup by str key (a Python 2 byte-string key with the same bytes also matches).
  bool Has(std::string_view key) const;
  PyView Key(std::string_view key) const;
  std::optional<PyView> Find(std::string_view key) const;
  // Dict lookup by any hashable key, e.g. Key(*MakeStrTuple({"S1", "54138969"})).
  PyView Key(const PyValue& key) const;
  std::optional<PyView> Find(const PyValue& key) const;
  // Dict entries in insertion order.
  std::vector<std::pair<PyView, PyView>> Items() const;

  // Numbers in row-major order from a numeric ndarray or a rectangular nested list/tuple
  // of numbers. expected_shape, when given, must match (-1 matches any extent); the
  // message names the expected and actual shapes.
  std::vector<double> ToDoubles(std::initializer_list<std::int64_t> expected_shape = {}) const;
  std::vector<double> ToDoubles(std::span<const std::int64_t> expected_shape) const;
  // Shape of an ndarray, or of a rectangular nested list/tuple of numbers.
  std::vector<std::int64_t> Shape() const;

  // A structured ndarray's field as an ndarray view (path "<path>.<name>").
  PyView Field(std::string_view name) const;

 private:
  PyView Child(std::shared_ptr<const PyValue> node, std::string path) const;
  std::string KeyPath(const PyValue& key) const;

  std::shared_ptr<const PyValue> node_;
  std::string source_;
  std::string path_;
};

}  // namespace rpt::io
