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

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
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
  Kind Peek() {
    SkipSpace();
    if (pos_ >= text_.size()) return Kind::kEnd;
    switch (text_[pos_]) {
      case '{':
        return Kind::kObject;
      case '[':
        return Kind::kArray;
      case '"':
        return Kind::kString;
      case 't':
        return Kind::kTrue;
      case 'f':
        return Kind::kFalse;
      case 'n':
        return Kind::kNull;
      default:
        if (text_[pos_] == '-' || IsDigit(text_[pos_])) return Kind::kNumber;
        FailNoValue();
    }
  }
  // '{' or '['; throws naming what was expected otherwise.
  void BeginObject();
  void BeginArray();
  // The next member of the object begun last: true with its key (valid until the next string is
  // read), then the caller reads its value; false at the closing '}'.
  bool NextKey(std::string_view* key);
  // The next element of the array begun last: true, then the caller reads it; false at ']'.
  bool NextElement() {  // the common cases inline: a frame line holds thousands of elements
    SkipSpace();
    if (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (after_begin_) {
        after_begin_ = false;
        if (c != ']') return true;
        ++pos_;
        return false;
      }
      if (c == ',' || c == ']') {
        ++pos_;
        return c == ',';
      }
    }
    return NextElementAtEnd();
  }
  // A number (finite: a literal beyond the double range is an error).
  double Number() {
    SkipSpace();
    double value = 0;
    const Short read = ShortDecimal(&value);
    if (read == Short::kRead) return value;
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    const auto [end, error] = std::from_chars(first, last, value);
    // std::from_chars also takes what JSON does not ("01", "1.", ".5", "inf"): checked on what it
    // read, unless ShortDecimal checked its start already (then only digits and an exponent follow,
    // whose grammar is the same in both).
    if (error != std::errc() || (read != Short::kLongDecimal && !IsJsonNumber(first, end))) return NumberSlow();
    pos_ = static_cast<std::size_t>(end - text_.data());
    after_begin_ = false;
    return value;  // finite: a literal beyond the double range is a result_out_of_range error
  }
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
  static bool IsDigit(char c) { return c >= '0' && c <= '9'; }
  static bool IsJsonNumber(const char* first, const char* end);
  // Clinger's fast path for what detectors write most: [-]digits[.digits] with at most 19 digits
  // whose value m (all digits as an integer) is below 2^53, read as m / 10^(fraction digits) with
  // at most 22 of them: both exact doubles, so one division rounds the decimal value correctly,
  // as std::from_chars does. Sets *value and consumes the number (kRead); else consumes nothing
  // and says whether the text starts as a well-formed number with eight decimals or more, which
  // std::from_chars reads faster (kLongDecimal), or is anything else (exponents, longer
  // mantissas, errors: kOther). Number() takes both.
  enum class Short {
    kRead,         // read and consumed
    kLongDecimal,  // [-]digits.dddddddd... well formed up to its eighth decimal (nothing consumed)
    kOther,        // anything else (nothing consumed)
  };
  Short ShortDecimal(double* value) {
    static constexpr double kPowersOfTen[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                                1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const std::size_t n = text_.size();
    std::size_t p = pos_;
    const bool negative = p < n && text_[p] == '-';
    if (negative) ++p;
    unsigned long long m = 0;
    int digits = 0, fraction = 0;
    if (p < n && text_[p] == '0') {
      ++p;
      if (p < n && IsDigit(text_[p])) return Short::kOther;  // a leading zero: the error is Number()'s
    } else {
      if (p >= n || !IsDigit(text_[p])) return Short::kOther;
      for (; p < n && IsDigit(text_[p]); ++p, ++digits) m = m * 10 + static_cast<unsigned>(text_[p] - '0');
    }
    if (p < n && text_[p] == '.') {
      ++p;
      if (p >= n || !IsDigit(text_[p])) return Short::kOther;
      // Eight decimals or more (full-precision numbers: 16-17 significant digits, mostly beyond
      // 2^53): std::from_chars reads the number faster than this loop could before it gave up.
      if (p + 8 <= n && EightDigits(text_.data() + p)) return Short::kLongDecimal;
      for (; p < n && IsDigit(text_[p]); ++p, ++digits, ++fraction) m = m * 10 + static_cast<unsigned>(text_[p] - '0');
    }
    if (digits > 19 || fraction > 22 || m > (1ULL << 53) || (p < n && (text_[p] == 'e' || text_[p] == 'E'))) {
      return Short::kOther;
    }
    const double magnitude = static_cast<double>(m) / kPowersOfTen[fraction];
    *value = negative ? -magnitude : magnitude;
    pos_ = p;
    after_begin_ = false;
    return Short::kRead;
  }
  // Whether the eight bytes at `s` are all ASCII digits, in a few word operations: each byte's
  // high nibble is 3 and stays 3 when 6 is added (0x3a-0x3f reach 0x40); a byte whose addition
  // carries into the next has high nibble f and fails the first test.
  static bool EightDigits(const char* s) {
    std::uint64_t w = 0;
    std::memcpy(&w, s, 8);
    constexpr std::uint64_t kHigh = 0xf0f0f0f0f0f0f0f0ULL;
    return ((w & kHigh) | (((w + 0x0606060606060606ULL) & kHigh) >> 4)) == 0x3333333333333333ULL;
  }
  void SkipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      ++pos_;
    }
  }
  [[noreturn]] void FailNoValue() const;
  bool NextElementAtEnd();
  double NumberSlow();
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
