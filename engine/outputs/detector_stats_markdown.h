// SPDX-License-Identifier: MIT
// `rpt detector-stats`: the statistics of one input as markdown tables on stdout (per view, per
// joint, confidences); `input` describes the input in the title.
#pragma once

#include <string>

#include "datasets/detector_stats/statistics.h"

namespace rpt::engine {

void PrintDetectorStatsMarkdown(const detector_stats::DetectorStats& stats, const std::string& input);

}  // namespace rpt::engine
