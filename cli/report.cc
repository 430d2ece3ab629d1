// SPDX-License-Identifier: MIT
#include "cli/report.h"

#include <cstdio>
#include <string>

namespace rpt::cli {

void PrintStepTimes(std::ostream& out, const metrics::TimingSummary& timing) {
  char line[160];
  std::snprintf(line, sizeof(line), "  %-18s %12s %12s\n", "step", "median (us)", "mean (us)");
  out << line;
  for (int s = 0; s < kNumSteps; ++s) {
    std::snprintf(line, sizeof(line), "  %-18s %12.2f %12.2f\n", std::string(kStepNames[s]).c_str(),
                  timing.step_us_median[s], timing.step_us_mean[s]);
    out << line;
  }
  std::snprintf(line, sizeof(line), "  %-18s %12.2f %12.2f\n", "frame (total)", timing.frame_us_median,
                timing.frame_us_mean);
  out << line;
}

nlohmann::ordered_json StepTimesJson(const metrics::TimingSummary& timing) {
  nlohmann::ordered_json steps = nlohmann::ordered_json::object();
  for (int s = 0; s < kNumSteps; ++s) steps[std::string(kStepNames[s])] = timing.step_us_median[s];
  return steps;
}

}  // namespace rpt::cli
