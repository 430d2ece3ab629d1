// SPDX-License-Identifier: MIT
// Generic 2D detections: the toolkit's own JSON interchange format, read and written.
//
//   {"joints": [names],
//    "frames": [{"id": "<label id>",
//                "views": [{"camera": "<name>", "poses": [[[x, y, score], ... per joint], ... per person]}]}]}
//
// Pixels of the original (distorted) image; score in [0, 1], 0 for a missing joint (a joint may
// also be written as null). Scores in (1, 1.5] are clamped to 1 and counted in
// Detections::warnings (datasets/input_warnings.h). A camera without detections has an empty "poses" list (or is left
// out). Exact schema: docs/datasets/generic_formats.md.
#pragma once

#include <filesystem>

#include "datasets/detections.h"

namespace rpt {

// Throws InputError naming the file and the JSON pointer: missing file, parse errors (line and
// column), unknown joint names, a pose with a different number of joints than "joints", scores
// that are negative or above 1.5, duplicate frame ids or cameras.
Detections ReadGenericDetections(const std::filesystem::path& path);

// Throws InputError naming the file when it cannot be written or a value is not finite or the
// shapes are inconsistent.
// Returns the number of strings that were not valid UTF-8 (written as U+FFFD).
int WriteGenericDetections(const std::filesystem::path& path, const Detections& detections);

// Checks what every detection reader guarantees: known joint names, one camera name per view,
// unique frame ids and cameras per frame, joint counts, finite values and scores in [0, 1].
// Throws InputError naming `source`.
void ValidateDetections(const Detections& detections, const std::string& source);

}  // namespace rpt
