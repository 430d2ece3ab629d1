// SPDX-License-Identifier: MIT
// One escaping function per kind of output, used by every writer of that kind, for text that comes
// from input files or the command line (camera, sequence, joint and configuration names, frame
// ids, paths). The terminal's is PrintableText (core/printable_text.h); each function here starts
// from it (or, for XML, from io::ValidUtf8), so control characters and escape sequences never
// reach a file raw either. tests/hostile_strings.h holds the strings every writer is tested with.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rpt::engine {

// HTML text and quoted attribute values: & < > " ' as entities, after PrintableText (line breaks
// escaped too).
std::string HtmlText(std::string_view text);

// JSON text placed inside a <script> element: every '<', '>' and '&' as \u003c, \u003e, \u0026 (so
// neither "</script" nor "<!--" can end or change the element), U+2028 and U+2029 as \u2028, \u2029
// (the JSON value is unchanged: these characters only occur inside its strings); bidirectional
// overrides and isolates become the text "\xe2\x80\xae" in their string (the page shows the names
// next to numbers, as the terminal does).
std::string ScriptJson(std::string json_text);

// A CSV field (RFC 4180): PrintableText (line breaks escaped, so a field is always one line), then a
// field starting with '=', '+', '-', '@' (a spreadsheet formula) or '\'' gets a leading '\'', and a
// field holding a comma or quote is quoted with inner quotes doubled.
std::string CsvField(std::string_view text);
// The fields of one CSV line as CsvField wrote them: quotes removed, doubled quotes single, the
// leading '\'' that CsvField added removed. Throws std::invalid_argument on an unclosed quote.
std::vector<std::string> SplitCsvLine(std::string_view line);

// A field of a tab-separated TRC file (a marker's name in the header, engine/outputs/trc_export.h):
// PrintableText with line breaks escaped, so a tab, newline or carriage return in a name is
// written as \x09, \x0a, \x0d and cannot add a column or a line.
std::string TrcField(std::string_view text);

// Markdown text (a table cell, a sentence): PrintableText (line breaks escaped), then the
// characters Markdown or inline HTML act on inside a line (\ ` * _ [ ] < > | ~ & ! $) with a
// backslash.
std::string MarkdownText(std::string_view text);
// A Markdown code span holding `text` literally: PrintableText (line breaks escaped), fenced with
// one back-tick more than the longest run inside (a back-tick in a path does not end it); "" is
// "` `".
std::string MarkdownCode(std::string_view text);

// XML text and quoted attribute values: bytes that are not valid UTF-8 as U+FFFD, the characters
// XML 1.0 forbids (controls other than tab, newline, carriage return; U+FFFE, U+FFFF) written as
// \xNN (PrintableText), & < > " ' as entities.
std::string XmlText(std::string_view text);

// XmlText for a quoted attribute value: tab, newline and carriage return as character references
// too (a parser turns them into spaces otherwise: a multi-line message lost its line breaks).
std::string XmlAttributeText(std::string_view text);

}  // namespace rpt::engine
