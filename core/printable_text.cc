// SPDX-License-Identifier: MIT
#include "core/printable_text.h"

#include <algorithm>
#include <cstdint>

#include "core/utf8.h"

namespace rpt {

namespace {

bool IsBidiControl(std::string_view text, std::size_t i, std::size_t length) {
  if (length != 3 || static_cast<std::uint8_t>(text[i]) != 0xe2) return false;
  const unsigned code = 0x2000u + ((static_cast<std::uint8_t>(text[i + 1]) & 0x3fu) << 6) +
                        (static_cast<std::uint8_t>(text[i + 2]) & 0x3fu);
  return (code >= 0x202a && code <= 0x202e) || (code >= 0x2066 && code <= 0x2069);  // overrides, isolates
}

void AppendEscaped(std::string_view bytes, std::string* out) {
  static const char* const kHex = "0123456789abcdef";
  for (const char byte : bytes) {
    const auto c = static_cast<std::uint8_t>(byte);
    *out += "\\x";
    *out += kHex[c >> 4];
    *out += kHex[c & 0xf];
  }
}

// Is the valid sequence of `length` bytes at text[i] a character the terminal must not see raw?
bool MustEscape(std::string_view text, std::size_t i, std::size_t length, LineBreaks line_breaks) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[i + k]); };
  if (length == 1) {
    const std::uint8_t c = byte(0);
    if (line_breaks == LineBreaks::kKeep && (c == '\n' || c == '\t')) return false;
    return c < 0x20 || c == 0x7f;
  }
  if (length == 2) return byte(0) == 0xc2 && byte(1) < 0xa0;  // C1 controls U+0080-U+009F
  if (IsBidiControl(text, i, length)) return true;
  if (length == 3 && byte(0) == 0xef && byte(1) == 0xbf) return byte(2) >= 0xbe;  // noncharacters U+FFFE, U+FFFF
  return false;
}

}  // namespace

std::string PrintableText(std::string_view text, LineBreaks line_breaks) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = Utf8SequenceLength(text, i);
    if (length == 0 || MustEscape(text, i, length, line_breaks)) {
      AppendEscaped(text.substr(i, std::max<std::size_t>(length, 1)), &out);
      i += std::max<std::size_t>(length, 1);
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

bool IsBidiControlAt(std::string_view text, std::size_t i) {
  return i + 3 <= text.size() && IsBidiControl(text, i, Utf8SequenceLength(text, i));
}

std::string QuoteName(std::string_view name) { return "'" + PrintableText(name, LineBreaks::kEscape) + "'"; }

std::string JoinNames(const std::vector<std::string>& names, std::string_view separator) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += separator;
    out += PrintableText(names[i], LineBreaks::kEscape);
  }
  return out;
}

}  // namespace rpt
