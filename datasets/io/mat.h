// SPDX-License-Identifier: MIT
// MATLAB MAT-file level 5 reader (the format of Shelf/Campus actorsGT.mat).
//
// Supported: little-endian files ('IM'), top-level miMATRIX (14) and miCOMPRESSED (15,
// zlib) variables, the small data element format, classes double, single, int8..uint64
// (stored in any MAT storage type, e.g. a double array saved as miUINT8), logical, char
// (UTF-8/UTF-16/UTF-32/uint8/uint16 storage), complex numeric, cell arrays and structs
// (and objects, read like structs with their class name). Numeric values are converted to
// double and kept column-major with their dims, so an empty 0x0 cell and a 1x0 cell stay
// distinguishable.
// Refused with a clear message: big-endian files, MAT v4, v7.3 (HDF5-based). Sparse
// arrays, function handles and opaque classes are kept as "unsupported" values that throw
// only when they are used.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace rpt::io {

enum class MatClass : std::uint8_t {
  kUnknown = 0,
  kCell = 1,
  kStruct = 2,
  kObject = 3,
  kChar = 4,
  kSparse = 5,
  kDouble = 6,
  kSingle = 7,
  kInt8 = 8,
  kUInt8 = 9,
  kInt16 = 10,
  kUInt16 = 11,
  kInt32 = 12,
  kUInt32 = 13,
  kInt64 = 14,
  kUInt64 = 15,
  kFunction = 16,
  kOpaque = 17,
};

const char* MatClassName(MatClass mat_class);  // "double", "uint8", "cell", ...

struct MatValue {
  MatClass mat_class = MatClass::kDouble;
  bool logical = false;
  bool complex = false;
  std::vector<std::size_t> dims;  // at least 2 entries, MATLAB order (rows, cols, ...)
  std::string name;               // array name as stored (empty inside cells)
  std::string where;              // "actorsGT.mat: actor3D{1,2}{3,1}", used in messages
  std::vector<double> real;       // numeric and logical values, column-major
  std::vector<double> imag;       // complex only
  std::string text;               // char arrays (UTF-8, column-major); object class name
  std::vector<MatValue> cells;    // cell arrays, column-major
  std::vector<std::string> field_names;  // structs and objects
  std::vector<MatValue> field_values;    // element e, field f at [e * field_names.size() + f]
  std::string unsupported;        // set for sparse / function / opaque values: why

  std::size_t NumElements() const;
  bool IsEmpty() const { return NumElements() == 0; }
  bool IsNumeric() const;  // double, single, integer classes (logical included)
  bool IsCell() const { return mat_class == MatClass::kCell; }
  bool IsStruct() const { return mat_class == MatClass::kStruct || mat_class == MatClass::kObject; }
  bool IsChar() const { return mat_class == MatClass::kChar; }
  std::size_t Rows() const { return dims.empty() ? 0 : dims[0]; }
  std::size_t Cols() const;  // product of dims[1:]
  // "14x3 double", "1x0 double", "1x4 cell", "14x2 uint8", "1x1 logical".
  std::string Describe() const;

  // Throws InputError("<where>: <what>").
  [[noreturn]] void Fail(const std::string& what) const;

  // Numeric values (column-major); throws unless numeric or logical.
  const std::vector<double>& Numeric() const;
  // Element (row, col) of a 2-D numeric array, bounds-checked.
  double At(std::size_t row, std::size_t col) const;
  // Checks for a rows x cols numeric matrix and returns it row-major: value (r, c) at
  // [r * cols + c]. Message e.g. "expected a 14x3 numeric matrix, got 1x0 double".
  std::vector<double> RowMajor(std::size_t rows, std::size_t cols) const;

  const MatValue& Cell(std::size_t linear_index) const;
  const MatValue& Cell(std::size_t row, std::size_t col) const;

  const std::string& Text() const;

  bool HasField(const std::string& field) const;
  const MatValue& Field(const std::string& field, std::size_t element = 0) const;
};

struct MatFile {
  std::string source;
  std::string header_text;  // "MATLAB 5.0 MAT-file, Platform: ..."
  std::map<std::string, MatValue> variables;

  bool Has(const std::string& name) const { return variables.count(name) != 0; }
  // Throws InputError naming the file, the variable and the variables present.
  const MatValue& Get(const std::string& name) const;
};

MatFile ParseMat(std::span<const std::uint8_t> bytes, const std::string& source);
MatFile ReadMat(const std::filesystem::path& path);

}  // namespace rpt::io
