// SPDX-License-Identifier: MIT
#include "cli/export_args.h"

#include "core/errors.h"

namespace rpt::cli {

void AddExportOptions(CLI::App* command, ExportArgs* args) {
  command
      ->add_option("--export", args->formats,
                   "files of 3D persons, comma-separated: json (predictions.json), csv (predictions.csv), trc "
                   "(trc/, one file per track for OpenSim), npz (predictions.npz, numpy arrays frames x persons x "
                   "joints x 4), h5 (predictions.h5, the same arrays in HDF5) (default json; docs/own_data.md)")
      ->each([args](const std::string&) { args->formats_given = true; });
  command->add_flag("--no-predictions", args->no_predictions, "write no 3D persons to files (no predictions.json, no exports; long runs); --follow still writes its lines to stdout");
  command->add_flag("--no-filled-joints", args->no_filled_joints,
                    "write joints no view saw, placed from a neighbour (provenance 'filled'), as missing");
  command->add_flag("--no-predicted-joints", args->no_predicted_joints,
                    "write the joints of persons held by tracking while nobody sees them (provenance 'predicted': "
                    "the track's last pose, repeated while it coasts) as missing");
  command->add_option("--trc-axes", args->trc_axes, "world axes of the TRC files: z-up (as is) or y-up (OpenSim)")
      ->check(CLI::IsMember({"z-up", "y-up"}))
      ->capture_default_str()
      ->each([args](const std::string&) { args->trc_option_given = "--trc-axes"; });
  command->add_option("--trc-units", args->trc_units, "unit of the TRC coordinates: m or mm")
      ->check(CLI::IsMember({"m", "mm"}))
      ->capture_default_str()
      ->each([args](const std::string&) { args->trc_option_given = "--trc-units"; });
}

engine::ExportOptions ExportOptionsOf(const ExportArgs& args) {
  engine::ExportOptions options;
  if (args.no_predictions) {
    if (args.formats_given) throw ConfigError("--no-predictions contradicts --export " + args.formats);
    options.formats.clear();
  } else if (args.formats_given) {  // '' is refused as any unknown name (it wrote JSON, the default)
    options.formats = engine::ParseExportFormats(args.formats);
  }
  // The other formats are always z up, in metres: a TRC option without TRC files would be read as
  // applying to them.
  if (!args.trc_option_given.empty() && !options.Has(engine::ExportFormat::kTrc)) {
    throw ConfigError(args.trc_option_given +
                      " sets the TRC files, which this run does not write: add trc to --export "
                      "(JSON, CSV, NPZ and HDF5 are always z up, in metres)");
  }
  options.filled_joints = !args.no_filled_joints;
  options.predicted_joints = !args.no_predicted_joints;
  options.trc_axes = args.trc_axes == "y-up" ? engine::TrcAxes::kYUp : engine::TrcAxes::kZUp;
  options.trc_millimetres = args.trc_units == "mm";
  return options;
}

}  // namespace rpt::cli
