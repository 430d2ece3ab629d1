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

// Re-loads the input of the recorded `rpt eval` or `rpt triangulate` command (without GT for the
// latter; its input options only; the configuration
// is the recorded config.json). Before it opens anything, it compares the input files with the
// digests run.json records (engine/input_digests.h): each path that differs or cannot be verified
// is a line in *warnings, or with `require_same_input` an InputError. It never opens a path that is
// not a regular file or folder, and never reads more frames than predictions.json holds. When it
// cannot re-load the input (not such a command, files moved, a different input), returns nullopt
// and sets *why to a one-line reason for the page; a reader's message about an input not verified
// as the run's goes to the terminal only (it may quote a file that is not the run's).
std::optional<std::vector<Sequence>> ReloadRecordedInput(const engine::RecordedRun& run, bool require_same_input,
                                                         std::string* why, std::vector<std::string>* warnings);

}  // namespace rpt::cli
