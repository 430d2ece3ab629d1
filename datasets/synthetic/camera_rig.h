// SPDX-License-Identifier: MIT
// Synthetic multi-camera rigs looking into a room (world frame: metres, z up, floor z = 0).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/camera.h"

namespace rpt::synthetic {

enum class RigLayout {
  kRing,    // evenly spaced azimuths around look_at with small jitter, all at height_m
  kRandom,  // stratified random azimuths, radius and height varied, aim point jittered
};

struct RigOptions {
  int num_cameras = 5;                     // count; cameras are named "cam0", "cam1", ...
  RigLayout layout = RigLayout::kRing;     // placement pattern, see RigLayout
  double radius_m = 5.0;                   // m, horizontal distance of the cameras from look_at_m (random: x0.75-1.25)
  double height_m = 2.5;                   // m above the floor; the random layout varies it by +-0.8 m (min 0.5 m)
  Eigen::Vector3d look_at_m{0.0, 0.0, 1.0};  // m, world point the cameras aim at (room centre at ~1 m height)
  int image_width = 1920;                  // px, image width
  int image_height = 1080;                 // px, image height
  double horizontal_fov_deg = 0.0;         // degrees across the image width; <= 0: 80 (none/opencv), 120 (fisheye)
  DistortionModel distortion = DistortionModel::kNone;  // lens model; coefficients randomised per camera

  // "" when valid, else "rig.key: problem" (core/options_check.h).
  std::string Check() const;
};

// Builds the rig. Deterministic in (options, seed). Every camera has a proper rotation
// (orthonormal, det +1), K with square pixels and a principal point near the image centre, and
// distortion coefficients that are monotonic well beyond the image corners. Throws ConfigError with
// the problem of options.Check().
std::vector<Camera> MakeCameraRig(const RigOptions& options, uint64_t seed);

// Camera looking from `center` at `target` with world up +z, rolled by `roll_rad` about its
// optical axis (x right, y down, z forward). `target` must not be straight above/below `center`.
Eigen::Matrix3d LookAtRotation(const Eigen::Vector3d& center, const Eigen::Vector3d& target, double roll_rad = 0.0);

// The normalised (undistorted) radius up to which the lens model is monotonic, i.e. where points
// cannot fold back into the image: +inf for a pinhole, the first radius where d r_d / d r <= 0
// otherwise (radial part; fisheye: tan of the folding angle, at most tan(89.9 deg)).
double MonotonicRadius(const Camera& camera);

}  // namespace rpt::synthetic
