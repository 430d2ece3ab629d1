// SPDX-License-Identifier: MIT
#include "engine/outputs/step_tables.h"

#include <cstdio>
#include <sstream>
#include <string>

namespace rpt::engine {

void PrintStepTimes(std::ostream& out, const metrics::TimingSummary& timing, const metrics::StepCountSummary* counts) {
  char line[200];
  if (counts != nullptr) {
    std::snprintf(line, sizeof(line), "  %-21s %12s %12s %14s  %s\n", "step", "median (us)", "mean (us)",
                  "count / frame", "items after the step");
  } else {
    std::snprintf(line, sizeof(line), "  %-21s %12s %12s\n", "step", "median (us)", "mean (us)");
  }
  out << line;
  if (timing.paf_grouping_frames > 0) {
    std::snprintf(line, sizeof(line), "  %-21s %12.2f %12.2f%s\n", kPafGroupingRow, timing.paf_grouping_us_median,
                  timing.paf_grouping_us_mean, counts != nullptr ? "              -  (before the pipeline)" : "");
    out << line;
  }
  for (int s = 0; s < kNumSteps; ++s) {
    if (counts != nullptr) {
      std::snprintf(line, sizeof(line), "  %-21s %12.2f %12.2f %14.2f  %s\n", std::string(kSteps[s].key).c_str(),
                    timing.step_us_median[s], timing.step_us_mean[s], counts->count_per_frame[s],
                    std::string(kSteps[s].item).c_str());
    } else {
      std::snprintf(line, sizeof(line), "  %-21s %12.2f %12.2f\n", std::string(kSteps[s].key).c_str(),
                    timing.step_us_median[s], timing.step_us_mean[s]);
    }
    out << line;
  }
  std::snprintf(line, sizeof(line), "  %-21s %12.2f %12.2f\n", "frame (total)", timing.frame_us_median,
                timing.frame_us_mean);
  out << line;
  if (timing.paf_grouping_frames > 0) {
    std::snprintf(line, sizeof(line), "  %-21s %12.2f %12.2f\n", "frame + grouping", timing.frame_with_grouping_us_median,
                  timing.frame_with_grouping_us_mean);
    out << line;
  }
  if (counts == nullptr) return;
  // The extra counters, four per line.
  for (int c = 0; c < metrics::kNumCounters; ++c) {
    std::snprintf(line, sizeof(line), "%s%s %.2f", c % 4 == 0 ? "  per frame: " : ", ",
                  std::string(metrics::kCounterNames[c]).c_str(), counts->counter_per_frame[c]);
    out << line << (c % 4 == 3 || c + 1 == metrics::kNumCounters ? "\n" : "");
  }
  out << "  " << NoiseLine(*counts) << "\n";
}

nlohmann::ordered_json StepTimesJson(const metrics::TimingSummary& timing) {
  nlohmann::ordered_json steps = nlohmann::ordered_json::object();
  if (timing.paf_grouping_frames > 0) steps[kPafGroupingRow] = timing.paf_grouping_us_median;
  for (int s = 0; s < kNumSteps; ++s) steps[std::string(kSteps[s].key)] = timing.step_us_median[s];
  return steps;
}

nlohmann::ordered_json StepCountsJson(const metrics::StepCountSummary& counts) {
  nlohmann::ordered_json steps = nlohmann::ordered_json::object();
  for (int s = 0; s < kNumSteps; ++s) steps[std::string(kSteps[s].key)] = counts.count_per_frame[s];
  return steps;
}

nlohmann::ordered_json CountersJson(const metrics::StepCountSummary& counts) {
  nlohmann::ordered_json counters = nlohmann::ordered_json::object();
  for (int c = 0; c < metrics::kNumCounters; ++c) {
    counters[std::string(metrics::kCounterNames[c])] = counts.counter_per_frame[c];
  }
  return counters;
}

std::string StepsCsv(const metrics::TimingSummary& timing, const metrics::StepCountSummary& counts) {
  std::ostringstream out;
  out << "step,items,count_per_frame,time_us_median,time_us_mean\n";
  char line[200];
  if (timing.paf_grouping_frames > 0) {
    std::snprintf(line, sizeof(line), "%s,,,%.3f,%.3f\n", kPafGroupingRow, timing.paf_grouping_us_median,
                  timing.paf_grouping_us_mean);
    out << line;
  }
  for (int s = 0; s < kNumSteps; ++s) {
    std::snprintf(line, sizeof(line), "%s,%s,%.4f,%.3f,%.3f\n", std::string(kSteps[s].key).c_str(),
                  std::string(kSteps[s].item).c_str(), counts.count_per_frame[s], timing.step_us_median[s],
                  timing.step_us_mean[s]);
    out << line;
  }
  return out.str();
}

std::string NoiseLine(const metrics::StepCountSummary& counts) {
  char line[160];
  if (counts.noise_frames == 0) return "estimated detection noise: not estimated (fixed score scale)";
  std::snprintf(line, sizeof(line), "estimated detection noise %.1f mm (median over %ld frames)",
                1000.0 * counts.noise_m_median, counts.noise_frames);
  return line;
}

}  // namespace rpt::engine
