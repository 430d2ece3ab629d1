// SPDX-License-Identifier: MIT
// One camera (or a stereo pair) in an OpenCV cv::FileStorage file, as calibrateCamera /
// stereoCalibrate users and the OpenCV samples save it, and ROS camera_info YAML:
//
//   %YAML:1.0
//   ---
//   image_width: 1920                       (or image_size / imageSize: [w, h])
//   image_height: 1080
//   camera_matrix: !!opencv-matrix          (or K, M, cameraMatrix, intrinsic_matrix)
//      rows: 3
//      cols: 3
//      dt: d
//      data: [ 1000., 0., 960., 0., 1000., 540., 0., 0., 1. ]
//   distortion_coefficients: !!opencv-matrix   (or D, dist, dist_coeffs, distCoeffs, distortion)
//      rows: 1
//      cols: 5
//      dt: d
//      data: [ -0.2, 0.05, 0.001, -0.0005, 0. ]
//   R: !!opencv-matrix  3x3 matrix or 3x1 Rodrigues vector (or rvec, rotation), world -> camera
//   T: !!opencv-matrix  3x1 (or tvec, t, translation), world -> camera: x_cam = R X + T
//
// Matrices may also be plain sequences or maps with "data" (ROS). Distortion: OpenCV's k1 k2 p1 p2
// [k3 [k4 k5 k6 ...]] (coefficients past k3 must be 0: the rational model is not supported), or
// the fisheye model k1..k4 when fisheye_model is non-zero or distortion_model is "fisheye" /
// "equidistant". Without R and T the camera is the world origin. The name is camera_name when
// present, else the file's stem.
//
// Stereo files (the OpenCV stereo_calib sample): M1 / K1 / cameraMatrix1, D1 / distCoeffs1, the
// same with 2, and R, T (camera 2 from camera 1): cameras "1" (the world origin) and "2". The
// sample writes intrinsics.yml and extrinsics.yml: given either, the other one beside it is read
// too.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "datasets/calibration/calibration.h"

namespace rpt {

// Reads an OpenCV FileStorage file as above, or every OpenCVFilesIn a folder (one camera per file,
// in name order); translations in `options.units` (default: metres, assumed). Throws InputError
// naming the file and the node.
Calibration ReadOpenCVCalibration(const std::filesystem::path& path, const CalibrationReadOptions& options,
                                  InputWarnings* warnings);

// The *.yml, *.yaml and *.xml files (any case) directly in `dir`, sorted by name.
std::vector<std::filesystem::path> OpenCVFilesIn(const std::filesystem::path& dir);

// Writes one camera as above (camera_name, image_width, image_height, camera_matrix,
// distortion_coefficients 1x5 or 1x4 with fisheye_model: 1, R 3x3, T 3x1 in `units`); XML when
// the file name ends in .xml. Throws InputError for the Human3.6M lens model.
void WriteOpenCVCamera(const std::filesystem::path& path, const Camera& camera, LengthUnit units);

// Shared with the EasyMocap layout (easymocap_yml.h).
namespace opencv_conventions {

// The lens model of OpenCV distortion coefficients: none for an empty list, else kOpenCV for 4
// or 5 coefficients (and 8, 12 or 14 whose coefficients past the fifth are 0), kFisheye for
// exactly 4 when `fisheye`. Throws InputError "<where>: ..." otherwise.
void SetDistortion(const std::vector<double>& coefficients, bool fisheye, const std::string& where, Camera* camera);

// The distortion coefficients written for `camera` (5 for kNone / kOpenCV, 4 for kFisheye);
// InputError "<where>: ..." for kH36M.
std::vector<double> DistortionCoefficients(const Camera& camera, const std::string& where);

// A rotation stored as 9 numbers (row-major matrix, re-orthonormalised within 1e-3 and counted
// by AcceptRotation) or 3 (Rodrigues vector). Throws InputError "<where>: ..." otherwise.
Eigen::Matrix3d Rotation(const std::vector<double>& numbers, const std::string& source, const std::string& where,
                         InputWarnings* warnings);

// 9 row-major numbers of a 3x3 matrix.
std::vector<double> RowMajor(const Eigen::Matrix3d& m);
// K from 9 row-major numbers.
Eigen::Matrix3d Matrix3(const std::vector<double>& v);

}  // namespace opencv_conventions
}  // namespace rpt
