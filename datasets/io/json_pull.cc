// SPDX-License-Identifier: MIT
#include "datasets/io/json_pull.h"

#include <locale.h>
#include <stdlib.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/errors.h"
#include "core/utf8.h"
#include "datasets/io/json_file.h"

namespace rpt::io {
namespace {

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void AppendUtf8(std::string* out, unsigned code_point) {
  if (code_point < 0x80) {
    out->push_back(static_cast<char>(code_point));
  } else if (code_point < 0x800) {
    out->push_back(static_cast<char>(0xC0 | (code_point >> 6)));
    out->push_back(static_cast<char>(0x80 | (code_point & 0x3F)));
  } else if (code_point < 0x10000) {
    out->push_back(static_cast<char>(0xE0 | (code_point >> 12)));
    out->push_back(static_cast<char>(0x80 | ((code_point >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code_point & 0x3F)));
  } else {
    out->push_back(static_cast<char>(0xF0 | (code_point >> 18)));
    out->push_back(static_cast<char>(0x80 | ((code_point >> 12) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | ((code_point >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code_point & 0x3F)));
  }
}

// What a character is, for "expected X, got Y".
std::string Describe(std::string_view text, std::size_t pos) {
  if (pos >= text.size()) return "the end of the line";
  const std::string_view rest = text.substr(pos);
  // What writers put where JSON has no value: Python's json.dumps writes NaN and Infinity; some
  // editors and Windows tools start a file with a byte-order mark.
  for (const std::string_view word : {"NaN", "Infinity", "-Infinity"}) {
    if (rest.starts_with(word)) {
      return "'" + std::string(word) +
             "', which is not JSON (a missing joint is [null, null, 0] or has score 0; Python: "
             "json.dumps(..., allow_nan=False) finds them)";
    }
  }
  if (rest.starts_with("\xEF\xBB\xBF")) return "a UTF-8 byte-order mark (write the text without it)";
  const unsigned char c = static_cast<unsigned char>(text[pos]);
  if (c >= 0x20 && c < 0x7F) return std::string("'") + static_cast<char>(c) + "'";
  char hex[8];
  std::snprintf(hex, sizeof(hex), "\\x%02X", c);
  return std::string("byte ") + hex;
}

}  // namespace

void JsonPull::Reset(std::string_view text) {
  text_ = text;
  pos_ = 0;
  after_begin_ = false;
}

void JsonPull::Fail(const std::string& what) const {
  throw InputError("column " + std::to_string(column()) + ": " + what);
}

void JsonPull::Expect(char c, const char* what) {
  SkipSpace();
  if (pos_ >= text_.size() || text_[pos_] != c)
    Fail(std::string("expected ") + what + ", got " + Describe(text_, pos_));
  ++pos_;
}

void JsonPull::FailNoValue() const { Fail("expected a JSON value, got " + Describe(text_, pos_)); }

bool JsonPull::IsJsonNumber(const char* first, const char* end) {
  const char* p = first;
  if (p < end && *p == '-') ++p;
  if (p == end || !IsDigit(*p)) return false;
  if (*p == '0' && p + 1 < end && IsDigit(p[1])) return false;  // a leading zero
  for (; p < end; ++p) {
    if (*p == '.') return p + 1 < end && IsDigit(p[1]);  // a digit after the point
    if (*p == 'e' || *p == 'E') return true;             // from_chars read a whole exponent
  }
  return true;
}

void JsonPull::BeginObject() {
  Expect('{', "an object '{'");
  after_begin_ = true;
}

void JsonPull::BeginArray() {
  Expect('[', "a list '['");
  after_begin_ = true;
}

bool JsonPull::NextKey(std::string_view* key) {
  SkipSpace();
  if (after_begin_) {
    after_begin_ = false;
    if (pos_ < text_.size() && text_[pos_] == '}') {
      ++pos_;
      return false;
    }
  } else {
    if (pos_ < text_.size() && text_[pos_] == '}') {
      ++pos_;
      return false;
    }
    Expect(',', "',' or '}'");
  }
  SkipSpace();
  if (pos_ >= text_.size() || text_[pos_] != '"') Fail("expected a key (a string), got " + Describe(text_, pos_));
  *key = String();
  Expect(':', "':'");
  return true;
}

// NextElement at the end of the text, or before a character that is neither ',' nor ']'.
bool JsonPull::NextElementAtEnd() {
  if (after_begin_) {  // the value that should come next reports what is there
    after_begin_ = false;
    return true;
  }
  Expect(',', "',' or ']'");
  return true;
}

// The text of the number at pos_ (RFC 8259: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?),
// consumed.
std::string_view JsonPull::NumberText() {
  SkipSpace();
  const std::size_t start = pos_;
  std::size_t p = pos_;
  const std::size_t n = text_.size();
  if (p < n && text_[p] == '-') ++p;
  if (p < n && text_[p] == '0') {
    ++p;
  } else if (p < n && IsDigit(text_[p])) {
    while (p < n && IsDigit(text_[p])) ++p;
  } else {
    pos_ = p;
    Fail("expected a number, got " + Describe(text_, p));
  }
  if (p < n && text_[p] == '.') {
    ++p;
    if (p >= n || !IsDigit(text_[p])) {
      pos_ = p;
      Fail("expected a digit after '.', got " + Describe(text_, p));
    }
    while (p < n && IsDigit(text_[p])) ++p;
  }
  if (p < n && (text_[p] == 'e' || text_[p] == 'E')) {
    ++p;
    if (p < n && (text_[p] == '+' || text_[p] == '-')) ++p;
    if (p >= n || !IsDigit(text_[p])) {
      pos_ = p;
      Fail("expected a digit in the exponent, got " + Describe(text_, p));
    }
    while (p < n && IsDigit(text_[p])) ++p;
  }
  pos_ = p;
  after_begin_ = false;
  return text_.substr(start, p - start);
}

// Number's way when std::from_chars did not read a JSON number: the precise error, or a literal
// below the double range (read as what strtod makes of it).
double JsonPull::NumberSlow() {
  SkipSpace();
  const std::size_t start = pos_;
  const std::string_view number = NumberText();
  double value = 0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Beyond the double range (1e400) or below its smallest value (1e-400): strtod says which, read
    // in the C locale (the process's LC_NUMERIC may want a decimal comma).
    static const locale_t c_locale = ::newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
    const std::string copy(number);
    value = ::strtod_l(copy.c_str(), nullptr, c_locale);
  } else if (error != std::errc() || end != number.data() + number.size()) {
    pos_ = start;
    Fail("expected a number");
  }
  if (!std::isfinite(value)) {
    pos_ = start;
    Fail("number " + std::string(number.substr(0, kMaxQuotedBytes)) + " is beyond the range of a double");
  }
  return value;
}

std::string_view JsonPull::IntegerText() {
  SkipSpace();
  const std::size_t start = pos_;
  const std::string_view number = NumberText();
  if (number.find_first_of(".eE") != std::string_view::npos) {
    pos_ = start;
    return {};
  }
  return number;
}

std::string_view JsonPull::String() {
  SkipSpace();
  if (pos_ >= text_.size() || text_[pos_] != '"') Fail("expected a string, got " + Describe(text_, pos_));
  const std::size_t start = ++pos_;
  // Fast path: no escape before the closing quote.
  std::size_t p = start;
  while (p < text_.size()) {
    const unsigned char c = static_cast<unsigned char>(text_[p]);
    if (c == '"' || c == '\\' || c < 0x20) break;
    ++p;
  }
  if (p < text_.size() && text_[p] == '"') {
    const std::string_view value = text_.substr(start, p - start);
    if (!IsValidUtf8(value)) Fail("string is not valid UTF-8");
    pos_ = p + 1;
    after_begin_ = false;
    return value;
  }
  return DecodeString(start);
}

std::string_view JsonPull::DecodeString(std::size_t start) {
  decoded_.clear();
  std::size_t p = start;
  const std::size_t n = text_.size();
  const auto fail_at = [&](std::size_t at, const std::string& what) {
    pos_ = at;
    Fail(what);
  };
  const auto hex4 = [&](std::size_t at) {
    if (at + 4 > n) fail_at(at, "expected 4 hex digits after \\u");
    unsigned value = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      const int digit = HexValue(text_[at + i]);
      if (digit < 0) fail_at(at + i, "expected 4 hex digits after \\u");
      value = value * 16 + static_cast<unsigned>(digit);
    }
    return value;
  };
  while (true) {
    if (p >= n) fail_at(p, "unterminated string");
    const unsigned char c = static_cast<unsigned char>(text_[p]);
    if (c == '"') break;
    if (c < 0x20) fail_at(p, "control character in a string (write it escaped)");
    if (c != '\\') {
      decoded_.push_back(static_cast<char>(c));
      ++p;
      continue;
    }
    if (p + 1 >= n) fail_at(p, "unterminated string");
    const char escape = text_[p + 1];
    p += 2;
    switch (escape) {
      case '"':
        decoded_.push_back('"');
        break;
      case '\\':
        decoded_.push_back('\\');
        break;
      case '/':
        decoded_.push_back('/');
        break;
      case 'b':
        decoded_.push_back('\b');
        break;
      case 'f':
        decoded_.push_back('\f');
        break;
      case 'n':
        decoded_.push_back('\n');
        break;
      case 'r':
        decoded_.push_back('\r');
        break;
      case 't':
        decoded_.push_back('\t');
        break;
      case 'u': {
        unsigned code_point = hex4(p);
        p += 4;
        if (code_point >= 0xDC00 && code_point <= 0xDFFF) fail_at(p - 6, "unpaired surrogate \\u escape");
        if (code_point >= 0xD800 && code_point <= 0xDBFF) {
          if (p + 2 > n || text_[p] != '\\' || text_[p + 1] != 'u') fail_at(p - 6, "unpaired surrogate \\u escape");
          const unsigned low = hex4(p + 2);
          if (low < 0xDC00 || low > 0xDFFF) fail_at(p, "unpaired surrogate \\u escape");
          code_point = 0x10000 + ((code_point - 0xD800) << 10) + (low - 0xDC00);
          p += 6;
        }
        AppendUtf8(&decoded_, code_point);
        break;
      }
      default:
        fail_at(p - 1, "invalid escape \\" + Describe(text_, p - 1));
    }
  }
  if (!IsValidUtf8(decoded_)) fail_at(start, "string is not valid UTF-8");
  pos_ = p + 1;
  after_begin_ = false;
  return decoded_;
}

bool JsonPull::Literal(std::string_view word) {
  if (text_.substr(pos_, word.size()) != word) Fail("expected a JSON value, got " + Describe(text_, pos_));
  pos_ += word.size();
  after_begin_ = false;
  return true;
}

bool JsonPull::Null() {
  if (Peek() != Kind::kNull) return false;
  return Literal("null");
}

void JsonPull::SkipValue(int depth) {
  switch (Peek()) {
    case Kind::kObject: {
      if (depth >= kMaxJsonDepth) Fail("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      BeginObject();
      std::string_view key;
      while (NextKey(&key)) SkipValue(depth + 1);
      break;
    }
    case Kind::kArray:
      if (depth >= kMaxJsonDepth) Fail("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      BeginArray();
      while (NextElement()) SkipValue(depth + 1);
      break;
    case Kind::kString:
      String();
      break;
    case Kind::kNumber:
      NumberText();
      break;
    case Kind::kTrue:
      Literal("true");
      break;
    case Kind::kFalse:
      Literal("false");
      break;
    case Kind::kNull:
      Literal("null");
      break;
    case Kind::kEnd:
      Fail("expected a JSON value, got the end of the line");
  }
}

void JsonPull::Skip() { SkipValue(0); }

void JsonPull::End() {
  SkipSpace();
  if (pos_ < text_.size()) Fail("unexpected " + Describe(text_, pos_) + " after the end of the JSON value");
}

}  // namespace rpt::io
