// SPDX-License-Identifier: MIT
// Cameras of a 4D-Association calibration.json (Zhang et al., CVPR 2020; the Shelf bundle in
// data/shelf/ and the Tsinghua multi-view dataset use the same file).
//
// A JSON object keyed by camera id ("0", "1", ...); each camera an object with
//   "K"        9 numbers, row-major 3x3 intrinsics (pixels)
//   "imgSize"  [width, height] in pixels
//   "RT"       12 numbers, row-major 3x4 [R | t], world -> camera, t in metres: x_cam = R X + t
//   or "R" (3 numbers = Rodrigues vector, or 9 = row-major matrix) and "T" (3 numbers, metres).
//      When "RT" is present it wins, as in 4D-Association's parser.
//   "distCoeff" optional, OpenCV order (k1, k2, p1, p2, k3, ...); absent = none. Only all-zero
//      coefficients are accepted: with distortion, 4D-Association undistorts its images (OpenCV
//      getOptimalNewCameraMatrix with "rectifyAlpha", then a rectification map) and works with
//      the new camera matrix, a model rpt does not reproduce. "rectifyAlpha" and "newImgSize"
//      are ignored (without distortion they change nothing).
// Cameras are named by their id and ordered numerically when every id is an integer (else by
// name). Rotations go through AcceptRotation: the files store them with 6-8 significant digits,
// so they are re-orthonormalised and counted under the file in `warnings`, never refused unless
// they are not rotations at all. Throws InputError naming the file and JSON pointer.
#pragma once

#include <filesystem>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

std::vector<Camera> ReadFourDaCalibration(const std::filesystem::path& path, InputWarnings* warnings);

}  // namespace rpt
