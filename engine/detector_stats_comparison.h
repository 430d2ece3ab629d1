// SPDX-License-Identifier: MIT
// `rpt detector-stats --compare`: one markdown table with a column per detector (the input's own
// detections, then simulated profiles on the same ground truth and cameras), as in
// docs/detector_model.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "datasets/detector_stats/statistics.h"

namespace rpt::engine {

// A labelled column of the comparison table.
struct DetectorStatsColumn {
  std::string name;
  detector_stats::DetectorStats stats;
};

// `input` describes the input in the title; `seed` is the simulation seed.
void PrintDetectorStatsComparison(const std::vector<DetectorStatsColumn>& columns, const std::string& input,
                                  uint64_t seed);

}  // namespace rpt::engine
