// SPDX-License-Identifier: MIT
// `rpt detector-stats --json`: the statistics of one input as a JSON object.
#pragma once

#include <nlohmann/json.hpp>

#include "datasets/detector_stats/statistics.h"

namespace rpt::engine {

nlohmann::ordered_json DetectorStatsJson(const detector_stats::DetectorStats& stats);

}  // namespace rpt::engine
