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
// one, or is an input file.
void CheckOutputOutsideInput(const std::filesystem::path& out, const InputSpec& spec);

}  // namespace rpt::engine
