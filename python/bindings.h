// SPDX-License-Identifier: MIT
// The Python module rpt._rpt (docs/python.md): one Register function per part of the API, each in
// its own file, called by module.cc; the types several parts share.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "core/errors.h"
#include "core/joints.h"
#include "core/pipeline/frame_stats.h"
#include "core/poses.h"
#include "engine/config.h"

namespace rpt::python {

namespace py = pybind11;

void RegisterErrors(py::module_& m);                                   // errors.cc
// Each line of `lines` (a reader's corrections and warnings, engine::InputWarningLines) as a Python
// warning of category rpt.InputWarning (a UserWarning); the GIL must be held. errors.cc
void WarnInput(const std::vector<std::string>& lines);
void RegisterCameras(py::module_& m, py::module_& cameras);            // camera_bindings.cc
void RegisterOptions(py::module_& m);                                  // options_bindings.cc
void RegisterDatasets(py::module_& datasets, py::module_& synthetic);  // datasets_bindings.cc
void RegisterTriangulator(py::module_& m);                             // triangulator_bindings.cc
void RegisterMetrics(py::module_& metrics);                            // metrics_bindings.cc
void RegisterExport(py::module_& exports);                             // export_bindings.cc

// An InputError about a path the caller named that does not exist (a dataset's root, a labels
// file), raised as rpt.InputFileNotFoundError like the readers' "file not found" (errors.cc).
class MissingInputError : public InputError {
 public:
  using InputError::InputError;
};

// The 3D persons of a sequence triangulated by Triangulator.process_sequence, what
// metrics.evaluate and export.write take: per frame its id, time, persons and step statistics.
struct Predictions {
  std::string sequence = "python";  // the sequence's name (exports, per-sequence summaries)
  double fps = 0;                   // of the sequence; 0 = unknown
  int cameras = 0;
  JointNames joints;  // output joints of the triangulator
  std::vector<std::string> frame_ids;
  std::vector<double> timestamps_s;  // NaN = unknown
  std::vector<Poses3D> persons;
  std::vector<FrameStats> stats;
  double wall_seconds = 0;  // the whole call, steady clock
};

// The configuration an `options` argument names: None (defaults), an rpt.Options or a dict
// ({"section": {"key": value}} or {"section.key": value}); checked (ConfigError naming the key).
engine::Config ConfigOf(py::handle options);

}  // namespace rpt::python
