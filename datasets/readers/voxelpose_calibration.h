// SPDX-License-Identifier: MIT
// VoxelPose camera files: calibration_shelf.json, calibration_campus.json (also the format
// VoxelPose's synthetic training data uses).
//
// File convention (VoxelPose lib/utils/cameras_cpu.py): a JSON object keyed by camera id
// ("0", "1", ...). Per camera:
//   "R"  3x3 rotation world -> camera,
//   "T"  3x1 camera CENTRE in world coordinates, millimetres,
//   "fx", "fy", "cx", "cy"  pixels,
//   "k"  3x1 radial coefficients (k1, k2, k3), "p" 2x1 tangential (p1, p2),
// and the projection x_cam = R (X - T), then VoxelPose's radial-tangential model, which is
// algebraically OpenCV's with (k1, k2, p1, p2, k3) = (k[0], k[1], p[0], p[1], k[2]).
// rpt's convention is x_cam = R X + t in metres, so the reader sets t = -R T / 1000
// (Camera::FromCenter with the centre in metres).
#pragma once

#include <filesystem>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

// Reads every camera of a VoxelPose calibration json, ordered by id (numerically when all ids
// are integers, so "10" follows "9"). Each camera is named by its id and gets the given image
// size (the file does not store one); a size of 0 is taken as twice the principal point and
// counted in `warnings` (datasets/calibration/image_size.h). Distortion: DistortionModel::kOpenCV as above, or kNone
// when all coefficients are zero; "k" and "p" may be absent (= zero).
//
// The Shelf file stores R with 6 decimals (|R^T R - I| up to ~1.1e-6, just above
// Camera::Validate's 1e-6 tolerance), so an R within 1e-3 of a rotation is replaced by the
// nearest rotation (AcceptRotation, datasets/input_warnings.h) and counted in `warnings` when
// given; the change moves projections by ~1e-3 px.
//
// Throws InputError naming the file and the JSON pointer for a missing file, a missing or
// malformed entry, an R that is not a rotation (|R^T R - I| > 1e-3, or a reflection), and a
// camera that fails Camera::Validate.
std::vector<Camera> ReadVoxelPoseCalibration(const std::filesystem::path& path, int image_width, int image_height,
                                             InputWarnings* warnings = nullptr);

}  // namespace rpt
