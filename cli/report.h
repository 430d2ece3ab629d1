// SPDX-License-Identifier: MIT
// Shared formatting of timing tables for the terminal and for JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "metrics/timing.h"

namespace rpt::cli {

// One line per step: name, median and mean microseconds; then the frame total.
void PrintStepTimes(std::ostream& out, const metrics::TimingSummary& timing);

// {"undistort": median_us, ...} in step order.
nlohmann::ordered_json StepTimesJson(const metrics::TimingSummary& timing);

}  // namespace rpt::cli
