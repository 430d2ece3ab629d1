// SPDX-License-Identifier: MIT
// The terminal's escaping: text for messages and lines that quote input (names, attribute values,
// tokens read from files, paths): valid UTF-8 is kept as it is; bytes that are not valid UTF-8,
// control characters (C0 other than newline and tab, DEL, C1 such as U+009B, the one-character
// escape sequence introducer) and the bidirectional overrides U+202A-U+202E and U+2066-U+2069
// (which reorder what a terminal shows) and the noncharacters U+FFFE and U+FFFF are written as
// \xNN per byte. Errors, warnings and
// printed names then never send an escape sequence or raw binary from a file to a terminal or a log.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rpt {

// kKeep: newline and tab stay (a message of several lines); kEscape: they are escaped too (one name
// inside a line: a camera, a sequence, a frame id, a path).
enum class LineBreaks { kKeep, kEscape };

std::string PrintableText(std::string_view text, LineBreaks line_breaks = LineBreaks::kKeep);

// Whether text[i] starts a bidirectional override or isolate (U+202A-U+202E, U+2066-U+2069; three
// bytes in UTF-8), which PrintableText escapes: shown raw, a name holding one reverses the text
// after it ("16.6 px" reads "xp 6.61").
bool IsBidiControlAt(std::string_view text, std::size_t i);

// A name from the input (a frame id, a camera, a joint, a key, a path) for a message or a line:
// in single quotes, PrintableText with line breaks escaped, so a crafted name can neither split
// the line nor act on the terminal.
std::string QuoteName(std::string_view name);

// Names from the input listed in a message ("cam0, cam1"): each PrintableText with line breaks
// escaped, unquoted (a name's newline split the message and could forge a line of its own).
std::string JoinNames(const std::vector<std::string>& names, std::string_view separator = ", ");

}  // namespace rpt
