// SPDX-License-Identifier: MIT
#include "datasets/calibration/cameras_json.h"

#include <string>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/calibration/camera_json.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/text_file.h"

namespace rpt {

Calibration ReadCamerasJson(const std::filesystem::path& path, InputWarnings* warnings) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  Calibration calibration;
  CalibrationDescription& d = calibration.description;
  d.format = CalibrationFormat::kJson;
  d.files = {path};
  d.extrinsics = "world to camera with the camera centre T: x_cam = R (X - T)";
  d.rotation = "3x3 matrix";
  d.units = LengthUnit::kMetres;
  d.distortion =
      "DC: OpenCV radial-tangential k1 k2 p1 p2 k3; \"type\": \"fisheye\" k1..k4; \"h36m\" Human3.6M variant";
  std::string pointer = "/cameras";
  if (root.is_array()) {
    if (root.empty()) throw InputError(source + ": /: an empty list of labels holds no cameras");
    pointer = "/0/cameras";
    d.notes.emplace_back("a labels file: the cameras of its first label");
  } else if (!root.is_object()) {
    throw InputError(source + ": /: expected {\"cameras\": [...]} or a list of labels, got " +
                     std::string(root.type_name()));
  }
  calibration.cameras = camera_json::ParseCameras(root, pointer, source, warnings);
  return calibration;
}

void WriteCamerasJson(const std::filesystem::path& path, const std::vector<Camera>& cameras) {
  const std::string source = path.string();
  std::string text = "{\"cameras\": [\n";
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    const nlohmann::ordered_json camera =
        camera_json::CameraJson(cameras[c], source, "camera " + std::to_string(c) + " (" + QuoteName(cameras[c].name) + ")");
    text += "  " + io::DumpJson(camera, -1) + (c + 1 < cameras.size() ? ",\n" : "\n");
  }
  text += "]}\n";
  io::WriteTextFile(path, io::NamedBy::kUser, text);
}

}  // namespace rpt
