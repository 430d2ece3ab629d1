// SPDX-License-Identifier: MIT
// UTF-8 validation shared by the message escaping (PrintableText) and the JSON and XML writers.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rpt {

// Length of the valid UTF-8 sequence starting at text[i] (1..4), or 0 when it is not valid: bad
// lead or continuation byte, overlong form, UTF-16 surrogate, beyond U+10FFFF, cut short.
std::size_t Utf8SequenceLength(std::string_view text, std::size_t i);

// True when every byte of `text` belongs to a valid UTF-8 sequence (control characters are valid).
bool IsValidUtf8(std::string_view text);

// An excerpt for a message that quotes input: `text` when at most `max_bytes` long, else its first
// bytes up to `max_bytes` cut at a character boundary, followed by "...".
std::string Utf8Excerpt(std::string_view text, std::size_t max_bytes);

}  // namespace rpt
