// SPDX-License-Identifier: MIT
#include "datasets/io/text_tokens.h"

#include "datasets/io/number_text.h"

#include "datasets/io/binary.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::io {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Tokens are shown in messages; a corrupt file may hold a very long one.
std::string Shown(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string shown(token.substr(0, std::min(token.size(), kMax)));
  if (token.size() > kMax) shown.append("...");  // appended: GCC 12 warns falsely (-Warray-bounds) on string + "..."
  return shown;
}

}  // namespace

TextTokens::TextTokens(std::string text, std::string source) : text_(std::move(text)), source_(std::move(source)) {}

TextTokens TextTokens::FromFile(const std::filesystem::path& path) {
  // ReadFileBytes refuses what is not a regular file (a FIFO would block the read for ever) and
  // files above the input size limit.
  const std::vector<std::uint8_t> bytes = detail::ReadFileBytes(path);
  return TextTokens(std::string(bytes.begin(), bytes.end()), path.string());
}

std::string_view TextTokens::Next() {
  while (pos_ < text_.size() && IsSpace(text_[pos_])) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return {};
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !IsSpace(text_[pos_])) ++pos_;
  token_line_ = line_;
  ++tokens_read_;
  return std::string_view(text_).substr(start, pos_ - start);
}

bool TextTokens::AtEnd() {
  std::size_t p = pos_;
  while (p < text_.size() && IsSpace(text_[p])) ++p;
  return p >= text_.size();
}

void TextTokens::ExpectEnd(const std::string& what) {
  if (AtEnd()) return;
  const std::string_view token = Next();
  Fail(QuoteName(Shown(token)) + " after the end of " + what);
}

std::int64_t TextTokens::MaxTokensLeft() const {
  // Every token but the last needs a separator: n tokens need at least 2n - 1 characters.
  const std::size_t left = text_.size() - pos_;
  return static_cast<std::int64_t>((left + 1) / 2);
}

bool TextTokens::ParseInt(std::string_view token, std::int64_t* value) { return ParseInteger(token, value); }

bool TextTokens::ParseFiniteDouble(std::string_view token, double* value) { return ParseFiniteNumber(token, value); }

std::string TextTokens::Here() const {
  return source_ + ":" + std::to_string(token_line_) + ": token " + std::to_string(tokens_read_);
}

void TextTokens::Fail(const std::string& message) const { throw InputError(Here() + ": " + message); }

void TextTokens::FailAtEnd(const std::string& what) const {
  throw InputError(source_ + ":" + std::to_string(line_) + ": unexpected end of file after token " +
                   std::to_string(tokens_read_) + ", expected " + what + " (file truncated?)");
}

void TextTokens::FailInt(std::string_view token, std::int64_t min_value, std::int64_t max_value,
                         const std::string& what) const {
  Fail(what + ": " + QuoteName(Shown(token)) + " is not an integer " + IntegerRangeText(min_value, max_value));
}

void TextTokens::FailNumber(std::string_view token, const std::string& what) const {
  Fail(what + ": " + QuoteName(Shown(token)) + " is not a finite number");
}

void TextTokens::FailCount(std::int64_t count, std::int64_t tokens_each, const std::string& what) const {
  Fail(what + " " + std::to_string(count) + ": needs " + std::to_string(count) + " x " + std::to_string(tokens_each) +
       " more numbers, the rest of the file holds at most " + std::to_string(MaxTokensLeft()));
}

}  // namespace rpt::io
