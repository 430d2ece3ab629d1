// SPDX-License-Identifier: MIT
// The hostile strings every writer is tested with (issue 19): names, ids and paths as someone else's
// files may hold them. Each targets one sink's syntax (HTML and <script>, terminal, CSV, Markdown,
// XML, file names); every sink gets all of them.
#pragma once

#include <string>
#include <vector>

namespace rpt::test {

inline const std::vector<std::string>& HostileStrings() {
  static const std::vector<std::string> strings = {
      "<!--<script>",                        // HTML: opens a comment inside <script>: blanked report.html
      "</script><b>x</b>",                   // HTML: ends the data block
      "a & b \"quoted\" 'single'",           // HTML/XML entities and attribute quotes
      "\x1b[31mred\x1b[0m\x1b]0;title\x07",  // terminal: colour and window-title escape sequences
      "\xc2\x9b"
      "31m C1 CSI",                      // terminal: the one-byte C1 escape introducer (U+009B)
      "left\xe2\x80\xaeright",           // terminal: right-to-left override (U+202E)
      "line\nbreak\ttab\rreturn",        // terminal, CSV, Markdown: line breaks
      "=HYPERLINK(\"http://x\",\"y\")",  // CSV: a spreadsheet formula
      "+1+2",
      "-3",
      "@SUM(A1)",
      "'quoted",  // CSV: the other formula-leading characters, and the guard itself
      "a,b",
      "\"",
      "",                                         // CSV: comma, lone quote, empty
      "`code` | pipe *star* _under_ [l](u) <i>",  // Markdown: code span, table, emphasis, link, HTML
      "``double`` ` ",
      "`",                                            // Markdown: back-tick runs, leading/trailing back-tick
      "bad \xef\xbf\xbe \xef\xbf\xbf",                // XML: U+FFFE, U+FFFF (not allowed in XML 1.0)
      std::string("nul\0byte", 8),                    // XML, terminal: NUL
      "\x01\x02\x7f",                                 // XML, terminal: C0 controls, DEL
      "\xff\xfe invalid \xc3",                        // not UTF-8
      "Z\xc3\xbcrich \xe2\x9c\x93 \xf0\x9f\x98\x80",  // valid UTF-8 that must stay as it is
      "cam a",
      "cam/a",
      "cam_a",
      "../..",
      ".",  // file names: distinct names, one cleaned name; paths
  };
  return strings;
}

}  // namespace rpt::test
