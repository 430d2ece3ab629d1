// SPDX-License-Identifier: MIT
#include "python/arrays.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "python/bindings.h"

namespace rpt::python {
namespace {

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

std::string ExpectedShapeText(const std::vector<py::ssize_t>& shape, const std::vector<std::string>& names) {
  std::string text = "(";
  for (size_t d = 0; d < shape.size(); ++d) {
    text += d > 0 ? ", " : "";
    text += shape[d] >= 0 ? std::to_string(shape[d]) : (d < names.size() ? names[d] : "n");
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

// Views as an integer array (a detector's int32 output, a cast too many): their scores are whole
// numbers, every joint scored below 1 reads as 0 (missing) and nobody is triangulated, without any
// error (a typed-code user's finding): said as an rpt.InputWarning naming the argument.
void WarnOfIntegerScores(py::handle object, const std::string& what) {
  if (!py::isinstance<py::array>(object)) return;
  const py::array array = py::reinterpret_borrow<py::array>(object);
  const char kind = array.dtype().kind();
  if ((kind != 'i' && kind != 'u') || array.size() == 0) return;
  WarnInput({what + ": an array of integers (" + py::str(array.dtype()).cast<std::string>() +
             "): its scores are whole numbers, so every joint scored below 1 reads as missing; give float32 or "
             "float64"});
}

}  // namespace

py::array_t<double> CheckedArray(py::handle object, const std::string& what, std::vector<py::ssize_t> shape) {
  py::array array;
  if (py::isinstance<py::array>(object)) {
    array = py::reinterpret_borrow<py::array>(object);
    // Real numbers of any width, in any layout: a detector's `keypoints[..., :3]` (a strided slice),
    // a Fortran-order or float32 array, integer pixels. The data is copied into C++ buffers anyway;
    // anything but float64 in C order is converted in that copy. Booleans, complex numbers, objects
    // and strings are no coordinates: refused, naming the argument.
    const char kind = array.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') {
      throw py::type_error(what + ": dtype " + py::str(array.dtype()).cast<std::string>() +
                           ", expected real numbers (float64, float32 or integers)");
    }
    const bool is_float64 = py::isinstance<py::array_t<double>>(object);
    if (!is_float64 || !(array.flags() & py::array::c_style)) {
      array = py::module_::import("numpy").attr("ascontiguousarray")(array, py::arg("dtype") = "float64");
    }
  } else {
    // Lists and other sequences: numpy converts them; what is not numbers, or ragged, is this
    // argument's ValueError (py::array_t::ensure clears numpy's error and leaves none to raise).
    try {
      array = py::module_::import("numpy").attr("ascontiguousarray")(object, py::arg("dtype") = "float64");
    } catch (py::error_already_set& e) {
      if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
      throw py::value_error(what + ": not an array of numbers (" + std::string(py::str(e.value())) + ")");
    }
  }
  if (array.ndim() != static_cast<py::ssize_t>(shape.size())) {
    throw py::value_error(what + ": shape " + ShapeText(array) + ", expected " + std::to_string(shape.size()) +
                          " dimensions " + ExpectedShapeText(shape, {}));
  }
  for (size_t d = 0; d < shape.size(); ++d) {
    if (shape[d] >= 0 && array.shape(static_cast<py::ssize_t>(d)) != shape[d]) {
      throw py::value_error(what + ": shape " + ShapeText(array) + ", expected " + ExpectedShapeText(shape, {}));
    }
  }
  return py::reinterpret_borrow<py::array_t<double>>(array);
}

// A joint of score 0 is missing whatever its coordinates: NaN there (numpy's usual "missing")
// becomes 0, as JSON's null does; NaN with a score above 0 stays an error (ValidateFrame).
void ClearCoordinatesOfMissingJoints(double* data, size_t size) {
  for (size_t i = 0; i + 2 < size; i += 3) {
    if (data[i + 2] == 0 && !(std::isfinite(data[i]) && std::isfinite(data[i + 1]))) data[i] = data[i + 1] = 0;
  }
}

void ViewFromArray(py::handle object, int num_joints, const std::string& what, Poses2D* view) {
  view->Clear(num_joints);
  if (object.is_none()) {  // the camera delivered nothing this frame (an empty array: it saw nobody)
    view->unavailable = true;
    return;
  }
  // An empty list is a camera that saw nobody, as an array of no persons is (numpy makes it shape (0,)).
  if ((py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) && py::len(object) == 0) return;
  const py::array_t<double> array = CheckedArray(object, what, {-1, -1, 3});
  WarnOfIntegerScores(object, what);
  if (array.shape(0) > 0 && array.shape(1) != num_joints) {
    throw py::value_error(what + ": " + std::to_string(array.shape(1)) + " joints, expected " +
                          std::to_string(num_joints) + " (shape (persons, " + std::to_string(num_joints) + ", 3))");
  }
  if (array.shape(0) == 0 && array.shape(1) != num_joints && array.shape(1) != 0) {
    throw py::value_error(what + ": " + std::to_string(array.shape(1)) + " joints, expected " +
                          std::to_string(num_joints));
  }
  view->data.assign(array.data(), array.data() + array.size());
  ClearCoordinatesOfMissingJoints(view->data.data(), view->data.size());
}

void ViewsFromPython(py::handle views, int num_cameras, int num_joints, std::vector<Poses2D>* out) {
  out->resize(static_cast<size_t>(num_cameras));
  if (py::isinstance<py::array>(views)) {  // one array (cameras, persons, joints, 3)
    const py::array_t<double> array = CheckedArray(views, "views", {num_cameras, -1, num_joints, 3});
    WarnOfIntegerScores(views, "views");
    const size_t per_view = array.size() / static_cast<size_t>(std::max(num_cameras, 1));
    for (int c = 0; c < num_cameras; ++c) {
      (*out)[c].Clear(num_joints);
      (*out)[c].data.assign(array.data() + c * per_view, array.data() + (c + 1) * per_view);
      ClearCoordinatesOfMissingJoints((*out)[c].data.data(), (*out)[c].data.size());
    }
    return;
  }
  if (!py::isinstance<py::list>(views) && !py::isinstance<py::tuple>(views)) {
    throw py::type_error("views: expected a list of one (persons, joints, 3) array per camera, got " +
                         py::str(py::type::of(views)).cast<std::string>());
  }
  const py::sequence list = py::reinterpret_borrow<py::sequence>(views);
  if (static_cast<int>(list.size()) != num_cameras) {
    throw py::value_error("views: " + std::to_string(list.size()) + " views for " + std::to_string(num_cameras) +
                          " cameras");
  }
  for (int c = 0; c < num_cameras; ++c) {
    ViewFromArray(list[static_cast<size_t>(c)], num_joints, "views[" + std::to_string(c) + "]", &(*out)[c]);
  }
}

Poses3D PersonsFromArray(py::handle object, int num_joints, const std::string& what) {
  Poses3D persons;
  persons.Clear(num_joints);
  if (object.is_none()) return persons;
  const py::array_t<double> array = CheckedArray(object, what, {-1, num_joints, 4});
  for (py::ssize_t p = 0; p < array.shape(0); ++p) persons.AddPerson();
  std::copy(array.data(), array.data() + array.size(), persons.data.begin());
  // A missing joint (score 0) may have NaN coordinates, as rpt's NPZ and HDF5 exports write it.
  for (size_t k = 0; k < persons.data.size(); k += 4) {
    double* joint = persons.data.data() + k;
    if (joint[3] == 0 && (std::isnan(joint[0]) || std::isnan(joint[1]) || std::isnan(joint[2]))) {
      joint[0] = joint[1] = joint[2] = 0;
    }
    for (int d = 0; d < 4; ++d) {
      if (!std::isfinite(joint[d])) {
        const size_t index = k / 4;
        throw py::value_error(what + ": person " + std::to_string(index / static_cast<size_t>(num_joints)) +
                              ", joint " + std::to_string(index % static_cast<size_t>(num_joints)) +
                              ": NaN or infinity (a missing joint has score 0; its coordinates may be NaN)");
      }
    }
  }
  return persons;
}

py::array_t<double> PersonsArray(const Poses3D& persons) {
  py::array_t<double> array(
      {static_cast<py::ssize_t>(persons.num_persons()), static_cast<py::ssize_t>(persons.num_joints), py::ssize_t{4}});
  std::copy(persons.data.begin(), persons.data.end(), array.mutable_data());
  return array;
}

namespace {

template <class T>
py::array_t<T> ReadOnlyView(std::vector<py::ssize_t> shape, const T* data, py::handle owner) {
  py::array_t<T> view(std::move(shape), {}, data, owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

}  // namespace

py::array_t<double> PersonsView(const Poses3D& persons, py::handle owner) {
  return ReadOnlyView<double>(
      {static_cast<py::ssize_t>(persons.num_persons()), static_cast<py::ssize_t>(persons.num_joints), py::ssize_t{4}},
      persons.data.data(), owner);
}

py::array_t<uint8_t> ProvenanceView(const Poses3D& persons, py::handle owner) {
  return ReadOnlyView<uint8_t>(
      {static_cast<py::ssize_t>(persons.num_persons()), static_cast<py::ssize_t>(persons.num_joints)},
      persons.provenance.data(), owner);
}

py::array_t<double> ViewOf(const Poses2D& view, int num_joints, py::handle owner) {
  const int persons = view.num_joints == num_joints ? view.num_persons() : 0;
  if (persons == 0) return ViewArray(Poses2D{}, num_joints);
  return ReadOnlyView<double>(
      {static_cast<py::ssize_t>(persons), static_cast<py::ssize_t>(num_joints), py::ssize_t{3}}, view.data.data(),
      owner);
}

py::array_t<long long> TrackIdsArray(const Poses3D& persons) {
  py::array_t<long long> array(static_cast<py::ssize_t>(persons.num_persons()));
  std::copy(persons.track_ids.begin(), persons.track_ids.end(), array.mutable_data());
  return array;
}

py::array_t<uint8_t> ProvenanceArray(const Poses3D& persons) {
  py::array_t<uint8_t> array(
      {static_cast<py::ssize_t>(persons.num_persons()), static_cast<py::ssize_t>(persons.num_joints)});
  uint8_t* out = array.mutable_data();
  for (int p = 0; p < persons.num_persons(); ++p) {
    for (int j = 0; j < persons.num_joints; ++j) *out++ = static_cast<uint8_t>(persons.Provenance(p, j));
  }
  return array;
}

py::array_t<double> ViewArray(const Poses2D& view, int num_joints) {
  const int persons = view.num_joints == num_joints ? view.num_persons() : 0;
  py::array_t<double> array({static_cast<py::ssize_t>(persons), static_cast<py::ssize_t>(num_joints), py::ssize_t{3}});
  if (persons > 0) std::copy(view.data.begin(), view.data.end(), array.mutable_data());
  return array;
}

Eigen::Matrix3d Matrix3From(py::handle object, const std::string& what) {
  const py::array_t<double> array = CheckedArray(object, what, {3, 3});
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = array.at(r, c);
  }
  if (!m.allFinite()) throw py::value_error(what + ": contains NaN or infinity");
  return m;
}

Eigen::Vector3d Vector3From(py::handle object, const std::string& what) {
  const py::array_t<double> array = CheckedArray(object, what, {3});
  const Eigen::Vector3d v(array.at(0), array.at(1), array.at(2));
  if (!v.allFinite()) throw py::value_error(what + ": contains NaN or infinity");
  return v;
}

py::array_t<double> MatrixArray(const Eigen::MatrixXd& matrix) {
  py::array_t<double> array({static_cast<py::ssize_t>(matrix.rows()), static_cast<py::ssize_t>(matrix.cols())});
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) array.mutable_at(r, c) = matrix(r, c);
  }
  return array;
}

}  // namespace rpt::python
