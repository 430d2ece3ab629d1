// SPDX-License-Identifier: MIT
#include "datasets/readers/fourda_calibration.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "datasets/calibration/rodrigues.h"
#include "datasets/calibration/row_major.h"
#include "datasets/camera_plausibility.h"
#include "datasets/io/json_file.h"

namespace rpt {
namespace {

// "R": a Rodrigues vector (axis * angle in radians) or a row-major matrix.
Eigen::Matrix3d ReadFourDaRotation(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const std::vector<double> r = io::JsonNumbers(root, pointer, source);
  if (r.size() == 9) return Matrix3FromRowMajor(r.data());
  if (r.size() != 3) {
    throw InputError(source + ": " + pointer + ": expected 3 numbers (Rodrigues vector) or 9 (row-major matrix), got " +
                     std::to_string(r.size()));
  }
  return RotationFromStoredRodrigues(Eigen::Vector3d(r[0], r[1], r[2]), source + ": " + pointer);
}

int FourDaImageSide(double value, const std::string& where) {
  if (!(value >= 1.0 && value <= 1e6) || value != std::floor(value)) {
    throw InputError(where + ": image size " + std::to_string(value) + " is not a positive integer");
  }
  return static_cast<int>(value);
}

}  // namespace

std::vector<Camera> ReadFourDaCalibration(const std::filesystem::path& path, InputWarnings* warnings) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  std::vector<Camera> cameras;
  io::ForEachJsonCamera(root, source, "K, RT, imgSize", [&](const std::string& id, const std::string& base) {
    Camera camera;
    camera.name = id;
    camera.K = Matrix3FromRowMajor(io::JsonNumbers(root, base + "/K", source, 9).data());
    const std::vector<double> size = io::JsonNumbers(root, base + "/imgSize", source, 2);
    camera.width = FourDaImageSide(size[0], source + ": " + base + "/imgSize");
    camera.height = FourDaImageSide(size[1], source + ": " + base + "/imgSize");

    Eigen::Matrix3d R;
    std::string rotation_pointer;
    if (io::JsonFind(root, base + "/RT") != nullptr) {
      rotation_pointer = base + "/RT";
      const std::vector<double> rt = io::JsonNumbers(root, rotation_pointer, source, 12);
      R << rt[0], rt[1], rt[2], rt[4], rt[5], rt[6], rt[8], rt[9], rt[10];
      camera.t = Eigen::Vector3d(rt[3], rt[7], rt[11]);
    } else if (io::JsonFind(root, base + "/R") != nullptr || io::JsonFind(root, base + "/T") != nullptr) {
      rotation_pointer = base + "/R";
      R = ReadFourDaRotation(root, rotation_pointer, source);
      const std::vector<double> t = io::JsonNumbers(root, base + "/T", source, 3);
      camera.t = Eigen::Vector3d(t[0], t[1], t[2]);
    } else {
      throw InputError(source + ": " + base + ": no extrinsics (expected \"RT\", or \"R\" and \"T\")");
    }
    camera.R = AcceptRotation(R, source, source + ": " + rotation_pointer, warnings);

    if (io::JsonFind(root, base + "/distCoeff") != nullptr) {
      const std::vector<double> dist = io::JsonNumbers(root, base + "/distCoeff", source);
      if (std::any_of(dist.begin(), dist.end(), [](double c) { return c != 0.0; })) {
        throw InputError(source + ": " + base +
                         "/distCoeff: non-zero distortion is not supported (4D-Association then works on images "
                         "rectified with OpenCV's getOptimalNewCameraMatrix, which rpt does not reproduce)");
      }
    }
    camera.model = DistortionModel::kNone;
    if (const std::string error = camera.Validate(); !error.empty()) {
      throw InputError(source + ": " + base + ": " + error);  // error names the camera
    }
    CountImplausibleCamera(camera, source, warnings);
    cameras.push_back(std::move(camera));
  });
  return cameras;
}

}  // namespace rpt
