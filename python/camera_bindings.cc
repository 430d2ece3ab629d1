// SPDX-License-Identifier: MIT
// rpt.Camera (core/camera.h: x_cam = R X + t, metres; pixels of the distorted image) and
// rpt.cameras: load / save every calibration format the CLI reads and writes
// (datasets/calibration/calibration.h).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <sstream>
#include <string>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/calibration/calibration.h"
#include "datasets/calibration/camera_json.h"
#include "engine/input.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/option_values.h"

namespace rpt::python {
namespace {

// A copy of a camera's matrix that refuses writes: the camera is read-only, and a write into a
// writeable copy (camera.K[0, 2] += 50) was silently lost.
py::array ReadOnly(py::array array) {
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

Camera MakeCamera(const std::string& name, int width, int height, py::handle K, py::handle R, py::handle t,
                  py::handle center, py::handle dist, const std::string& model) {
  Camera camera;
  camera.name = name;
  camera.width = width;
  camera.height = height;
  camera.K = Matrix3From(K, "K");
  if (!R.is_none()) camera.R = Matrix3From(R, "R");
  if (!t.is_none() && !center.is_none()) throw py::value_error("give t or center, not both");
  if (!t.is_none()) camera.t = Vector3From(t, "t");
  if (!center.is_none()) camera.t = -camera.R * Vector3From(center, "center");
  py::ssize_t given = 0;  // coefficients given
  if (!dist.is_none()) {
    const py::array_t<double> d = CheckedArray(dist, "dist", {-1});
    given = d.size();
    if (d.size() > 5) throw py::value_error("dist: " + std::to_string(d.size()) + " coefficients, at most 5");
    for (py::ssize_t i = 0; i < d.size(); ++i) camera.dist[static_cast<size_t>(i)] = d.at(i);
  }
  const std::vector<std::pair<DistortionModel, std::string>> models = {{DistortionModel::kNone, "none"},
                                                                       {DistortionModel::kOpenCV, "opencv"},
                                                                       {DistortionModel::kH36M, "h36m"},
                                                                       {DistortionModel::kFisheye, "fisheye"}};
  bool known = false;
  for (const auto& [value, text] : models) {
    if (text == model) camera.model = value, known = true;
  }
  if (!known) throw ConfigError("model: " + QuoteName(model) + " is not none | opencv | h36m | fisheye");
  // 1-3 coefficients were padded with zeros: [k1, k2, k3] made k3 the tangential p1, silently (the
  // file readers refuse such a list).
  if (given > 0 && given < 4 && camera.model != DistortionModel::kNone) {
    throw py::value_error("dist: " + std::to_string(given) + " coefficients; model=" + QuoteName(model) + " takes " +
                          (camera.model == DistortionModel::kFisheye ? std::string("k1 k2 k3 k4")
                                                                    : std::string("k1 k2 p1 p2 [k3] (4 or 5)")));
  }
  // Coefficients the model does not use would be ignored without a word (an OpenCV dist passed
  // without model= gave the pinhole's pixels).
  const int used = camera.model == DistortionModel::kNone ? 0 : camera.model == DistortionModel::kFisheye ? 4 : 5;
  for (int i = used; i < 5; ++i) {
    if (camera.dist[static_cast<size_t>(i)] == 0.0) continue;
    if (used == 0) {
      throw py::value_error("dist: non-zero coefficients, but model=" + QuoteName(model) +
                            " uses none (pass model='opencv' for k1 k2 p1 p2 k3, 'fisheye' for k1 k2 k3 k4)");
    }
    std::ostringstream message;
    message << "dist: coefficient " << i + 1 << " is " << camera.dist[static_cast<size_t>(i)] << ", but model="
            << QuoteName(model) << " uses the first " << used;
    throw py::value_error(message.str());
  }
  if (const std::string problem = camera.Validate(); !problem.empty()) throw InputError(problem);  // names the camera
  return camera;
}

std::string ModelText(DistortionModel model) {
  switch (model) {
    case DistortionModel::kOpenCV:
      return "opencv";
    case DistortionModel::kH36M:
      return "h36m";
    case DistortionModel::kFisheye:
      return "fisheye";
    default:
      return "none";
  }
}

// Points (n, 3) or (3,) -> distorted pixels (n, 2) and whether each is in front of the camera.
py::tuple Project(const Camera& camera, py::handle points) {
  const bool single = py::isinstance<py::array>(points) && py::reinterpret_borrow<py::array>(points).ndim() == 1;
  const py::array_t<double> array =
      single ? CheckedArray(points, "points", {3}) : CheckedArray(points, "points", {-1, 3});
  const py::ssize_t n = single ? 1 : array.shape(0);
  py::array_t<double> uv({n, py::ssize_t{2}});
  py::array_t<bool> in_front(n);
  const double* in = array.data();
  double* out = uv.mutable_data();
  bool* front = in_front.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      Eigen::Vector2d pixel;
      front[i] = camera.Project(Eigen::Vector3d(in[3 * i], in[3 * i + 1], in[3 * i + 2]), &pixel);
      out[2 * i] = pixel.x();
      out[2 * i + 1] = pixel.y();
    }
  }
  return py::make_tuple(uv, in_front);
}

// Distorted pixels (n, 2) -> undistorted pixels (same K).
py::array_t<double> UndistortPoints(const Camera& camera, py::handle points) {
  const py::array_t<double> array = CheckedArray(points, "points", {-1, 2});
  const py::ssize_t n = array.shape(0);
  py::array_t<double> result({n, py::ssize_t{2}});
  const double* in = array.data();
  double* out = result.mutable_data();
  py::gil_scoped_release release;
  for (py::ssize_t i = 0; i < n; ++i) {
    const Eigen::Vector2d undistorted = camera.UndistortPixel(Eigen::Vector2d(in[2 * i], in[2 * i + 1]));
    out[2 * i] = undistorted.x();
    out[2 * i + 1] = undistorted.y();
  }
  return result;
}

}  // namespace

void RegisterCameras(py::module_& m, py::module_& cameras) {
  py::class_<Camera>(m, "Camera",
                     "A calibrated camera: x_cam = R X + t (metres), pixels of the distorted image (core/camera.h).")
      .def(py::init(&MakeCamera), py::kw_only(), py::arg("name") = "", py::arg("width"), py::arg("height"),
           py::arg("K"), py::arg("R") = py::none(), py::arg("t") = py::none(), py::arg("center") = py::none(),
           py::arg("dist") = py::none(), py::arg("model") = "none",
           "K, R: 3x3; t (cam_from_world translation) or center (camera centre in the world), metres; dist: up to 5 "
           "coefficients (opencv, h36m: k1 k2 p1 p2 k3; fisheye: k1 k2 k3 k4); model: none | opencv | h36m | fisheye")
      .def_readonly("name", &Camera::name)
      .def_readonly("width", &Camera::width)
      .def_readonly("height", &Camera::height)
      .def_property_readonly("K", [](const Camera& c) { return ReadOnly(MatrixArray(c.K)); })
      .def_property_readonly("R", [](const Camera& c) { return ReadOnly(MatrixArray(c.R)); })
      .def_property_readonly("t", [](const Camera& c) { return ReadOnly(MatrixArray(c.t).reshape({3})); })
      .def_property_readonly("center", [](const Camera& c) { return ReadOnly(MatrixArray(c.Center()).reshape({3})); })
      .def_property_readonly(
          "dist",
          [](const Camera& c) {
            return ReadOnly(MatrixArray(Eigen::Map<const Eigen::Matrix<double, 5, 1>>(c.dist.data())).reshape({5}));
          })
      // A Camera is a value: copies are independent cameras (a deepcopy in a notebook failed).
      .def("__copy__", [](const Camera& c) { return c; })
      .def("__deepcopy__", [](const Camera& c, py::dict) { return c; }, py::arg("memo"))
      // Pickled as the constructor's arguments and unpickled through the constructor's checks (a
      // multiprocessing worker gets the same camera; a tampered pickle gets the constructor's errors).
      .def(py::pickle(
          [](const Camera& c) {
            return py::make_tuple(c.name, c.width, c.height, MatrixArray(c.K), MatrixArray(c.R),
                                  MatrixArray(c.t).reshape({3}),
                                  MatrixArray(Eigen::Map<const Eigen::Matrix<double, 5, 1>>(c.dist.data())).reshape({5}),
                                  ModelText(c.model));
          },
          [](const py::tuple& state) {
            if (state.size() != 8) throw InputError("Camera (unpickled): expected 8 values, got " + std::to_string(state.size()));
            return MakeCamera(state[0].cast<std::string>(), state[1].cast<int>(), state[2].cast<int>(), state[3], state[4],
                              state[5], py::none(), state[6], state[7].cast<std::string>());
          }))
      .def_property_readonly("model", [](const Camera& c) { return ModelText(c.model); })
      .def("project", &Project, py::arg("points"),
           "World points (n, 3) in metres -> (pixels (n, 2) in the distorted image, in_front (n,) bool)")
      .def("undistort_points", &UndistortPoints, py::arg("points"),
           "Distorted pixels (n, 2) -> undistorted pixels (n, 2), same K")
      .def(
          "to_json", [](const Camera& c) { return PythonOf(camera_json::CameraJson(c, "Camera.to_json", c.name)); },
          "The camera as our cameras JSON object (T = camera centre; docs/cameras.md)")
      .def("__repr__", [](const Camera& c) {
        return "Camera(" + QuoteName(c.name) + ", " + std::to_string(c.width) + "x" + std::to_string(c.height) + ", " +
               ModelText(c.model) + ")";
      });

  cameras.def(
      "load",
      [](const std::filesystem::path& path, py::kwargs options) {
        CalibrationReadOptions read;
        SetOptionFields(options, "cameras.load", "", &read);
        InputWarnings warnings;
        std::vector<Camera> list;
        {
          py::gil_scoped_release release;
          list = ReadCalibration(path, read, &warnings).cameras;
        }
        WarnInput(engine::InputWarningLines(warnings));  // what `rpt cameras show` prints
        return list;
      },
      py::arg("path"),
      "The cameras of a calibration file or folder, any format the CLI reads (json, opencv, easymocap, toml, colmap, "
      "voxelpose, panoptic, 4da). Options: format='auto', units='default' (m | cm | mm), image_width=0, "
      "image_height=0. Corrections and doubts (rotations re-orthonormalised, image sizes guessed, cameras "
      "implausibly far) are warnings of category rpt.InputWarning, as `rpt cameras show` prints them.");
  cameras.def(
      "save",
      [](const std::filesystem::path& path, const std::vector<Camera>& list, py::kwargs options) {
        CalibrationWriteOptions write;
        SetOptionFields(options, "cameras.save", "", &write);
        InputWarnings written;
        {
          py::gil_scoped_release release;
          WriteCalibration(path, list, write, &written);
        }
        WarnInput(engine::InputWarningLines(written));
      },
      py::arg("path"), py::arg("cameras"),
      "Writes cameras as json, opencv, easymocap or toml (format='auto': from the file name; units='default').");
}

}  // namespace rpt::python
