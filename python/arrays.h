// SPDX-License-Identifier: MIT
// numpy arrays in and out: the checks every array from Python passes before C++ reads it (dtype,
// shape, C-contiguous layout; values are checked by the callers, the CLI's ValidateFrame), and the
// arrays the module returns. A refused array raises TypeError (dtype) or ValueError (shape,
// layout) naming the argument; nothing is read from an array that was not checked.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/poses.h"

namespace rpt::python {

namespace py = pybind11;

// A float64 array checked to be C-contiguous with `ndim` dimensions; float32 is converted. `what`
// names the argument in the error ("views[2]"). A dimension of `shape` >= 0 must match.
py::array_t<double> CheckedArray(py::handle object, const std::string& what, std::vector<py::ssize_t> shape);

// One camera's 2D detections, shape (persons, joints, 3): u_px, v_px, score per joint; None or a
// (0, joints, 3) array for a view without detections.
void ViewFromArray(py::handle object, int num_joints, const std::string& what, Poses2D* view);
// One view per camera: a list (or tuple) of such arrays, or one array of shape (cameras, persons,
// joints, 3).
void ViewsFromPython(py::handle views, int num_cameras, int num_joints, std::vector<Poses2D>* out);

// 3D persons, shape (persons, joints, 4): x, y, z (m), score per joint; track ids -1.
Poses3D PersonsFromArray(py::handle object, int num_joints, const std::string& what);

// Copies out: (persons, joints, 4) float64, (persons,) int64 track ids, (persons, joints) uint8
// provenance codes, (persons, joints, 3) float64 of 2D views.
py::array_t<double> PersonsArray(const Poses3D& persons);
py::array_t<long long> TrackIdsArray(const Poses3D& persons);
py::array_t<uint8_t> ProvenanceArray(const Poses3D& persons);
py::array_t<double> ViewArray(const Poses2D& view, int num_joints);
// Zero-copy, read-only views of stored results (rpt.Predictions): (persons, joints, 4) float64 and
// (persons, joints) uint8 over `persons`' own buffers, kept alive by `owner` (the Python object that
// holds `persons`, which never changes them).
py::array_t<double> PersonsView(const Poses3D& persons, py::handle owner);
py::array_t<uint8_t> ProvenanceView(const Poses3D& persons, py::handle owner);
// The same for 2D detections and ground truth held by a frame (rpt.datasets.Frame): (persons,
// joints, 3) float64; a view of another joint count is empty (as ViewArray).
py::array_t<double> ViewOf(const Poses2D& view, int num_joints, py::handle owner);

// Fixed-size matrices of a camera, refused unless finite and of the shape.
Eigen::Matrix3d Matrix3From(py::handle object, const std::string& what);
Eigen::Vector3d Vector3From(py::handle object, const std::string& what);
py::array_t<double> MatrixArray(const Eigen::MatrixXd& matrix);

}  // namespace rpt::python
