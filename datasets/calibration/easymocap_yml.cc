// SPDX-License-Identifier: MIT
#include "datasets/calibration/easymocap_yml.h"

#include <set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/calibration/file_storage.h"
#include "datasets/calibration/image_size.h"
#include "datasets/calibration/opencv_yml.h"
#include "datasets/calibration/rodrigues.h"
#include "datasets/camera_plausibility.h"
#include "datasets/io/text_file.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using file_storage::File;
using namespace opencv_conventions;

constexpr double kRotationAgreement = 1e-6;  // max |R(R_) - Rot_| accepted when both are stored

// The rotation of camera `name`: R_ (Rodrigues vector, or a matrix), else Rot_; both must agree.
// Sets *form to what was read.
Eigen::Matrix3d ReadRotation(const File& extri, const std::string& name, InputWarnings* warnings, std::string* form) {
  const std::string r_key = "R_" + name, rot_key = "Rot_" + name;
  const bool has_r = extri.Find(r_key) != nullptr, has_rot = extri.Find(rot_key) != nullptr;
  if (!has_r && !has_rot) throw InputError(extri.source + ": " + r_key + ": missing (camera " + QuoteName(name) + " of names)");
  if (!has_r) {
    *form = "Rot_ (3x3 matrix)";
    return Rotation(extri.Numbers(rot_key, 9, "3x3"), extri.source, extri.source + ": " + rot_key, warnings);
  }
  const std::vector<double> r = extri.AnyNumbers(r_key);
  *form = r.size() == 3 ? "R_ (Rodrigues vector)" : "R_ (3x3 matrix)";
  const Eigen::Matrix3d R = Rotation(r, extri.source, extri.source + ": " + r_key, warnings);
  if (has_rot) {
    const Eigen::Matrix3d rot = Matrix3(extri.Numbers(rot_key, 9, "3x3"));
    const double difference = (rot - R).cwiseAbs().maxCoeff();
    if (!(difference <= kRotationAgreement)) {
      throw InputError(extri.source + ": " + rot_key + " differs from " + r_key + " by up to " +
                       std::to_string(difference) + " (they must hold the same rotation)");
    }
  }
  return R;
}

int OptionalSide(const File& intri, const std::string& key) {
  return intri.Find(key) != nullptr ? intri.Integer(key, 1, 1'000'000) : 0;
}

// A camera name that can be part of a FileStorage key (OpenCV accepts letters, digits, '-', '_'
// and ' '; spaces are refused too, as EasyMocap splits nothing but keys with them are fragile).
void CheckKeyName(const std::string& name, const std::string& source) {
  const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
  if (!ok) {
    throw InputError(source + ": cannot write camera " + QuoteName(name) +
                     " in the EasyMocap layout: its name becomes part of keys (K_<name>), which allow only letters, "
                     "digits, '-' and '_'; rename it or write json or toml");
  }
}

}  // namespace

std::vector<fs::path> EasyMocapFiles(const fs::path& path) {
  std::error_code ec;
  fs::path intri = path, extri = path;
  if (fs::is_directory(path, ec)) {
    intri = path / "intri.yml";
    extri = path / "extri.yml";
  } else if (path.stem() == "intri") {
    extri = path.parent_path() / ("extri" + path.extension().string());
  } else if (path.stem() == "extri") {
    intri = path.parent_path() / ("intri" + path.extension().string());
  }
  for (const fs::path& file : {intri, extri}) {
    if (!IsRegularFile(file)) {
      throw InputError(file.string() + ": file not found (EasyMocap cameras are intri.yml and extri.yml side by side)");
    }
  }
  return {intri, extri};
}

Calibration ReadEasyMocapCalibration(const fs::path& path, const CalibrationReadOptions& options,
                                     InputWarnings* warnings) {
  const std::vector<fs::path> paths = EasyMocapFiles(path);
  const File intri = file_storage::ReadFile(paths[0]);
  const File extri = paths[1] == paths[0] ? intri : file_storage::ReadFile(paths[1]);
  const double metres_per_unit = MetresPerUnit(options.units);

  Calibration calibration;
  CalibrationDescription& d = calibration.description;
  d.format = CalibrationFormat::kEasyMocap;
  d.files = paths[1] == paths[0] ? std::vector<fs::path>{paths[0]} : paths;
  d.extrinsics = "world to camera: x_cam = R X + T";
  d.units = options.units == LengthUnit::kDefault ? LengthUnit::kMetres : options.units;
  d.units_assumed = options.units == LengthUnit::kDefault;
  d.distortion = "OpenCV radial-tangential k1 k2 p1 p2 [k3] (dist_ or D_)";

  const std::vector<std::string> names = intri.Strings("names");
  if (names.empty()) throw InputError(intri.source + ": names: the list of cameras is empty");
  std::set<std::string> seen, forms;
  bool missing_distortion = false;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) throw InputError(intri.source + ": names: camera " + QuoteName(name) + " appears twice");
    Camera camera;
    camera.name = name;
    camera.K = Matrix3(intri.Numbers("K_" + name, 9, "3x3"));
    std::string dist_key = "dist_" + name;
    if (intri.Find(dist_key) == nullptr) dist_key = "D_" + name;
    if (intri.Find(dist_key) != nullptr) {
      SetDistortion(intri.AnyNumbers(dist_key), false, intri.source + ": " + dist_key, &camera);
    } else {
      missing_distortion = true;
    }
    camera.height = OptionalSide(intri, "H_" + name);
    camera.width = OptionalSide(intri, "W_" + name);
    std::string form;
    camera.R = ReadRotation(extri, name, warnings, &form);
    forms.insert(form);
    const std::vector<double> t = extri.Numbers("T_" + name, 3, "3x1");
    camera.t = Eigen::Vector3d(t[0], t[1], t[2]) * metres_per_unit;
    const std::string where = intri.source + ": camera " + QuoteName(name);
    CompleteImageSize(&camera, options.image_width, options.image_height, intri.source, where, warnings);
    if (const std::string error = camera.Validate(); !error.empty()) throw InputError(where + ": " + error);
    CountImplausibleCamera(camera, intri.source, warnings, extri.source);
    calibration.cameras.push_back(std::move(camera));
  }
  for (const std::string& form : forms) d.rotation += (d.rotation.empty() ? "" : ", ") + form;
  if (missing_distortion) d.notes.emplace_back("cameras without dist_ / D_ have no distortion");
  return calibration;
}

void WriteEasyMocapCameras(const fs::path& intri_path, const fs::path& extri_path, const std::vector<Camera>& cameras,
                           LengthUnit units) {
  const bool one_file = intri_path == extri_path;
  file_storage::Writer intri(intri_path.extension() == ".xml", intri_path.string());
  file_storage::Writer extri(extri_path.extension() == ".xml", extri_path.string());
  file_storage::Writer& extrinsics = one_file ? intri : extri;
  std::vector<std::string> names;
  for (const Camera& camera : cameras) {
    CheckKeyName(camera.name, intri_path.string());
    if (camera.model == DistortionModel::kFisheye) {
      throw InputError(intri_path.string() + ": cannot write camera " + QuoteName(camera.name) +
                       " in the EasyMocap layout: EasyMocap has no fisheye model (write toml or json, which keep "
                       "it; rpt writes OpenCV files in this layout only)");
    }
    names.push_back(camera.name);
  }
  intri.Strings("names", names);
  if (!one_file) extri.Strings("names", names);
  for (const Camera& camera : cameras) {
    const std::string& name = camera.name;
    intri.Matrix("K_" + name, 3, 3, RowMajor(camera.K));
    const std::vector<double> dist = DistortionCoefficients(camera, intri_path.string() + ": camera " + QuoteName(name));
    intri.Matrix("dist_" + name, 1, static_cast<int>(dist.size()), dist);
    intri.Integer("H_" + name, camera.height);
    intri.Integer("W_" + name, camera.width);
  }
  for (const Camera& camera : cameras) {
    const std::string& name = camera.name;
    const Eigen::Vector3d r = RodriguesFromRotation(camera.R);
    const Eigen::Vector3d t = camera.t / MetresPerUnit(units);
    extrinsics.Matrix("R_" + name, 3, 1, {r.x(), r.y(), r.z()});
    extrinsics.Matrix("Rot_" + name, 3, 3, RowMajor(camera.R));
    extrinsics.Matrix("T_" + name, 3, 1, {t.x(), t.y(), t.z()});
  }
  io::WriteTextFile(intri_path, io::NamedBy::kUser, intri.Finish());
  if (!one_file) io::WriteTextFile(extri_path, io::NamedBy::kUser, extri.Finish());
}

}  // namespace rpt
