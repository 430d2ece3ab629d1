// SPDX-License-Identifier: MIT
// The thresholds file of `rpt check`: its schema (ThresholdsSchemaText(), also in docs/results.md) and
// ReadThresholdsFile(), which validates the whole file before any evaluation runs.
#pragma once

#include <string>
#include <vector>

#include "engine/config.h"
#include "engine/input.h"

namespace rpt::engine {

// One bound on one summary metric, e.g. min recall500 99.
struct ThresholdCheck {
  std::string metric;  // a key of the run summary (ThresholdMetricNames())
  std::string bound;   // "min" (achieved >= limit) or "max" (achieved <= limit)
  double limit = 0.0;
};

struct ThresholdEvaluation {
  std::string name;
  std::string json_path;      // "/evaluations/3", for messages
  InputSpec input;            // paths resolved against the file's folder
  Config config;              // defaults + "set", checked
  std::string required_path;  // root, labels or detections: absent -> the evaluation is skipped ("" = none)
  std::vector<ThresholdCheck> checks;  // "min" then "max", each in key order
};

struct ThresholdsFile {
  std::string path;
  std::vector<ThresholdEvaluation> evaluations;
};

// The summary keys a check may bound.
const std::vector<std::string>& ThresholdMetricNames();

// The file format, as printed by `rpt check --help`.
const std::string& ThresholdsSchemaText();

// Reads and validates `path`. Throws InputError naming the file and the JSON path on unknown keys
// (with "did you mean"), wrong types, unknown metrics or datasets, and bad "set" overrides.
ThresholdsFile ReadThresholdsFile(const std::string& path);

}  // namespace rpt::engine
