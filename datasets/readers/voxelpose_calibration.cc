// SPDX-License-Identifier: MIT
#include "datasets/readers/voxelpose_calibration.h"

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "datasets/calibration/image_size.h"
#include "datasets/calibration/row_major.h"
#include "datasets/camera_plausibility.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"

namespace rpt {
namespace {

// Optional n x 1 coefficient vector; absent = zeros.
std::vector<double> OptionalCoefficients(const nlohmann::json& root, const std::string& pointer,
                                         const std::string& source, std::size_t n) {
  if (io::JsonFind(root, pointer) == nullptr) return std::vector<double>(n, 0.0);
  return io::JsonMatrix(root, pointer, source, n, 1);
}

}  // namespace

std::vector<Camera> ReadVoxelPoseCalibration(const std::filesystem::path& path, int image_width, int image_height,
                                             InputWarnings* warnings) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  std::vector<Camera> cameras;
  io::ForEachJsonCamera(root, source, "R, T, fx, fy, cx, cy", [&](const std::string& id, const std::string& base) {
    const Eigen::Matrix3d R_file = Matrix3FromRowMajor(io::JsonMatrix(root, base + "/R", source, 3, 3).data());
    const std::vector<double> center_mm = io::JsonMatrix(root, base + "/T", source, 3, 1);
    const Eigen::Matrix3d R = AcceptRotation(R_file, source, source + ": " + base + "/R", warnings);

    // x_cam = R (X - C): the file's T is the centre C, in millimetres.
    Camera camera = Camera::FromCenter(R, Eigen::Vector3d(center_mm[0], center_mm[1], center_mm[2]) / 1000.0);
    camera.name = id;
    // Read before the comma initialiser: a throw inside one (a missing key) aborts Debug builds
    // (Eigen asserts that every coefficient was given).
    const double fx = io::JsonNumber(root, base + "/fx", source);
    const double fy = io::JsonNumber(root, base + "/fy", source);
    const double cx = io::JsonNumber(root, base + "/cx", source);
    const double cy = io::JsonNumber(root, base + "/cy", source);
    camera.K << fx, 0.0, cx,  //
        0.0, fy, cy,          //
        0.0, 0.0, 1.0;

    const std::vector<double> k = OptionalCoefficients(root, base + "/k", source, 3);
    const std::vector<double> p = OptionalCoefficients(root, base + "/p", source, 2);
    camera.dist = {k[0], k[1], p[0], p[1], k[2]};
    const bool distorted = std::any_of(camera.dist.begin(), camera.dist.end(), [](double c) { return c != 0.0; });
    camera.model = distorted ? DistortionModel::kOpenCV : DistortionModel::kNone;

    // No size given (0): twice the principal point, counted.
    CompleteImageSize(&camera, image_width, image_height, source, source + ": " + base, warnings);
    if (const std::string error = camera.Validate(); !error.empty()) {
      throw InputError(source + ": " + base + ": " + error);  // error names the camera
    }
    CountImplausibleCamera(camera, source, warnings);
    cameras.push_back(std::move(camera));
  });
  return cameras;
}

}  // namespace rpt
