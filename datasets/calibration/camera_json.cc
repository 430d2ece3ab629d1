// SPDX-License-Identifier: MIT
#include "datasets/calibration/camera_json.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/camera_plausibility.h"
#include "datasets/io/input_limits.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"

namespace rpt::camera_json {
namespace {

using nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

[[noreturn]] void Fail(const std::string& source, const std::string& pointer, const std::string& what) {
  throw InputError(source + ": " + pointer + ": " + what);
}

OrderedJson MatrixJson(const Eigen::Matrix3d& m) {
  OrderedJson rows = OrderedJson::array();
  for (int r = 0; r < 3; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2)});
  return rows;
}

// The keys of a camera object. A key the reader does not know was ignored without a word: "model":
// "fisheye" for "type", or "dist" for "DC", gave a pinhole or undistorted camera and 3D off by
// centimetres; they are counted, the first named with the key it may mean.
const std::vector<std::string> kCameraKeys = {"name", "K", "DC", "R", "T", "width", "height", "type"};

// The known key another tool's name for it stands for ("dist" is OpenCV's "DC"), else "".
std::string KnownKeyForOtherName(const std::string& key) {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> kOtherNames = {
      {"DC", {"D", "dist", "dist_coeffs", "distCoeffs", "distortion", "distortion_coefficients", "distortions",
              "k_dist", "dc"}},
      {"type", {"model", "lens", "camera_type", "camera_model", "distortion_model", "projection", "fisheye"}},
      {"K", {"intrinsics", "intrinsic", "camera_matrix", "cameraMatrix", "matrix", "k", "M"}},
      {"R", {"rotation", "rvec", "r", "rot", "rotation_matrix"}},
      {"T", {"t", "translation", "tvec", "center", "centre", "C", "position"}},
      {"width", {"image_width", "w"}},
      {"height", {"image_height", "h"}},
      {"name", {"id", "camera_name", "camera", "serial"}}};
  for (const auto& [known, others] : kOtherNames) {
    if (std::find(others.begin(), others.end(), key) != others.end()) return known;
  }
  return "";
}

// "'model' in /cameras/0 (did you mean 'type'?)"
std::string UnknownKeyText(const std::string& key, const std::string& pointer) {
  const std::string known = KnownKeyForOtherName(key);
  return QuoteName(key) + " in " + pointer +
         (known.empty() ? DidYouMeanKey(key, kCameraKeys) : " (did you mean '" + known + "'?)");
}

}  // namespace

Camera ParseCamera(const json& root, const std::string& pointer, const std::string& source, InputWarnings* warnings) {
  const json& j = io::JsonAt(root, pointer, source);
  if (!j.is_object()) Fail(source, pointer, "expected a camera object, got " + std::string(j.type_name()));
  std::string type;
  if (const json* t = io::JsonFind(root, pointer + "/type"); t && !t->is_null()) {
    type = io::JsonString(root, pointer + "/type", source);
  }
  DistortionModel model = DistortionModel::kOpenCV;
  if (type == "fisheye") {
    model = DistortionModel::kFisheye;
  } else if (type == "h36m") {
    model = DistortionModel::kH36M;
  } else if (!type.empty() && type != "pinhole" && type != "opencv" && type != "perspective") {
    Fail(source, pointer + "/type", "unknown camera type " + QuoteName(type) + " (known: fisheye, pinhole, h36m)");
  }

  std::vector<double> dc;
  if (const json* d = io::JsonFind(root, pointer + "/DC"); d && !d->is_null()) {
    // Accept [k...] and [[k...]] (a 1xN matrix as some exporters write it).
    std::string dc_pointer = pointer + "/DC";
    if (d->is_array() && d->size() == 1 && (*d)[0].is_array()) dc_pointer += "/0";
    dc = io::JsonNumbers(root, dc_pointer, source);
  }
  std::array<double, 5> dist{0, 0, 0, 0, 0};
  if (model == DistortionModel::kFisheye) {
    if (dc.size() != 4) {
      Fail(source, pointer + "/DC",
           "a fisheye camera needs 4 coefficients (k1, k2, k3, k4), got " + std::to_string(dc.size()));
    }
  } else if (dc.size() != 5 && dc.size() != 4 && !dc.empty()) {
    Fail(source, pointer + "/DC", "expected 5 coefficients (k1, k2, p1, p2, k3), got " + std::to_string(dc.size()));
  }
  std::copy(dc.begin(), dc.end(), dist.begin());
  if (model != DistortionModel::kFisheye && std::all_of(dist.begin(), dist.end(), [](double v) { return v == 0; })) {
    model = DistortionModel::kNone;
  }

  const std::vector<double> k = io::JsonMatrix(root, pointer + "/K", source, 3, 3);
  const std::vector<double> r = io::JsonMatrix(root, pointer + "/R", source, 3, 3);
  const std::vector<double> t = io::JsonMatrix(root, pointer + "/T", source, 3, 1);
  Eigen::Matrix3d R;
  Eigen::Matrix3d K;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      R(row, col) = r[3 * row + col];
      K(row, col) = k[3 * row + col];
    }
  }
  R = AcceptRotation(R, source, source + ": " + pointer + "/R", warnings);
  Camera camera = Camera::FromCenter(R, Eigen::Vector3d(t[0], t[1], t[2]));
  camera.name = io::JsonString(root, pointer + "/name", source);
  camera.K = K;
  camera.model = model;
  camera.dist = dist;
  const std::int64_t width = io::JsonInt(root, pointer + "/width", source);
  const std::int64_t height = io::JsonInt(root, pointer + "/height", source);
  if (width <= 0 || height <= 0 || width > 1'000'000 || height > 1'000'000) {
    Fail(source, pointer, "image size " + std::to_string(width) + "x" + std::to_string(height) + " is not plausible");
  }
  camera.width = static_cast<int>(width);
  camera.height = static_cast<int>(height);
  if (const std::string error = camera.Validate(); !error.empty()) Fail(source, pointer, error);
  return camera;
}

std::vector<Camera> ParseCameras(const json& root, const std::string& pointer, const std::string& source,
                                 InputWarnings* warnings) {
  const json& list = io::JsonAt(root, pointer, source);
  if (!list.is_array() || list.empty()) Fail(source, pointer, "expected a non-empty list of cameras");
  io::CheckCameraCount(list.size(), source + ": " + pointer);
  std::vector<Camera> cameras;
  std::unordered_set<std::string> names;
  long unknown_keys = 0;
  std::string first_unknown;
  for (size_t c = 0; c < list.size(); ++c) {
    cameras.push_back(ParseCamera(root, io::JsonPointerJoin(pointer, c), source, warnings));
    for (const auto& [key, value] : list[c].items()) {
      if (std::find(kCameraKeys.begin(), kCameraKeys.end(), key) != kCameraKeys.end()) continue;
      if (unknown_keys++ == 0) first_unknown = UnknownKeyText(key, io::JsonPointerJoin(pointer, c));
    }
    CountImplausibleCamera(cameras.back(), source, warnings);
    if (!names.insert(cameras.back().name).second) {
      Fail(source, io::JsonPointerJoin(pointer, c) + "/name",
           "camera name " + QuoteName(cameras.back().name) + " appears twice");
    }
  }
  if (warnings != nullptr) {
    warnings->AddUnused(source, "keys in camera objects rpt does not read, ignored (the first: " + first_unknown + ")",
                        unknown_keys);
  }
  return cameras;
}

OrderedJson CameraJson(const Camera& camera, const std::string& source, const std::string& where) {
  for (Eigen::Index i = 0; i < 9; ++i) {
    io::CheckFiniteToWrite(camera.K.data()[i], source, where);
    io::CheckFiniteToWrite(camera.R.data()[i], source, where);
  }
  const Eigen::Vector3d center = camera.Center();
  for (int i = 0; i < 3; ++i) io::CheckFiniteToWrite(center[i], source, where);
  for (double d : camera.dist) io::CheckFiniteToWrite(d, source, where);
  OrderedJson j;
  j["name"] = camera.name;
  j["K"] = MatrixJson(camera.K);
  switch (camera.model) {
    case DistortionModel::kNone:
      j["DC"] = {0.0, 0.0, 0.0, 0.0, 0.0};
      break;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M:
      j["DC"] = {camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3], camera.dist[4]};
      break;
    case DistortionModel::kFisheye:
      j["DC"] = {camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3]};
      break;
  }
  j["R"] = MatrixJson(camera.R);
  j["T"] = OrderedJson::array(
      {OrderedJson::array({center[0]}), OrderedJson::array({center[1]}), OrderedJson::array({center[2]})});
  j["width"] = camera.width;
  j["height"] = camera.height;
  if (camera.model == DistortionModel::kFisheye) j["type"] = "fisheye";
  if (camera.model == DistortionModel::kH36M) j["type"] = "h36m";
  return j;
}

}  // namespace rpt::camera_json
