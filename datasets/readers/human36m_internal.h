// SPDX-License-Identifier: MIT
// Internal pieces of the Human3.6M reader shared with the H3WB reader (not a public header).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"
#include "datasets/io/py_value.h"

namespace rpt::h36m_ego {

// Cameras of `subject` from the dict stored in the learnable-triangulation labels npy
// (`subject_names`, `camera_names`, structured `cameras` with R, t (mm), K, dist). R is stored as
// float32: it goes through AcceptRotation and is counted in `warnings`.
std::vector<Camera> LearnableTriCameras(const io::PyView& labels, const std::string& subject, DistortionModel model,
                                        InputWarnings* warnings);

// A Human3.6M camera from the raw calibration numbers. R is world->camera, centre in metres.
// Distortion stored as (k1, k2, p1, p2, k3); zeroed for kNone.
Camera MakeH36mCamera(const std::string& id, const Eigen::Matrix3d& R_cam_from_world, const Eigen::Vector3d& center_m,
                      double fx, double fy, double cx, double cy, double k1, double k2, double k3, double p1, double p2,
                      DistortionModel model);

}  // namespace rpt::h36m_ego
