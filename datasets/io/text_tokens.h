// SPDX-License-Identifier: MIT
// Whitespace-separated numbers read in order from a text file, for formats that are a plain
// stream of counts and matrices (4D-Association's detection and skeleton files). Every error is
// an InputError naming the file, the line and the token number:
//   "gt.txt:17: token 905: frame 0, person 1: identity: '1.5' is not an integer".
// Reading never goes past the end of the text, and CheckCount() bounds a count by the tokens the
// rest of the text can still hold, so a corrupt count cannot trigger a huge allocation.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rpt::io {

class TextTokens {
 public:
  // `source` names the text in messages (usually the file path).
  TextTokens(std::string text, std::string source);
  // Throws InputError "<path>: file not found or unreadable".
  static TextTokens FromFile(const std::filesystem::path& path);

  // The next token as an integer in [min_value, max_value]. `what` is a callable returning the
  // description used in messages; it is only called on error.
  template <class What>
  std::int64_t Int(std::int64_t min_value, std::int64_t max_value, const What& what) {
    const std::string_view token = Next();
    if (token.empty()) FailAtEnd(what());
    std::int64_t value = 0;
    if (!ParseInt(token, &value) || value < min_value || value > max_value) {
      FailInt(token, min_value, max_value, what());
    }
    return value;
  }

  // The next token as a finite number; on error as Int().
  template <class What>
  double Number(const What& what) {
    const std::string_view token = Next();
    if (token.empty()) FailAtEnd(what());
    double value = 0;
    if (!ParseFiniteDouble(token, &value)) FailNumber(token, what());
    return value;
  }

  // Throws unless `count` items of `tokens_each` tokens each can still follow (at most one token
  // per two characters remain): "<Here()>: <what> N: needs N x E more numbers, the rest of the
  // file holds at most M".
  template <class What>
  void CheckCount(std::int64_t count, std::int64_t tokens_each, const What& what) {
    if (count > 0 && tokens_each > 0 && count > MaxTokensLeft() / tokens_each) FailCount(count, tokens_each, what());
  }

  // True when only whitespace is left.
  bool AtEnd();
  // Throws "<Here()>: '<token>' after the end of <what>" when anything but whitespace is left.
  void ExpectEnd(const std::string& what);
  // "<source>:<line>: token <n>" of the last token read (token 0 = none read yet).
  std::string Here() const;
  // Throws InputError "<Here()>: <message>".
  [[noreturn]] void Fail(const std::string& message) const;

  const std::string& source() const { return source_; }
  long line() const { return token_line_; }      // line of the last token read (1-based)
  long tokens_read() const { return tokens_read_; }

 private:
  std::string_view Next();  // empty at the end of the text
  std::int64_t MaxTokensLeft() const;
  static bool ParseInt(std::string_view token, std::int64_t* value);
  static bool ParseFiniteDouble(std::string_view token, double* value);
  [[noreturn]] void FailAtEnd(const std::string& what) const;
  [[noreturn]] void FailInt(std::string_view token, std::int64_t min_value, std::int64_t max_value,
                            const std::string& what) const;
  [[noreturn]] void FailNumber(std::string_view token, const std::string& what) const;
  [[noreturn]] void FailCount(std::int64_t count, std::int64_t tokens_each, const std::string& what) const;

  std::string text_;
  std::string source_;
  std::size_t pos_ = 0;
  long line_ = 1;        // line at pos_
  long token_line_ = 1;  // line of the last token read
  long tokens_read_ = 0;
};

}  // namespace rpt::io
