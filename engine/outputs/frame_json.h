// SPDX-License-Identifier: MIT
// One triangulated frame as JSON text, the same object in predictions.json's "frames" list and on
// each line of the live output (engine/outputs/frame_lines_writer.h):
//   {"id": "...", "time": t or null, "persons": [[[x, y, z, score], ...], ...],
//    "track_ids": [...], "provenance": [[code per joint], ...]}
// metres in the world frame with 6 decimals, seconds with 6, scores with 4 (std::to_chars, the text
// printf's "%.6f" gives; from 1e15 on, which no decimal can refine, the shortest exact form such
// as 1e+300); coordinates that are not finite are null; provenance codes index
// ProvenanceNames() (engine/outputs/export_options.h). A missing joint (score 0) is written as
// [null, null, null, 0], as NPZ's NaN and CSV's absent row say; without
// ExportOptions::filled_joints a filled joint is written so too. Appended to a string whose capacity
// is reused, so a warm writer allocates nothing.
#pragma once

#include <string>
#include <string_view>

#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"

namespace rpt::engine {

// Appends `frame` as above. A frame id that is not valid UTF-8 is written with U+FFFD and counted in
// *replaced (when given).
void AppendFrameJson(const FrameOutput& frame, const ExportOptions& options, std::string* out, int* replaced = nullptr);

// Appends `text` (valid UTF-8) as a JSON string, escaped as nlohmann::json::dump escapes it.
void AppendJsonString(std::string_view text, std::string* out);

}  // namespace rpt::engine
