// SPDX-License-Identifier: MIT
#include "core/option_codec.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/closest_name.h"
#include "core/text.h"
#include "core/utf8.h"

namespace rpt {
namespace {

constexpr std::string_view kBlanks = " \t\r\n";

// The whole text is the integer (optional sign, decimal digits); false otherwise or out of Int's range.
template <class Int>
bool IntegerFromText(std::string_view text, Int* out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  if (first == last || (first != text.data() && *first == '-')) return false;  // "+-1" is not a number
  Int value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last) return false;
  *out = value;
  return true;
}

// The whole text is a finite number (optional sign, decimal or exponent notation).
bool NumberFromText(std::string_view text, double* out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  if (first == last || (first != text.data() && *first == '-')) return false;
  double value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool InRange(double value, const OptionSpec& spec) {
  const bool above_min = spec.min_exclusive ? value > spec.min : value >= spec.min;
  return std::isfinite(value) && above_min && value <= spec.max;
}

// A bound of a range: integers without a fraction ("1000000000"), others as FormatNumber.
std::string BoundText(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    return FixedText(value, 0);
  }
  return FormatNumber(value);
}

// "integer in [2, 64]", "number > 0", "integer".
std::string WithRange(std::string noun, const OptionSpec& spec) {
  const std::string range = OptionRangeText(spec);
  if (range.empty()) return noun;
  return noun + (range.front() == '[' || range.front() == '(' ? " in " : " ") + range;
}

// Quotes at most kMaxQuotedValueBytes of the value (a config file's value can be a long list).
constexpr std::size_t kMaxQuotedValueBytes = 80;
std::string Problem(std::string_view text, std::string_view expected) {
  std::string problem = "'";
  return problem.append(Utf8Excerpt(text, kMaxQuotedValueBytes)).append("' is not ").append(expected);
}

constexpr std::string_view kBoolProblem = "true or false (also yes/no, on/off, 1/0)";
constexpr std::string_view kNamesProblem = "a list of names ([\"a\", \"b\"] or a,b)";
constexpr std::string_view kVectorProblem = "three numbers [x, y, z] (or x,y,z)";

// One item of a list text: a JSON string (quoted) or anything else as written.
struct ListItem {
  std::string text;
  bool quoted = false;
};

void AppendUtf8(std::uint32_t code, std::string* out) {
  if (code < 0x80) {
    out->push_back(static_cast<char>(code));
  } else if (code < 0x800) {
    out->push_back(static_cast<char>(0xC0 | (code >> 6)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else if (code < 0x10000) {
    out->push_back(static_cast<char>(0xE0 | (code >> 12)));
    out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else {
    out->push_back(static_cast<char>(0xF0 | (code >> 18)));
    out->push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
}

// Four hex digits at text[*i]; advances *i.
bool ReadHex4(std::string_view text, size_t* i, std::uint32_t* code) {
  if (*i + 4 > text.size()) return false;
  const auto [ptr, ec] = std::from_chars(text.data() + *i, text.data() + *i + 4, *code, 16);
  if (ec != std::errc() || ptr != text.data() + *i + 4) return false;
  *i += 4;
  return true;
}

// The JSON string starting at text[*i] (a '"'); advances *i past its closing quote.
bool ReadJsonString(std::string_view text, size_t* i, std::string* out) {
  ++*i;
  while (*i < text.size()) {
    const char c = text[(*i)++];
    if (c == '"') return true;
    if (static_cast<unsigned char>(c) < 0x20) return false;
    if (c != '\\') {
      out->push_back(c);
      continue;
    }
    if (*i >= text.size()) return false;
    const char e = text[(*i)++];
    switch (e) {
      case '"':
      case '\\':
      case '/':
        out->push_back(e);
        break;
      case 'b':
        out->push_back('\b');
        break;
      case 'f':
        out->push_back('\f');
        break;
      case 'n':
        out->push_back('\n');
        break;
      case 'r':
        out->push_back('\r');
        break;
      case 't':
        out->push_back('\t');
        break;
      case 'u': {
        std::uint32_t code = 0;
        if (!ReadHex4(text, i, &code) || (code >= 0xDC00 && code <= 0xDFFF)) return false;
        if (code >= 0xD800 && code <= 0xDBFF) {  // a surrogate pair
          std::uint32_t low = 0;
          if (text.substr(*i, 2) != "\\u") return false;
          *i += 2;
          if (!ReadHex4(text, i, &low) || low < 0xDC00 || low > 0xDFFF) return false;
          code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        AppendUtf8(code, out);
        break;
      }
      default:
        return false;
    }
  }
  return false;
}

// The items of a list text: a JSON list when it starts with '[' (false when it is not one), else
// a comma list.
bool ReadList(std::string_view text, std::vector<ListItem>* items) {
  const std::string_view t = TrimBlanks(text);
  if (t == "\"\"") return true;  // "" (what a shell passes for `=""` inside single quotes): the empty list
  if (t.empty() || t.front() != '[') {
    for (std::string& item : SplitList(t)) items->push_back({std::move(item), false});
    return true;
  }
  size_t i = 1;
  const auto skip_blanks = [&] {
    while (i < t.size() && kBlanks.find(t[i]) != std::string_view::npos) ++i;
  };
  skip_blanks();
  if (i < t.size() && t[i] == ']') return i + 1 == t.size();
  while (true) {
    skip_blanks();
    if (i >= t.size()) return false;
    if (t[i] == '"') {
      ListItem item{{}, true};
      if (!ReadJsonString(t, &i, &item.text)) return false;
      items->push_back(std::move(item));
    } else {
      const size_t start = i;
      while (i < t.size() && std::string_view(" \t\r\n,[]{}\"").find(t[i]) == std::string_view::npos) ++i;
      if (i == start) return false;
      items->push_back({std::string(t.substr(start, i - start)), false});
    }
    skip_blanks();
    if (i >= t.size()) return false;
    if (t[i] == ']') return i + 1 == t.size();
    if (t[i++] != ',') return false;
  }
}

// `text` as a JSON string literal.
std::string JsonString(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

template <class Int>
std::string ParseInteger(std::string_view text, const OptionSpec& spec, Int* out) {
  Int value = 0;
  if (!IntegerFromText(TrimBlanks(text), &value) || !InRange(static_cast<double>(value), spec)) {
    return Problem(text, "an " + WithRange("integer", spec));
  }
  *out = value;
  return {};
}

template <class Int>
std::string CheckInteger(Int value, const OptionSpec& spec) {
  return InRange(static_cast<double>(value), spec)
             ? std::string()
             : Problem(option_codec::Format(value), "an " + WithRange("integer", spec));
}

}  // namespace

std::vector<std::string> SplitList(std::string_view text) {
  std::vector<std::string> items;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string_view item = TrimBlanks(text.substr(start, end - start));
    if (!item.empty()) items.emplace_back(item);
    start = end + 1;
  }
  return items;
}

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0) return std::signbit(value) ? "-0.0" : "0.0";
  // The shortest digits that read back exactly, laid out as JSON (nlohmann::json) writes them:
  // fixed notation with ".0" for integers up to 15 digits and for 4 leading zeros at most after
  // the point, else d.ddde+XX.
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::scientific);
  std::string_view scientific(buffer, static_cast<size_t>(end - buffer));
  std::string out;
  if (scientific.front() == '-') {
    out = "-";
    scientific.remove_prefix(1);
  }
  const size_t e = scientific.find('e');
  std::string digits(1, scientific[0]);
  if (e > 2) digits += scientific.substr(2, e - 2);
  int exponent = 0;
  std::from_chars(scientific.data() + e + (scientific[e + 1] == '+' ? 2 : 1), scientific.data() + scientific.size(),
                  exponent);
  const int k = static_cast<int>(digits.size());
  const int n = exponent + 1;  // the point sits after the first n digits
  if (k <= n && n <= 15) return out.append(digits).append(n - k, '0').append(".0");
  if (0 < n && n <= 15) return out.append(digits, 0, n).append(".").append(digits, n);
  if (-4 < n && n <= 0) return out.append("0.").append(-n, '0').append(digits);
  out.append(digits, 0, 1);
  if (k > 1) out.append(".").append(digits, 1);
  char exponent_text[16];
  std::snprintf(exponent_text, sizeof(exponent_text), "e%c%02d", n - 1 < 0 ? '-' : '+', std::abs(n - 1));
  return out.append(exponent_text);
}

std::string OptionRangeText(const OptionSpec& spec) {
  const bool has_min = std::isfinite(spec.min), has_max = std::isfinite(spec.max);
  std::string range;
  if (has_min && has_max) {
    range.append(spec.min_exclusive ? "(" : "[").append(BoundText(spec.min)).append(", ");
    range.append(BoundText(spec.max)).append("]");
  } else if (has_min) {
    range.append(spec.min_exclusive ? "> " : ">= ").append(BoundText(spec.min));
  } else if (has_max) {
    range.append("<= ").append(BoundText(spec.max));
  }
  return range;
}

std::string OptionMessage(std::string_view where, std::string_view key, std::string_view problem) {
  return std::string(where) + ": " + std::string(key) + ": " + std::string(problem);
}

namespace option_codec {

std::string Parse(std::string_view text, const OptionSpec&, bool* out) {
  const std::string_view t = TrimBlanks(text);
  if (t == "true" || t == "yes" || t == "on" || t == "1") {
    *out = true;
  } else if (t == "false" || t == "no" || t == "off" || t == "0") {
    *out = false;
  } else {
    return Problem(text, kBoolProblem);
  }
  return {};
}

std::string Parse(std::string_view text, const OptionSpec& spec, int* out) { return ParseInteger(text, spec, out); }

std::string Parse(std::string_view text, const OptionSpec& spec, std::uint64_t* out) {
  return ParseInteger(text, spec, out);
}

std::string Parse(std::string_view text, const OptionSpec& spec, double* out) {
  double value = 0;
  if (!NumberFromText(TrimBlanks(text), &value) || !InRange(value, spec)) {
    return Problem(text, "a " + WithRange("number", spec));
  }
  *out = value;
  return {};
}

std::string Parse(std::string_view text, const OptionSpec&, std::string* out) {
  *out = std::string(TrimBlanks(text));
  return {};
}

std::string Parse(std::string_view text, const OptionSpec&, std::vector<std::string>* out) {
  std::vector<ListItem> items;
  if (!ReadList(text, &items)) return Problem(text, kNamesProblem);
  const bool json = !TrimBlanks(text).empty() && TrimBlanks(text).front() == '[';
  std::vector<std::string> names;
  for (ListItem& item : items) {
    if (json && !item.quoted) return Problem(text, kNamesProblem);  // [1, 2]: JSON names are strings
    names.push_back(std::move(item.text));
  }
  *out = std::move(names);
  return {};
}

std::string Parse(std::string_view text, const OptionSpec&, Eigen::Vector3d* out) {
  std::vector<ListItem> items;
  if (!ReadList(text, &items) || items.size() != 3) return Problem(text, kVectorProblem);
  Eigen::Vector3d value;
  for (int i = 0; i < 3; ++i) {
    if (items[i].quoted || !NumberFromText(items[i].text, &value[i])) return Problem(text, kVectorProblem);
  }
  *out = value;
  return {};
}

std::string ParseName(std::string_view text, const std::vector<std::string>& names, std::size_t* index) {
  const std::string_view t = TrimBlanks(text);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == t) {
      *index = i;
      return {};
    }
  }
  return Problem(text, "one of " + Join(names)) + DidYouMean(t, names);
}

std::string Format(bool value) { return value ? "true" : "false"; }
std::string Format(int value) { return std::to_string(value); }
std::string Format(std::uint64_t value) { return std::to_string(value); }
std::string Format(double value) { return FormatNumber(value); }
std::string Format(const std::string& value) { return value; }

std::string Format(const std::vector<std::string>& value) {
  // A comma list when it reads back as the same names, else a JSON list.
  bool plain = true;
  for (const std::string& name : value) {
    plain = plain && !name.empty() && name.find(',') == std::string::npos && TrimBlanks(name) == name;
  }
  if (plain && !value.empty() && value.front().front() == '[') plain = false;
  if (plain) return Join(value, ",");
  std::string out;
  for (const std::string& name : value) AppendItem(&out, JsonString(name));
  return "[" + out + "]";
}

std::string Format(const Eigen::Vector3d& value) {
  return FormatNumber(value.x()) + "," + FormatNumber(value.y()) + "," + FormatNumber(value.z());
}

std::string TypeText(const bool*, const OptionSpec&) { return "true | false"; }
std::string TypeText(const int*, const OptionSpec& spec) { return WithRange("integer", spec); }
std::string TypeText(const std::uint64_t*, const OptionSpec& spec) { return WithRange("integer", spec); }
std::string TypeText(const double*, const OptionSpec& spec) { return WithRange("number", spec); }
std::string TypeText(const std::string*, const OptionSpec&) { return "text"; }
std::string TypeText(const std::vector<std::string>*, const OptionSpec&) { return "list of names"; }
std::string TypeText(const Eigen::Vector3d*, const OptionSpec&) { return "[x, y, z]"; }
std::string EnumTypeText(const std::vector<std::string>& names) { return Join(names, " | "); }

std::string Check(int value, const OptionSpec& spec) { return CheckInteger(value, spec); }
std::string Check(std::uint64_t value, const OptionSpec& spec) { return CheckInteger(value, spec); }

std::string Check(double value, const OptionSpec& spec) {
  return InRange(value, spec) ? std::string() : Problem(FormatNumber(value), "a " + WithRange("number", spec));
}

std::string Check(const Eigen::Vector3d& value, const OptionSpec&) {
  return value.allFinite() ? std::string() : Problem(Format(value), kVectorProblem);
}

}  // namespace option_codec
}  // namespace rpt
