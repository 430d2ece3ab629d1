// SPDX-License-Identifier: MIT
#include "datasets/synthetic/camera_rig.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "core/options_check.h"
#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
namespace {

// d r_d / d r of the radial-tangential model's radial part, as a function of s = r^2.
double RadTanRadialDerivative(const std::array<double, 5>& d, double s) {
  return 1.0 + s * (3.0 * d[0] + s * (5.0 * d[1] + s * 7.0 * d[4]));
}

// d theta_d / d theta of the fisheye model.
double FisheyeDerivative(const std::array<double, 5>& d, double theta) {
  const double s = theta * theta;
  return 1.0 + s * (3.0 * d[0] + s * (5.0 * d[1] + s * (7.0 * d[2] + s * 9.0 * d[3])));
}

// Smallest x in (0, x_max] with derivative(x) <= 0 (scan with growing steps, then bisection), or
// +inf when there is none.
template <typename Derivative>
double FirstNonPositive(Derivative derivative, double x_max) {
  double previous = 0.0;
  double x = 0.0;
  while (x < x_max) {
    x = std::min(x_max, x + 1e-3 + 0.01 * x);
    if (!(derivative(x) > 0.0)) {
      double lo = previous, hi = x;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (derivative(mid) > 0.0 ? lo : hi) = mid;
      }
      return lo;
    }
    previous = x;
  }
  return std::numeric_limits<double>::infinity();
}

// Normalised distorted abscissa of the undistorted point (x, 0) (radial part only).
double DistortedAbscissa(DistortionModel model, const std::array<double, 5>& d, double x) {
  switch (model) {
    case DistortionModel::kNone:
      return x;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M: {
      const double s = x * x;
      return x * (1.0 + s * (d[0] + s * (d[1] + s * d[4])));
    }
    case DistortionModel::kFisheye: {
      const double theta = std::atan(x);
      const double s = theta * theta;
      return theta * (1.0 + s * (d[0] + s * (d[1] + s * (d[2] + s * d[3]))));
    }
  }
  return x;
}

// Random lens coefficients with realistic magnitudes.
std::array<double, 5> SampleDistortion(DistortionModel model, Rng& rng) {
  std::array<double, 5> d{0, 0, 0, 0, 0};
  switch (model) {
    case DistortionModel::kNone:
      break;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M:
      d[0] = rng.Uniform(-0.30, -0.05);                    // k1: barrel distortion
      d[1] = rng.Uniform(-0.02, 0.12);                     // k2
      d[2] = std::clamp(rng.Normal(0.0, 8e-4), -2e-3, 2e-3);  // p1
      d[3] = std::clamp(rng.Normal(0.0, 8e-4), -2e-3, 2e-3);  // p2
      d[4] = rng.Uniform(-0.01, 0.01);                     // k3
      break;
    case DistortionModel::kFisheye:
      d[0] = rng.Uniform(-0.02, 0.06);    // k1
      d[1] = rng.Uniform(-0.02, 0.01);    // k2
      d[2] = rng.Uniform(-0.005, 0.005);  // k3
      d[3] = rng.Uniform(-0.002, 0.002);  // k4
      break;
  }
  return d;
}

}  // namespace

double MonotonicRadius(const Camera& camera) {
  switch (camera.model) {
    case DistortionModel::kNone:
      return std::numeric_limits<double>::infinity();
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M: {
      const double s = FirstNonPositive([&](double x) { return RadTanRadialDerivative(camera.dist, x); }, 1e4);
      return std::sqrt(s);
    }
    case DistortionModel::kFisheye: {
      const double theta_max = 89.9 * std::numbers::pi / 180.0;
      const double theta = FirstNonPositive([&](double x) { return FisheyeDerivative(camera.dist, x); }, theta_max);
      return std::tan(std::min(theta, theta_max));
    }
  }
  return std::numeric_limits<double>::infinity();
}

Eigen::Matrix3d LookAtRotation(const Eigen::Vector3d& center, const Eigen::Vector3d& target, double roll_rad) {
  const Eigen::Vector3d z_axis = (target - center).normalized();
  const Eigen::Vector3d x_axis = z_axis.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y_axis = z_axis.cross(x_axis);
  Eigen::Matrix3d rotation;
  rotation.row(0) = x_axis.transpose();
  rotation.row(1) = y_axis.transpose();
  rotation.row(2) = z_axis.transpose();
  const Eigen::Matrix3d roll = Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return roll * rotation;
}

namespace {

// The field of view a rig uses: the given one, or the lens model's default.
double FieldOfViewDeg(const RigOptions& options) {
  const bool fisheye = options.distortion == DistortionModel::kFisheye;
  return options.horizontal_fov_deg > 0.0 ? options.horizontal_fov_deg : (fisheye ? 120.0 : 80.0);
}

}  // namespace

std::string RigOptions::Check() const {
  OptionsChecker checker("rig");
  checker("num_cameras", num_cameras, OptionSpec{.min = 1});
  checker("image_width", image_width, OptionSpec{.min = 1});
  checker("image_height", image_height, OptionSpec{.min = 1});
  checker("radius_m", radius_m, OptionSpec{.min = 0, .min_exclusive = true});
  const bool fisheye = distortion == DistortionModel::kFisheye;
  if (!(FieldOfViewDeg(*this) < (fisheye ? 179.0 : 170.0))) {
    std::string problem = "'";
    problem.append(FormatNumber(horizontal_fov_deg)).append("' is too wide for the lens model (it must be below ");
    checker.Require(problem.append(fisheye ? "179)" : "170)"), "horizontal_fov_deg");
  }
  return checker.error();
}

std::vector<Camera> MakeCameraRig(const RigOptions& options, uint64_t seed) {
  ThrowIfInvalid(options);
  const bool fisheye = options.distortion == DistortionModel::kFisheye;
  const double fov_deg = FieldOfViewDeg(options);

  Rng rng(DeriveSeed(seed, 0x716));
  const bool ring = options.layout == RigLayout::kRing;
  const int n = options.num_cameras;
  const double azimuth_offset = rng.Uniform(0.0, 2.0 * std::numbers::pi);
  const double w = options.image_width, h = options.image_height;
  const double half_fov = 0.5 * fov_deg * std::numbers::pi / 180.0;

  std::vector<Camera> cameras;
  cameras.reserve(n);
  for (int i = 0; i < n; ++i) {
    Camera camera;
    camera.name = "cam" + std::to_string(i);
    camera.width = options.image_width;
    camera.height = options.image_height;

    // Placement.
    double azimuth, radius, height;
    Eigen::Vector3d target = options.look_at_m;
    double roll;
    if (ring) {
      azimuth = azimuth_offset + 2.0 * std::numbers::pi * i / n + rng.Normal(0.0, 0.03);
      radius = options.radius_m * (1.0 + rng.Uniform(-0.02, 0.02));
      height = options.height_m + rng.Uniform(-0.05, 0.05);
      const double dz = rng.Normal(0.0, 0.03), dy = rng.Normal(0.0, 0.05), dx = rng.Normal(0.0, 0.05);  // random.h
      target += Eigen::Vector3d(dx, dy, dz);
      roll = rng.Normal(0.0, 0.005);
    } else {
      azimuth = azimuth_offset + 2.0 * std::numbers::pi * (i + rng.Uniform(-0.35, 0.35)) / n;
      radius = options.radius_m * rng.Uniform(0.75, 1.25);
      height = std::max(0.5, options.height_m + rng.Uniform(-0.8, 0.8));
      const double dz = rng.Uniform(-0.3, 0.3), dy = rng.Uniform(-0.5, 0.5), dx = rng.Uniform(-0.5, 0.5);  // random.h
      target += Eigen::Vector3d(dx, dy, dz);
      roll = rng.Normal(0.0, 0.03);
    }
    const Eigen::Vector3d center(options.look_at_m.x() + radius * std::cos(azimuth),
                                 options.look_at_m.y() + radius * std::sin(azimuth), height);
    camera.R = LookAtRotation(center, target, roll);
    camera.t = -camera.R * center;

    // Lens: resample until the model is monotonic well beyond the image corners.
    camera.model = options.distortion;
    const double corner_radius = std::tan(half_fov) * std::hypot(1.0, h / w);
    for (int attempt = 0;; ++attempt) {
      camera.dist = attempt < 100 ? SampleDistortion(options.distortion, rng) : std::array<double, 5>{0, 0, 0, 0, 0};
      if (attempt >= 100) break;
      const double limit = MonotonicRadius(camera);
      if (fisheye ? std::atan(limit) > std::min(1.5, 1.15 * std::atan(corner_radius)) : limit > 1.5 * corner_radius) break;
    }

    // Intrinsics: the horizontal field of view spans the image width (up to the jitter).
    const double focal_jitter = ring ? 1.0 + rng.Uniform(-0.02, 0.02) : rng.Uniform(0.9, 1.1);
    const double focal = focal_jitter * 0.5 * w / DistortedAbscissa(camera.model, camera.dist, std::tan(half_fov));
    camera.K = Eigen::Matrix3d::Identity();
    camera.K(0, 0) = focal;
    camera.K(1, 1) = focal;
    camera.K(0, 2) = 0.5 * w + rng.Normal(0.0, 0.005 * w);
    camera.K(1, 2) = 0.5 * h + rng.Normal(0.0, 0.005 * h);
    cameras.push_back(camera);
  }
  return cameras;
}

}  // namespace rpt::synthetic
