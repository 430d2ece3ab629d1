// SPDX-License-Identifier: MIT
// The quiet NaN that marks a missing number (a metric without data, a joint not seen).
#pragma once

#include <limits>

namespace rpt {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace rpt
