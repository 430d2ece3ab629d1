// SPDX-License-Identifier: MIT
// A COLMAP text model (cameras.txt + images.txt, datasets/readers/colmap_text.h) as a calibration:
// one camera per line of images.txt, with the intrinsics of its CAMERA_ID and its pose
// (quaternion QW QX QY QZ and TX TY TZ, world -> camera: x_cam = R(q) X + t), named by the image
// NAME without its extension ("cam01/00001.jpg" -> "cam01/00001"). COLMAP's scale is arbitrary
// unless the model was scaled: CalibrationReadOptions::units says what one unit is (default
// metres, assumed).
#pragma once

#include <filesystem>
#include <vector>

#include "datasets/calibration/calibration.h"

namespace rpt {

// `path` is cameras.txt, images.txt (the other one beside it) or the folder holding both.
// Throws InputError naming the file and the line.
Calibration ReadColmapCalibration(const std::filesystem::path& path, const CalibrationReadOptions& options,
                                  InputWarnings* warnings);

}  // namespace rpt
