// SPDX-License-Identifier: MIT
// A number with a fixed count of decimals, as the JSON outputs write coordinates (6 decimals),
// scores (4) and times (6): the same characters as std::to_chars(value, std::chars_format::fixed,
// decimals), which rounds the exact binary value correctly, but several times faster for the
// numbers a frame holds (std::to_chars takes a general, slow path for a fixed precision; a live
// frame's output line holds about 300 numbers).
#pragma once

#include <string>

namespace rpt::engine {

// Appends `value` (finite) with `decimals` digits after the point (0 to 6 on the fast path; up to
// 80 through std::to_chars itself): "-0.000000" for small negative values and -0.0, as
// std::to_chars writes them.
void AppendFixedDecimal(double value, int decimals, std::string* out);

}  // namespace rpt::engine
