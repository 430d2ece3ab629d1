// SPDX-License-Identifier: MIT
// A pull parser of JSON text in memory, for a format read value by value as it arrives (the
// detection lines of `rpt triangulate --follow`, datasets/readers/detection_lines.h), where a
// document tree would cost more than the triangulation of the frame: the caller asks for the value
// it expects next and nothing is built. Numbers are read with std::from_chars, strings without
// escapes are views into the text, a string with escapes is decoded into a buffer that is reused,
// so a warm parser allocates nothing.
//
// The grammar is RFC 8259's, checked strictly: no trailing commas, comments, NaN, leading zeros or
// '+', no control characters in strings, strings valid UTF-8 (escaped surrogates paired). Values
// nest at most kMaxJsonDepth levels (the limit of io/json_file.h). Every error throws InputError
// "column C: <what>" (C: the 1-based byte offset of the offending character); the caller prefixes
// the source and the line.
//
//   JsonPull json(line);
//   json.BeginObject();
//   std::string_view key;
//   while (json.NextKey(&key)) {
//     if (key == "views") { json.BeginArray(); while (json.NextElement()) json.Skip(); }
//     else json.Skip();
//   }
//   json.End();
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rpt::io {

class JsonPull {
 public:
  enum class Kind { kObject, kArray, kString, kNumber, kTrue, kFalse, kNull, kEnd };

  explicit JsonPull(std::string_view text = {}) { Reset(text); }
  // Parses `text` from its start (the decoding buffer is kept).
  void Reset(std::string_view text);

  // The kind of the next value (after whitespace), kEnd at the end of the text; throws on a
  // character no value starts with.
  Kind Peek();
  // '{' or '['; throws naming what was expected otherwise.
  void BeginObject();
  void BeginArray();
  // The next member of the object begun last: true with its key (valid until the next string is
  // read), then the caller reads its value; false at the closing '}'.
  bool NextKey(std::string_view* key);
  // The next element of the array begun last: true, then the caller reads it; false at ']'.
  bool NextElement();
  // A number (finite: a literal beyond the double range is an error).
  double Number();
  // A number written as an integer literal (no fraction, no exponent): its text, else empty
  // (nothing is consumed then).
  std::string_view IntegerText();
  // A string, decoded; valid until the next string is read.
  std::string_view String();
  // Consumes `null` and returns true when the next value is null; else consumes nothing.
  bool Null();
  // One value of any kind.
  void Skip();
  // Only whitespace is left.
  void End();

  // 1-based byte column of the next character (for messages).
  std::size_t column() const { return pos_ + 1; }
  // Throws InputError "column C: <what>" at the next character.
  [[noreturn]] void Fail(const std::string& what) const;

 private:
  void SkipSpace();
  void Expect(char c, const char* what);
  std::string_view NumberText();
  void SkipValue(int depth);
  bool Literal(std::string_view word);
  std::string_view DecodeString(std::size_t start);

  std::string_view text_;
  std::size_t pos_ = 0;
  // A container was just begun: its first element (or its end) comes next, without a comma.
  bool after_begin_ = false;
  std::string decoded_;
};

}  // namespace rpt::io
