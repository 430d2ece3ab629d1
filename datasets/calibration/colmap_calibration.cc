// SPDX-License-Identifier: MIT
#include "datasets/calibration/colmap_calibration.h"

#include <map>
#include <set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/camera_plausibility.h"
#include "datasets/readers/colmap_text.h"

namespace rpt {

Calibration ReadColmapCalibration(const std::filesystem::path& path, const CalibrationReadOptions& options,
                                  InputWarnings* warnings) {
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::is_directory(path, ec) ? path : path.parent_path();
  const std::filesystem::path cameras_path = folder / "cameras.txt", images_path = folder / "images.txt";
  const std::vector<ColmapCamera> colmap_cameras = ReadColmapCamerasText(cameras_path);
  const std::vector<ColmapImage> images = ReadColmapImagesText(images_path, warnings);
  const std::string source = images_path.string();

  Calibration calibration;
  CalibrationDescription& d = calibration.description;
  d.format = CalibrationFormat::kColmap;
  d.files = {cameras_path, images_path};
  d.extrinsics = "world to camera: x_cam = R(q) X + t";
  d.rotation = "unit quaternion QW QX QY QZ";
  d.units = options.units == LengthUnit::kDefault ? LengthUnit::kMetres : options.units;
  d.units_assumed = options.units == LengthUnit::kDefault;
  d.distortion = "per COLMAP camera model (PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV, OPENCV_FISHEYE)";
  d.notes.emplace_back("one camera per image, named by the image name without its extension");

  std::map<int, const ColmapCamera*> by_id;
  for (const ColmapCamera& camera : colmap_cameras) by_id[camera.camera_id] = &camera;
  std::set<std::string> names;
  for (const ColmapImage& image : images) {
    const std::string where = source + ":" + std::to_string(image.line);
    const auto it = by_id.find(image.camera_id);
    if (it == by_id.end()) {
      throw InputError(where + ": CAMERA_ID " + std::to_string(image.camera_id) + " is not in " +
                       cameras_path.string());
    }
    Camera camera = ColmapCameraToCamera(*it->second, cameras_path.string());
    camera.name = std::filesystem::path(image.name).replace_extension().string();
    if (camera.name.empty()) throw InputError(where + ": the image has no NAME");
    if (!names.insert(camera.name).second) {
      throw InputError(where + ": a second image named " + QuoteName(camera.name) + " (camera names must be unique)");
    }
    camera.R = ColmapQuaternionToRotation(image.qvec_wxyz);
    camera.t = image.tvec * MetresPerUnit(options.units);
    if (const std::string error = camera.Validate(); !error.empty()) throw InputError(where + ": " + error);
    CountImplausibleCamera(camera, source, warnings);
    calibration.cameras.push_back(std::move(camera));
  }
  if (calibration.cameras.empty()) throw InputError(source + ": no image, so no camera pose");
  return calibration;
}

}  // namespace rpt
