// SPDX-License-Identifier: MIT
// EasyMocap's camera files (easymocap/mytools/camera_utils.py): intri.yml and extri.yml, written
// by cv::FileStorage, one set of keys per camera of the `names` list:
//
//   intri.yml: names: ["01", "02"], K_01 (3x3), dist_01 (1x5: k1 k2 p1 p2 k3; or D_01),
//              optional H_01, W_01 (image height, width)
//   extri.yml: names, R_01 (3x1 Rodrigues vector), Rot_01 (3x3 matrix, the same rotation),
//              T_01 (3x1): world -> camera, x_cam = R X + T, metres in EasyMocap
//
// As in EasyMocap, R_ is the rotation read; Rot_ alone is accepted, and when both are there they
// must agree (within 1e-6). Both sets of keys may also be in one file (what the OpenCV writer
// writes for several cameras).
#pragma once

#include <filesystem>
#include <vector>

#include "datasets/calibration/calibration.h"

namespace rpt {

// `path` is intri.* (extri.* with the same extension beside it is read too), extri.* (likewise),
// a folder holding intri.yml and extri.yml, or one file holding both sets of keys. Translations
// in `options.units` (default: metres, assumed). Throws InputError naming the file and the key.
Calibration ReadEasyMocapCalibration(const std::filesystem::path& path, const CalibrationReadOptions& options,
                                     InputWarnings* warnings);

// The intri.yml and extri.yml files of `path` (intri.* / extri.* or a folder), as ReadEasyMocapCalibration finds them.
std::vector<std::filesystem::path> EasyMocapFiles(const std::filesystem::path& path);

// Writes the keys above for every camera: into intri + extri files when `intri` and `extri`
// differ, else both sets into one file. H_ and W_ are written too. Throws InputError for camera
// names that cannot be part of a key (letters, digits, '-', '_' and ' ' only), fisheye and
// Human3.6M lens models (EasyMocap has neither).
void WriteEasyMocapCameras(const std::filesystem::path& intri, const std::filesystem::path& extri,
                           const std::vector<Camera>& cameras, LengthUnit units);

}  // namespace rpt
