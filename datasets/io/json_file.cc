// SPDX-License-Identifier: MIT
#include "datasets/io/json_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <new>
#include <optional>
#include <unordered_set>
#include <utility>

#include "core/errors.h"
#include "core/utf8.h"
#include "datasets/io/number_text.h"
#include "datasets/io/binary.h"
#include "datasets/io/input_limits.h"

namespace rpt::io {
namespace {

std::string ShownPointer(const std::string& pointer) { return pointer.empty() ? std::string("/") : pointer; }

[[noreturn]] void Fail(const std::string& source, const std::string& pointer, const std::string& what) {
  throw InputError(source + ": " + ShownPointer(pointer) + ": " + what);
}

std::string TypeName(const nlohmann::json& j) { return j.type_name(); }

// nlohmann reports a byte offset; count lines/columns for the message (1-based; the
// offset points just past the offending character).
void LineColumn(std::string_view text, std::size_t byte, std::size_t* line, std::size_t* column) {
  byte = std::min(byte, text.size());
  *line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i + 1 < byte; ++i) {
    if (text[i] == '\n') {
      ++*line;
      line_start = i + 1;
    }
  }
  *column = byte > line_start ? byte - line_start : 1;
}

std::string CutText(std::string_view text, std::size_t max_bytes) { return Utf8Excerpt(text, max_bytes); }

// nlohmann quotes the token it stopped at ("last read: '<token>'", "number overflow parsing
// '<token>'"): a string token runs to the end of its line, a number token as long as its digits.
// The quote is cut to kMaxQuotedBytes.
std::string BoundQuote(const std::string& message) {
  const std::size_t open = message.find('\'');
  const std::size_t close = message.rfind('\'');
  if (open == std::string::npos || close <= open) return message;
  return message.substr(0, open + 1) + CutText(std::string_view(message).substr(open + 1, close - open - 1), kMaxQuotedBytes) +
         message.substr(close);
}

// The byte at which `text` (JSON) first opens its (limit + 1)-th nested array or object.
std::size_t TooDeepAt(std::string_view text, int limit) {
  int depth = 0;
  for (std::size_t pos = 0; pos < text.size(); ++pos) {
    const char c = text[pos];
    if (c == '"') {
      for (++pos; pos < text.size() && text[pos] != '"'; ++pos) pos += text[pos] == '\\' ? 1 : 0;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return pos;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return text.size();
}

[[noreturn]] void ThrowAt(std::string_view text, const std::string& source, std::size_t position, const std::string& what) {
  std::size_t line = 0, column = 0;
  LineColumn(text, position, &line, &column);
  throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
}

[[noreturn]] void ThrowTooDeep(std::string_view text, const std::string& source) {
  ThrowAt(text, source, TooDeepAt(text, kMaxJsonDepth) + 1,
          "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (no file rpt reads needs more than 6)");
}

// nlohmann's parse error without its "[json.exception.parse_error.101] parse error at line 1, column 2: " prefix.
std::string ParseErrorText(const nlohmann::detail::exception& e) {
  std::string msg = e.what();
  if (msg.rfind("[json.exception", 0) == 0) {
    if (auto p = msg.find("] "); p != std::string::npos) msg = msg.substr(p + 2);
    if (msg.rfind("parse error", 0) == 0) {
      if (auto p = msg.find(": "); p != std::string::npos) msg = msg.substr(p + 2);
    }
  }
  return "JSON parse error: " + BoundQuote(msg);
}

// A nlohmann SAX handler (the DOM builder, or the acceptor that only checks), except that every error the parser reports (syntax errors and number
// overflows such as 1e400, which nlohmann reports as out_of_range.406 rather than parse_error)
// becomes an InputError naming the source, line and column, and that arrays and objects nested
// deeper than kMaxJsonDepth stop the parse. sax_parse calls the methods of this type (it is a
// template on the SAX type), so hiding the base's methods is enough.
// The byte position of the n-th (1-based) object key of `text`: a string followed by ':'.
std::size_t NthKeyAt(std::string_view text, std::size_t n) {
  std::size_t keys = 0;
  for (std::size_t pos = 0; pos < text.size(); ++pos) {
    if (text[pos] != '"') continue;
    const std::size_t start = pos;
    for (++pos; pos < text.size() && text[pos] != '"'; ++pos) pos += text[pos] == '\\' ? 1 : 0;
    std::size_t next = pos + 1;
    while (next < text.size() && (text[next] == ' ' || text[next] == '\t' || text[next] == '\n' || text[next] == '\r')) ++next;
    if (next < text.size() && text[next] == ':' && ++keys == n) return start;
  }
  return text.size();
}

template <class Sax>
class Guarded : public Sax {
 public:
  template <class... SaxArgs>
  Guarded(std::string_view text, const std::string& source, SaxArgs&&... sax_args)
      : Sax(std::forward<SaxArgs>(sax_args)...), text_(text), source_(source) {}

  bool start_object(std::size_t size) {
    if (++depth_ > kMaxJsonDepth) ThrowTooDeep(text_, source_);
    // This level's keys start anew (the lists keep their memory for the next object).
    if (keys_.size() < static_cast<std::size_t>(depth_)) keys_.resize(depth_);
    keys_[depth_ - 1].small.clear();
    keys_[depth_ - 1].large.clear();
    return Sax::start_object(size);
  }
  // A key given twice in one object: nlohmann keeps the last value unseen (a second "views": []
  // emptied a frame). Refused naming the line and column of the second.
  bool key(typename Sax::string_t& name) {
    ++key_count_;
    const std::uint64_t hash = std::hash<std::string_view>{}(name);
    ObjectKeys& keys = keys_[depth_ - 1];
    bool seen = false;
    if (keys.large.empty()) {
      seen = std::find(keys.small.begin(), keys.small.end(), hash) != keys.small.end();
      keys.small.push_back(hash);
      if (keys.small.size() > 32) keys.large.insert(keys.small.begin(), keys.small.end());  // many keys: a set
    } else {
      seen = !keys.large.insert(hash).second;
    }
    if (seen) {
      ThrowAt(text_, source_, NthKeyAt(text_, key_count_) + 1,
              "key " + QuoteName(CutText(name, kMaxQuotedBytes)) + " appears twice in this object (the second would replace the first unseen)");
    }
    return Sax::key(name);
  }
  bool start_array(std::size_t size) {
    if (++depth_ > kMaxJsonDepth) ThrowTooDeep(text_, source_);
    return Sax::start_array(size);
  }
  bool end_object() {
    --depth_;
    return Sax::end_object();
  }
  bool end_array() {
    --depth_;
    return Sax::end_array();
  }

  [[noreturn]] bool parse_error(std::size_t position, const std::string& /*token*/, const nlohmann::detail::exception& e) {
    ThrowAt(text_, source_, position, ParseErrorText(e));
  }

 private:
  struct ObjectKeys {
    std::vector<std::uint64_t> small;      // the keys' hashes so far
    std::unordered_set<std::uint64_t> large;  // the same, once there are many
  };
  std::string_view text_;
  const std::string& source_;
  int depth_ = 0;
  std::vector<ObjectKeys> keys_;  // per nesting level
  std::size_t key_count_ = 0;     // keys so far, to find the position of a repeated one
};

// Builds the document; and the same errors without the document.
template <class Json>
using DomBuilder = Guarded<nlohmann::detail::json_sax_dom_parser<Json>>;
using SyntaxChecker = Guarded<nlohmann::detail::json_sax_acceptor<nlohmann::json>>;

// Empties `value` from the innermost elements out, without allocating: nlohmann's destructor
// first copies an array's or object's elements into a new list (to avoid recursion), which when
// memory has just run out throws std::bad_alloc inside a destructor and ends the process. Depth is
// bounded by kMaxJsonDepth.
template <class Json>
void FreeWithoutAllocating(Json& value) {
  if (value.is_array()) {
    while (!value.empty()) {
      FreeWithoutAllocating(value.back());
      value.erase(value.size() - 1);
    }
  } else if (value.is_object()) {
    while (!value.empty()) {
      auto last = value.begin();
      FreeWithoutAllocating(last.value());
      value.erase(last);
    }
  }
}

template <class Json>
Json Parse(std::string_view text, const std::string& source) {
  Json root;  // outside the try: still whole in the handler, which frees it without allocating
  try {
    DomBuilder<Json> builder(text, source, root, /*allow_exceptions=*/true);
    Json::sax_parse(text.begin(), text.end(), &builder);
  } catch (const std::bad_alloc&) {
    FreeWithoutAllocating(root);
    throw InputError(source + ": out of memory parsing " + std::to_string(text.size() >> 20) +
                     " MB of JSON (a document takes several times its file size in memory)");
  }
  return root;
}

// Appends `value`'s JSON text (compact, as dump() writes it) to `out` until `out` is longer than `limit` bytes: each level of
// nesting writes a byte before it recurses, so the recursion ends within `limit` levels.
template <class Json>
void AppendExcerpt(const Json& value, std::size_t limit, std::string* out) {
  auto quoted = [&](const std::string& text) {
    const std::size_t room = limit + 1 - std::min(limit + 1, out->size());
    return Json(CutText(text, room)).dump(-1, ' ', false, Json::error_handler_t::replace);
  };
  if (value.is_object() || value.is_array()) {
    const bool object = value.is_object();
    out->push_back(object ? '{' : '[');
    for (auto it = value.begin(); it != value.end() && out->size() <= limit; ++it) {
      if (it != value.begin()) out->push_back(',');
      if (object) out->append(quoted(it.key()) + ":");
      AppendExcerpt(it.value(), limit, out);
    }
    out->push_back(object ? '}' : ']');
  } else if (value.is_string()) {
    out->append(quoted(value.template get_ref<const typename Json::string_t&>()));
  } else {
    out->append(value.dump());
  }
}

template <class Json>
std::string Excerpt(const Json& value, std::size_t max_bytes) {
  std::string text;
  AppendExcerpt(value, max_bytes, &text);
  return CutText(text, max_bytes);
}

bool IsJsonSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

nlohmann::json ParseJsonText(std::string_view text, const std::string& source) {
  return Parse<nlohmann::json>(text, source);
}

void CheckJsonText(std::string_view text, const std::string& source) {
  SyntaxChecker checker(text, source);
  nlohmann::json::sax_parse(text.begin(), text.end(), &checker);
}

std::optional<std::vector<std::pair<std::size_t, std::size_t>>> JsonArrayElements(std::string_view text) {
  std::size_t pos = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // a UTF-8 BOM
  while (pos < text.size() && IsJsonSpace(text[pos])) ++pos;
  if (pos >= text.size() || text[pos] != '[') return std::nullopt;
  std::vector<std::pair<std::size_t, std::size_t>> elements;
  constexpr std::size_t kNone = std::string_view::npos;
  std::size_t first = kNone, last = kNone;  // first and last byte of the element being scanned
  int depth = 0;
  for (++pos; pos < text.size(); ++pos) {
    const char c = text[pos];
    if (IsJsonSpace(c)) continue;
    if (depth == 0 && (c == ',' || c == ']')) {
      if (first != kNone) elements.emplace_back(first, last + 1);
      first = kNone;
      if (c == ']') break;
      continue;
    }
    if (first == kNone) first = pos;
    if (c == '"') {
      for (++pos; pos < text.size() && text[pos] != '"'; ++pos) pos += text[pos] == '\\' ? 1 : 0;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    }
    last = pos;
  }
  return elements;
}

nlohmann::json LoadJsonFile(const std::filesystem::path& path) {
  const auto bytes = detail::ReadFileBytes(path);
  return ParseJsonText(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), detail::SourceName(path));
}

nlohmann::ordered_json LoadOrderedJsonFile(const std::filesystem::path& path) {
  const auto bytes = detail::ReadFileBytes(path);
  return Parse<nlohmann::ordered_json>(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                                       detail::SourceName(path));
}

std::string JsonExcerpt(const nlohmann::json& value, std::size_t max_bytes) { return Excerpt(value, max_bytes); }
std::string JsonExcerpt(const nlohmann::ordered_json& value, std::size_t max_bytes) { return Excerpt(value, max_bytes); }

std::string JsonPointerJoin(std::string_view base, std::string_view token) {
  std::string out(base);
  out += '/';
  for (char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string JsonPointerJoin(std::string_view base, std::size_t index) { return std::string(base) + "/" + std::to_string(index); }

const nlohmann::json* JsonFind(const nlohmann::json& root, const std::string& pointer) {
  try {
    const nlohmann::json::json_pointer ptr(pointer);
    if (!root.contains(ptr)) return nullptr;
    return &root.at(ptr);
  } catch (const nlohmann::json::exception&) {
    return nullptr;  // malformed pointer or an index into a non-array
  }
}

const nlohmann::json& JsonAt(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const nlohmann::json* j = JsonFind(root, pointer);
  if (!j) Fail(source, pointer, "missing");
  return *j;
}

double JsonNumber(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const auto& j = JsonAt(root, pointer, source);
  if (!j.is_number()) Fail(source, pointer, "expected a number, got " + TypeName(j));
  return j.get<double>();
}

std::optional<std::int64_t> JsonToInt64(const nlohmann::json& j) {
  if (j.is_number_unsigned()) {
    const auto u = j.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return std::nullopt;
    return static_cast<std::int64_t>(u);
  }
  if (j.is_number_integer()) return j.get<std::int64_t>();
  if (j.is_number_float()) {
    // Integral doubles inside the int64 range; 2^63 itself is the first double outside it.
    const double d = j.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && d >= -0x1p63 && d < 0x1p63) return static_cast<std::int64_t>(d);
  }
  return std::nullopt;
}

std::int64_t JsonInt(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const auto& j = JsonAt(root, pointer, source);
  if (const auto value = JsonToInt64(j)) return *value;
  if (j.is_number_unsigned() || (j.is_number_float() && j.get<double>() == std::floor(j.get<double>()))) {
    Fail(source, pointer, "integer " + JsonExcerpt(j) + " is outside the 64-bit signed range");
  }
  Fail(source, pointer, "expected an integer, got " + (j.is_number() ? JsonExcerpt(j) : TypeName(j)));
}

std::int64_t JsonIntIn(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                       std::int64_t min_value, std::int64_t max_value) {
  const std::int64_t value = JsonInt(root, pointer, source);
  if (value < min_value || value > max_value) {
    Fail(source, pointer, std::to_string(value) + " is not an integer " + IntegerRangeText(min_value, max_value));
  }
  return value;
}

bool JsonBool(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const auto& j = JsonAt(root, pointer, source);
  if (!j.is_boolean()) Fail(source, pointer, "expected true or false, got " + TypeName(j));
  return j.get<bool>();
}

std::string JsonString(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const auto& j = JsonAt(root, pointer, source);
  if (!j.is_string()) Fail(source, pointer, "expected a string, got " + TypeName(j));
  return j.get<std::string>();
}

std::vector<double> JsonNumbers(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                                std::size_t expected_count) {
  const auto& j = JsonAt(root, pointer, source);
  const std::string want =
      expected_count == kAnyCount ? std::string("an array of numbers") : "an array of " + std::to_string(expected_count) + " numbers";
  if (!j.is_array()) Fail(source, pointer, "expected " + want + ", got " + TypeName(j));
  if (expected_count != kAnyCount && j.size() != expected_count) {
    Fail(source, pointer, "expected " + want + ", got " + std::to_string(j.size()) + " elements");
  }
  std::vector<double> out;
  out.reserve(j.size());
  for (const auto& v : j) {
    if (!v.is_number()) Fail(source, pointer, "expected " + want + ", found " + TypeName(v) + " at index " + std::to_string(out.size()));
    out.push_back(v.get<double>());
  }
  return out;
}

std::vector<double> JsonMatrix(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                               std::size_t rows, std::size_t cols) {
  const auto& j = JsonAt(root, pointer, source);
  const std::string want = "expected " + std::to_string(rows) + "x" + std::to_string(cols) + " array of numbers";
  if (!j.is_array()) Fail(source, pointer, want + ", got " + TypeName(j));
  std::vector<double> out;
  out.reserve(rows * cols);
  // Flat form.
  if (j.size() == rows * cols && std::all_of(j.begin(), j.end(), [](const nlohmann::json& v) { return v.is_number(); })) {
    for (const auto& v : j) out.push_back(v.get<double>());
    return out;
  }
  if (j.size() != rows) Fail(source, pointer, want + ", got " + std::to_string(j.size()) + " rows");
  for (std::size_t r = 0; r < rows; ++r) {
    const auto& row = j[r];
    if (!row.is_array() || row.size() != cols) {
      Fail(source, pointer, want + ", row " + std::to_string(r) + " is " + (row.is_array() ? std::to_string(row.size()) + " long" : TypeName(row)));
    }
    for (const auto& v : row) {
      if (!v.is_number()) Fail(source, pointer, want + ", found " + TypeName(v) + " in row " + std::to_string(r));
      out.push_back(v.get<double>());
    }
  }
  return out;
}

std::vector<std::string> JsonObjectKeysNumericOrder(const nlohmann::json& object) {
  auto small_integer = [](const std::string& text) {
    return !text.empty() && text.size() <= 9 &&
           std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  };
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  if (std::all_of(keys.begin(), keys.end(), small_integer)) {
    std::sort(keys.begin(), keys.end(),
              [](const std::string& a, const std::string& b) {
                long long x = 0;
                long long y = 0;
                ParseInteger(a, &x);  // small_integer() checked every key
                ParseInteger(b, &y);
                return x < y;
              });
  }
  return keys;
}

void ForEachJsonCamera(const nlohmann::json& root, const std::string& source, const std::string& members,
                       const std::function<void(const std::string& id, const std::string& pointer)>& per_camera) {
  if (!root.is_object()) throw InputError(source + ": expected an object keyed by camera id");
  if (root.empty()) throw InputError(source + ": no cameras");
  CheckCameraCount(root.size(), source + ": /");
  for (const std::string& id : JsonObjectKeysNumericOrder(root)) {
    const std::string pointer = JsonPointerJoin("", id);
    if (!root.at(id).is_object()) throw InputError(source + ": " + pointer + ": expected an object with " + members);
    per_camera(id, pointer);
  }
}

}  // namespace rpt::io
