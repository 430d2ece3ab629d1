// SPDX-License-Identifier: MIT
// Walks JSON text one character at a time and tells the characters of its strings (the quotes,
// escapes and contents) from the rest: for scans that act on the structure only (splitting a
// --grid value at commas outside lists and strings, dropping the blanks between tokens).
#pragma once

namespace rpt::io {

class JsonStringScanner {
 public:
  // Feeds the next character; true when it belongs to a string (its opening or closing quote too).
  bool InString(char c) {
    if (in_string_) {
      if (escaped_) {
        escaped_ = false;
      } else if (c == '\\') {
        escaped_ = true;
      } else if (c == '"') {
        in_string_ = false;
      }
      return true;
    }
    in_string_ = c == '"';
    return in_string_;
  }

 private:
  bool in_string_ = false, escaped_ = false;
};

}  // namespace rpt::io
