// SPDX-License-Identifier: MIT
// Shared formatting of the step tables (times and counts) for the terminal, JSON and CSV.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "metrics/step_counts.h"
#include "metrics/timing.h"

namespace rpt::engine {

// The row of the reader's part-affinity grouping (SequenceFrame::paf_grouping_us): in the step
// table, summary.json's step times and steps.csv when the reader grouped raw candidates (the
// shelf-4da reader), absent otherwise. It runs before the pipeline and is not in "frame (total)";
// "frame + grouping" adds it.
inline constexpr const char* kPafGroupingRow = "paf_grouping (reader)";

// One line per step: name, median and mean microseconds, and with `counts` the mean number of
// items the step left per frame (and what they are), the reader's grouping first when there is
// one; then the frame total (and the frame with the grouping). With `counts`, a
// line with the extra counters per frame and one with the estimated detection noise follow.
void PrintStepTimes(std::ostream& out, const metrics::TimingSummary& timing,
                    const metrics::StepCountSummary* counts = nullptr);

// {"undistort": median_us, ...} in step order ("paf_grouping (reader)" first when present).
nlohmann::ordered_json StepTimesJson(const metrics::TimingSummary& timing);

// {"undistort": mean items per frame, ...} in step order.
nlohmann::ordered_json StepCountsJson(const metrics::StepCountSummary& counts);
// {"pruned_limbs": mean per frame, ...} in kCounterNames order.
nlohmann::ordered_json CountersJson(const metrics::StepCountSummary& counts);

// steps.csv: step,items,count_per_frame,time_us_median,time_us_mean (one row per step; the
// reader's grouping first when present, with items and count empty).
std::string StepsCsv(const metrics::TimingSummary& timing, const metrics::StepCountSummary& counts);

// "estimated detection noise 12.3 mm (median over 300 frames)", or "... not estimated (fixed
// score scale)" when no frame has an estimate.
std::string NoiseLine(const metrics::StepCountSummary& counts);

}  // namespace rpt::engine
