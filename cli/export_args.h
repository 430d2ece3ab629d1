// SPDX-License-Identifier: MIT
// The export options of rpt eval and rpt triangulate (--export, --no-predictions,
// --no-filled-joints, --no-predicted-joints, --trc-axes, --trc-units) and the engine::ExportOptions
// they make.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "engine/outputs/export_options.h"

namespace rpt::cli {

struct ExportArgs {
  std::string formats;  // not given: json
  bool formats_given = false;  // --export was given (an empty value is refused, not the default)
  bool no_predictions = false;
  bool no_filled_joints = false;
  bool no_predicted_joints = false;
  std::string trc_axes = "z-up";
  std::string trc_units = "m";
  std::string trc_option_given;  // "--trc-axes" or "--trc-units" when one was given (they need TRC in --export)
};

void AddExportOptions(CLI::App* command, ExportArgs* args);

// Throws ConfigError for contradicting options (--no-predictions with --export, --trc-axes or
// --trc-units without trc in --export) and bad names.
engine::ExportOptions ExportOptionsOf(const ExportArgs& args);

}  // namespace rpt::cli
