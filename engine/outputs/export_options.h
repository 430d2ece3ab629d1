// SPDX-License-Identifier: MIT
// Which files of 3D persons a run writes (rpt eval and rpt triangulate: --export, --no-predictions,
// --no-filled-joints, --trc-axes, --trc-units) and what every export shares: the provenance names
// and which joints are written. The formats and their schemas: docs/own_data.md, "Exports".
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/poses.h"

namespace rpt::engine {

enum class ExportFormat { kJson, kCsv, kTrc, kNpz, kH5 };
inline constexpr std::array<ExportFormat, 5> kExportFormats = {
    ExportFormat::kJson, ExportFormat::kCsv, ExportFormat::kTrc, ExportFormat::kNpz, ExportFormat::kH5};

// World axes of the TRC files: as they are (z up, the convention of every dataset reader and of
// most calibrations), or rotated for OpenSim's y up: (x, y, z) -> (x, z, -y), a rotation of -90
// degrees about x.
enum class TrcAxes { kZUp, kYUp };

struct ExportOptions {
  std::vector<ExportFormat> formats = {ExportFormat::kJson};  // empty: no predictions at all
  // Joints no view saw, placed from a neighbour (JointProvenance::kFilled), are written; false: written as missing.
  bool filled_joints = true;
  // Joints of a person tracking holds while nobody sees it (JointProvenance::kPredicted: its track's
  // last pose, repeated while it coasts) are written; false: written as missing (frozen copies are no
  // marker data for inverse kinematics).
  bool predicted_joints = true;
  TrcAxes trc_axes = TrcAxes::kZUp;
  bool trc_millimetres = false;  // TRC coordinates in mm instead of m

  bool Has(ExportFormat format) const;
};

// "json", "csv", "trc", "npz", "h5".
std::string_view ExportFormatName(ExportFormat format);
// What it writes in a run folder: "predictions.json", "predictions.csv", "trc" (a folder),
// "predictions.npz", "predictions.h5".
std::string_view ExportFileName(ExportFormat format);
// Parses "json,csv,trc" (names as above, comma-separated, no repeats). Throws ConfigError naming
// the option (`--export`) and the bad name.
std::vector<ExportFormat> ParseExportFormats(const std::string& text);

// "triangulated", "filled", "smoothed", "lifted", "predicted": the JointProvenance values by code.
std::string_view ProvenanceName(JointProvenance provenance);
const std::vector<std::string>& ProvenanceNames();

// Joint j of person p is written as present: score > 0, not filled unless filled joints are
// written and not predicted unless predicted joints are.
inline bool JointWritten(const Poses3D& persons, int p, int j, const ExportOptions& options) {
  if (!(persons.data[(static_cast<size_t>(p) * persons.num_joints + j) * 4 + 3] > 0)) return false;
  const JointProvenance provenance = persons.Provenance(p, j);
  return (options.filled_joints || provenance != JointProvenance::kFilled) &&
         (options.predicted_joints || provenance != JointProvenance::kPredicted);
}

}  // namespace rpt::engine
