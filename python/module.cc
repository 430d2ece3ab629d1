// SPDX-License-Identifier: MIT
// The extension rpt._rpt, imported by the package rpt (python/rpt/__init__.py). docs/python.md.
#include "python/bindings.h"

PYBIND11_MODULE(_rpt, m) {
  namespace py = pybind11;
  using namespace rpt::python;
  m.doc() = "rpt: multi-view 3D pose triangulation, datasets, metrics and exports (docs/python.md)";
  // Arrays in and out are numpy's: without it the first array would fail, far from the cause.
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set&) {
    throw py::import_error("rpt needs numpy, which this Python (" +
                           py::module_::import("sys").attr("executable").cast<std::string>() +
                           ") cannot import: install it (Debian: python3-numpy) or run the Python rpt was built for");
  }
  py::module_ cameras = m.def_submodule("cameras", "Calibration files of every format the CLI reads and writes");
  py::module_ datasets = m.def_submodule("datasets", "The CLI's inputs: dataset readers, labels, detections");
  py::module_ synthetic = m.def_submodule("synthetic", "Generated scenes and the simulated detector's profiles");
  py::module_ metrics = m.def_submodule("metrics", "The evaluation of `rpt eval`");
  py::module_ exports = m.def_submodule("export", "The CLI's exports of 3D persons");
  RegisterErrors(m);
  RegisterCameras(m, cameras);
  RegisterOptions(m);
  RegisterDatasets(datasets, synthetic);
  RegisterTriangulator(m);
  RegisterMetrics(metrics);
  RegisterExport(exports);
}
