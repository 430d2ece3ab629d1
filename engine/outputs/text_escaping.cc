// SPDX-License-Identifier: MIT
#include "engine/outputs/text_escaping.h"

#include <algorithm>
#include <stdexcept>

#include "core/printable_text.h"
#include "datasets/io/json_output.h"

namespace rpt::engine {
namespace {

// `text` with & < > " ' as entities (HTML and XML share them).
std::string MarkupEntities(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string HtmlText(std::string_view text) { return MarkupEntities(PrintableText(text, LineBreaks::kEscape)); }

std::string ScriptJson(std::string json_text) {
  std::string out;
  out.reserve(json_text.size());
  for (size_t i = 0; i < json_text.size(); ++i) {
    const char c = json_text[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xe2' && i + 2 < json_text.size() && json_text[i + 1] == '\x80' &&
               (json_text[i + 2] == '\xa8' || json_text[i + 2] == '\xa9')) {
      out += json_text[i + 2] == '\xa8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else if (IsBidiControlAt(json_text, i)) {
      // Shown as the text "\xe2\x80\xae" (a JSON string's "\\xe2..."), as PrintableText writes it:
      // raw, a name holding one reversed the numbers after it in a caption ("16.6 px": "xp 6.61").
      for (int k = 0; k < 3; ++k, ++i) {
        const auto byte = static_cast<unsigned char>(json_text[i]);
        out += "\\\\x";
        out += "0123456789abcdef"[byte >> 4];
        out += "0123456789abcdef"[byte & 0xf];
      }
      --i;
    } else {
      out += c;
    }
  }
  return out;
}

std::string CsvField(std::string_view raw) {
  std::string text = PrintableText(raw, LineBreaks::kEscape);
  if (!text.empty() && std::string_view("=+-@'").find(text.front()) != std::string_view::npos) text = "'" + text;
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string TrcField(std::string_view text) { return PrintableText(text, LineBreaks::kEscape); }

std::vector<std::string> SplitCsvLine(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  if (quoted) throw std::invalid_argument("a quoted field is not closed");
  for (std::string& field : fields) {
    if (field.size() > 1 && field.front() == '\'' &&
        std::string_view("=+-@'").find(field[1]) != std::string_view::npos) {
      field.erase(0, 1);
    }
  }
  return fields;
}

std::string MarkdownText(std::string_view raw) {
  const std::string text = PrintableText(raw, LineBreaks::kEscape);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (std::string_view("\\`*_[]<>|~&!$").find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::string MarkdownCode(std::string_view raw) {
  const std::string text = PrintableText(raw, LineBreaks::kEscape);
  if (text.empty()) return "` `";  // "``" would be two back-ticks, not a code span
  size_t longest = 0, run = 0;
  for (const char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(longest + 1, '`');
  // A space inside each fence keeps a leading or trailing back-tick apart from it (Markdown strips one space each
  // side).
  const bool pad = !text.empty() && (text.front() == '`' || text.back() == '`' || text.front() == ' ');
  return fence + (pad ? " " : "") + text + (pad ? " " : "") + fence;
}

std::string XmlText(std::string_view text) {
  return MarkupEntities(PrintableText(io::ValidUtf8(std::string(text)), LineBreaks::kKeep));
}

std::string XmlAttributeText(std::string_view text) {
  std::string out;
  for (const char c : XmlText(text)) {
    if (c == '\n') {
      out += "&#10;";
    } else if (c == '\r') {
      out += "&#13;";
    } else if (c == '\t') {
      out += "&#9;";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace rpt::engine
