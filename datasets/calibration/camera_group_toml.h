// SPDX-License-Identifier: MIT
// Pose2Sim and anipose camera groups (.toml): one table per camera, world -> camera.
//
//   [cam_1]
//   name = "cam_1"
//   size = [ 1920.0, 1080.0]                          width, height (px)
//   matrix = [ [ 1000.0, 0.0, 960.0], [ 0.0, 1000.0, 540.0], [ 0.0, 0.0, 1.0]]
//   distortions = [ -0.2, 0.05, 0.001, -0.0005]       k1 k2 p1 p2 [k3]; fisheye: k1 k2 k3 k4
//   rotation = [ 1.2, -0.1, 0.3]                      Rodrigues vector, world -> camera
//   translation = [ 0.5, 0.8, 3.6]                    x_cam = R(rotation) X + translation
//   fisheye = false                                   optional (Pose2Sim)
//
//   [metadata]                                        skipped (and capture_volume, charuco,
//   adjusted = false                                  checkerboard, as Pose2Sim does)
//
// Units: Pose2Sim calibrates in metres; anipose in the units of its board's square size (often
// millimetres): CalibrationReadOptions::units says which, default metres (assumed, and a rig that
// looks like millimetres is warned by the plausibility checks). Cameras come in file order and
// are named by "name" (else the table's key).
#pragma once

#include <filesystem>
#include <vector>

#include "datasets/calibration/calibration.h"

namespace rpt {

// Throws InputError "<file>:<line>:<column>: ..." for TOML syntax errors and "<file>:<line>:
// [<table>].<key>: ..." for missing or malformed values.
Calibration ReadCameraGroupToml(const std::filesystem::path& path, const CalibrationReadOptions& options,
                                InputWarnings* warnings);

// Writes tables [cam_1] .. [cam_N] as Pose2Sim does (name = the camera's name, size as floats, 5
// distortion coefficients or 4 for fisheye with fisheye = true) and a [metadata] table;
// translations in `units` (default metres), numbers in their shortest exact form. Throws
// InputError for the Human3.6M lens model.
void WriteCameraGroupToml(const std::filesystem::path& path, const std::vector<Camera>& cameras, LengthUnit units);

}  // namespace rpt
