// SPDX-License-Identifier: MIT
// Our cameras JSON file, the canonical form `rpt cameras convert` goes through:
//
//   {"cameras": [
//     {"name": "cam0", "width": 1920, "height": 1080, "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]],
//      "DC": [-0.21, 0.07, 0.0011, -0.0007, -0.012], "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
//      "T": [[0.0], [-4.0], [1.5]]},
//     ...]}
//
// Each camera in the camera schema of the generic labels (docs/datasets/generic_formats.md):
// R world -> camera, T the camera CENTRE in metres (x_cam = R (X - T)), DC the OpenCV
// coefficients k1 k2 p1 p2 k3 (or "type": "fisheye" with k1..k4, "h36m"). A labels file (a JSON
// list of labels) is read too: the cameras of its first label.
#pragma once

#include <filesystem>
#include <vector>

#include "datasets/calibration/calibration.h"

namespace rpt {

// Throws InputError naming the file and the JSON pointer.
Calibration ReadCamerasJson(const std::filesystem::path& path, InputWarnings* warnings);

// One camera per line; doubles in their shortest exact form, so write -> read gives the same
// projections to round-off. Throws InputError naming the file and camera for non-finite values
// or when the file cannot be written.
void WriteCamerasJson(const std::filesystem::path& path, const std::vector<Camera>& cameras);

}  // namespace rpt
