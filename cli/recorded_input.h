// SPDX-License-Identifier: MIT
// The input of a recorded `rpt eval` run, re-loaded for `rpt report` from the command line that
// run.json records (GT, cameras and detections are not copied into the run folder: the dataset
// stays their one source). Parsing the recorded argument vector needs the input options of the
// command line, hence here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "datasets/sequence.h"
#include "engine/report/report_run.h"

namespace rpt::cli {

// Re-loads the input of the recorded `rpt eval` or `rpt triangulate` command (without GT for the latter) (its input options only; the configuration
// is the recorded config.json). When it cannot (not an eval command, files moved), returns nullopt
// and sets *why to a one-line reason.
std::optional<std::vector<Sequence>> ReloadRecordedInput(const engine::RecordedRun& run, std::string* why);

}  // namespace rpt::cli
