// SPDX-License-Identifier: MIT
// One camera in our JSON schema (docs/datasets/generic_formats.md, "Camera keys"): the camera
// objects of the generic labels and of the cameras JSON file (cameras_json.h).
//
//   {"name": "cam0", "width": 1920, "height": 1080, "K": 3x3, "DC": [k1, k2, p1, p2, k3],
//    "R": 3x3 world -> camera, "T": camera centre in metres (3x1 or flat), "type": optional}
//
// Not a public header: it exposes nlohmann::json, a private dependency of rpt_datasets.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt::camera_json {

// The camera object at `pointer`. An R within 1e-3 of a rotation is replaced by the nearest
// rotation and counted in `warnings` (nullptr: not counted, for re-parses of cameras already
// counted). Throws InputError "<source>: <pointer>/<key>: ..." for malformed values and cameras
// that fail Camera::Validate.
Camera ParseCamera(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                   InputWarnings* warnings);

// The non-empty list of cameras at `pointer`, names unique, each implausible camera counted
// (CountImplausibleCamera) in `warnings` when given.
std::vector<Camera> ParseCameras(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                                 InputWarnings* warnings);

// The camera object of `camera` (T = its centre; "type" for fisheye and h36m). Throws InputError
// "<source>: cannot write <where>: value is not finite" for non-finite values.
nlohmann::ordered_json CameraJson(const Camera& camera, const std::string& source, const std::string& where);

}  // namespace rpt::camera_json
