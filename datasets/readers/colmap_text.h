// SPDX-License-Identifier: MIT
// COLMAP text model files (cameras.txt, images.txt), as written by `colmap model_converter
// --output_type TXT` and shipped by EgoHumans under colmap/workplace/.
//
// cameras.txt: '#' comment lines, then one camera per line: CAMERA_ID MODEL WIDTH HEIGHT PARAMS...
// images.txt:  '#' comment lines, then two lines per image:
//                IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME
//                POINTS2D[] as (X, Y, POINT3D_ID) ... (may be an empty line)
// The image pose maps world (COLMAP) to camera: x_cam = R(q) X + t.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

struct ColmapCamera {
  int camera_id = 0;
  std::string model;           // e.g. "OPENCV_FISHEYE"
  int width = 0;
  int height = 0;
  std::vector<double> params;  // model parameters in COLMAP order
  int line = 0;                // line number in the file (for messages)
};

struct ColmapImage {
  int image_id = 0;
  Eigen::Vector4d qvec_wxyz = Eigen::Vector4d(1, 0, 0, 0);  // unit quaternion, world -> camera
  Eigen::Vector3d tvec = Eigen::Vector3d::Zero();           // world -> camera translation
  int camera_id = 0;
  std::string name;  // e.g. "cam01/00001.jpg"
  int line = 0;
};

// Parse the text formats; `source` names the data in messages ("<source>:<line>: ...").
// Throws InputError on malformed lines, non-finite numbers, duplicate ids and quaternions whose
// norm is not within 1e-3 of 1 (AcceptQuaternion, datasets/input_warnings.h: they are normalised
// otherwise, and counted in `warnings` when given and the norm is off by more than round-off).
std::vector<ColmapCamera> ParseColmapCamerasText(std::istream& in, const std::string& source);
std::vector<ColmapImage> ParseColmapImagesText(std::istream& in, const std::string& source,
                                               InputWarnings* warnings = nullptr);
// Path overloads: open the file (InputError naming it when missing) and parse.
std::vector<ColmapCamera> ReadColmapCamerasText(const std::filesystem::path& path);
std::vector<ColmapImage> ReadColmapImagesText(const std::filesystem::path& path, InputWarnings* warnings = nullptr);

// Rotation matrix of a unit quaternion (w, x, y, z), COLMAP's convention.
Eigen::Matrix3d ColmapQuaternionToRotation(const Eigen::Vector4d& qvec_wxyz);

// Intrinsics of a COLMAP camera as a Camera (R = I, t = 0, name empty). Supported models:
// SIMPLE_PINHOLE (f cx cy), PINHOLE (fx fy cx cy), SIMPLE_RADIAL (f cx cy k), RADIAL
// (f cx cy k1 k2), OPENCV (fx fy cx cy k1 k2 p1 p2), FULL_OPENCV when k4..k6 are 0, and
// OPENCV_FISHEYE (fx fy cx cy k1 k2 k3 k4 -> DistortionModel::kFisheye). Throws InputError naming
// `source` and the line for other models or a wrong parameter count.
Camera ColmapCameraToCamera(const ColmapCamera& camera, const std::string& source);

}  // namespace rpt
