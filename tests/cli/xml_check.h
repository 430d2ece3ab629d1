// SPDX-License-Identifier: MIT
// A strict reader for the XML subset rpt writes (declaration, nested elements with quoted attributes,
// whitespace between them): enough to prove that JUnit output is well-formed and to read it back.
// With Markup::kDocument it also reads what sweep.html holds: a <!DOCTYPE ...> line and character
// data between elements (the five named entities only), kept in XmlElement::text.
#pragma once

#include <cctype>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rpt::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;  // entities decoded
  std::vector<XmlElement> children;
  std::string text;  // the element's own character data, entities decoded (Markup::kDocument only)
};

enum class Markup {
  kElementsOnly,  // JUnit: elements and whitespace
  kDocument,      // (X)HTML: also a doctype and text between elements
};

class XmlReader {
 public:
  // Throws std::runtime_error("offset N: why") when `text` is not well-formed.
  static XmlElement Parse(const std::string& text, Markup markup = Markup::kElementsOnly) {
    XmlReader reader(text);
    reader.allow_text_ = markup == Markup::kDocument;
    reader.SkipSpace();
    if (reader.allow_text_ && reader.text_.compare(reader.pos_, 9, "<!DOCTYPE") == 0) {
      const size_t end = reader.text_.find('>', reader.pos_);
      if (end == std::string::npos) reader.Fail("unterminated doctype");
      reader.pos_ = end + 1;
    }
    if (reader.text_.compare(reader.pos_, 5, "<?xml") == 0) {
      const size_t end = reader.text_.find("?>", reader.pos_);
      if (end == std::string::npos) reader.Fail("unterminated declaration");
      reader.pos_ = end + 2;
    }
    reader.SkipSpace();
    XmlElement root = reader.Element();
    reader.SkipSpace();
    if (reader.pos_ != reader.text_.size()) reader.Fail("content after the root element");
    return root;
  }

 private:
  explicit XmlReader(const std::string& text) : text_(text) {}

  [[noreturn]] void Fail(const std::string& why) const {
    throw std::runtime_error("offset " + std::to_string(pos_) + ": " + why);
  }
  void SkipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  void Expect(char c) {
    if (pos_ >= text_.size() || text_[pos_] != c) Fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  std::string Name() {
    const size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
                                   text_[pos_] == '-' || text_[pos_] == '.' || text_[pos_] == ':')) {
      ++pos_;
    }
    if (pos_ == start) Fail("expected a name");
    return text_.substr(start, pos_ - start);
  }
  // Characters up to `stop` (not consumed), entities and decimal character references (&#10;)
  // decoded; '<' is an error. In an attribute value a literal tab, newline or carriage return
  // becomes a space, as XML's attribute-value normalisation does (a line break survives only as
  // a reference).
  std::string CharacterData(char stop, const char* where, bool attribute = false) {
    std::string value;
    while (pos_ < text_.size() && text_[pos_] != stop) {
      const char c = text_[pos_];
      if (c == '<') Fail(std::string("'<' in ") + where);
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') Fail("control character");
      if (c == '&' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '#') {
        const size_t end = text_.find(';', pos_);
        if (end == std::string::npos) Fail("unterminated character reference");
        const std::string digits = text_.substr(pos_ + 2, end - pos_ - 2);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) Fail("bad character reference");
        const int code = std::stoi(digits);
        if (code < 1 || code > 127) Fail("character reference outside ASCII (not needed by rpt)");
        value += static_cast<char>(code);
        pos_ = end + 1;
        continue;
      }
      if (attribute && (c == '\t' || c == '\n' || c == '\r')) {
        value += ' ';
        ++pos_;
        continue;
      }
      if (c == '&') {
        static const std::map<std::string, char> entities = {
            {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
        const size_t end = text_.find(';', pos_);
        if (end == std::string::npos) Fail("unterminated entity");
        const auto it = entities.find(text_.substr(pos_ + 1, end - pos_ - 1));
        if (it == entities.end()) Fail("unknown entity");
        value += it->second;
        pos_ = end + 1;
        continue;
      }
      value += c;
      ++pos_;
    }
    return value;
  }
  std::string AttributeValue() {
    const char quote = text_[pos_];
    if (quote != '"' && quote != '\'') Fail("expected a quoted value");
    ++pos_;
    std::string value = CharacterData(quote, "an attribute value", /*attribute=*/true);
    Expect(quote);
    return value;
  }
  XmlElement Element() {
    Expect('<');
    XmlElement element;
    element.name = Name();
    while (true) {
      SkipSpace();
      if (pos_ >= text_.size()) Fail("unterminated tag");
      if (text_[pos_] == '/') {
        ++pos_;
        Expect('>');
        return element;
      }
      if (text_[pos_] == '>') {
        ++pos_;
        break;
      }
      const std::string key = Name();
      Expect('=');
      if (!element.attributes.emplace(key, AttributeValue()).second) Fail("repeated attribute " + key);
    }
    while (true) {
      if (allow_text_) element.text += CharacterData('<', "text");
      SkipSpace();
      if (text_.compare(pos_, 2, "</") == 0) {
        pos_ += 2;
        if (Name() != element.name) Fail("mismatched closing tag of " + element.name);
        SkipSpace();
        Expect('>');
        return element;
      }
      if (pos_ >= text_.size() || text_[pos_] != '<') Fail("expected an element or </" + element.name + ">");
      element.children.push_back(Element());
    }
  }

  const std::string& text_;
  size_t pos_ = 0;
  bool allow_text_ = false;
};

}  // namespace rpt::test
