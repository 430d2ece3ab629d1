// SPDX-License-Identifier: MIT
// Text for messages that quote input (names, attribute values, tokens read from files): valid
// UTF-8 is kept as it is; bytes that are not valid UTF-8, and control characters other than
// newline and tab, are written as \xNN. Errors and warnings then never send raw binary from a
// damaged file to a terminal, a log or a JSON report.
#pragma once

#include <string>
#include <string_view>

namespace rpt {

std::string PrintableText(std::string_view text);

}  // namespace rpt
