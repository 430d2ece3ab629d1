// SPDX-License-Identifier: MIT
// Where a command may write its output folder: never into its input. A run folder is built beside
// the named folder and swapped in as a whole (datasets/io/staged_output.h), so an output folder that
// is a dataset folder, lies inside one or holds one would move the dataset's files into the new
// folder (a kill at the wrong moment would leave them in a temporary one).
#pragma once

#include <filesystem>

#include "engine/input.h"

namespace rpt::engine {

// Throws ConfigError naming the option and the input when `out` is a folder input of `spec`
// (--root, an OpenPose folder given as --detections, --coco-images, ...), lies inside one, holds
// one, or holds an input file.
void CheckOutputOutsideInput(const std::filesystem::path& out, const InputSpec& spec);

// Throws ConfigError naming the option when the page `out` of `rpt report` (a file) is the run
// folder `run_dir` or an existing file in it other than a page (*.html): `--out RUN/predictions.json`
// replaced the predictions the report had just read.
void CheckOutputOutsideRunFolder(const std::filesystem::path& out, const std::filesystem::path& run_dir);

}  // namespace rpt::engine
