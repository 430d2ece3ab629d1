// SPDX-License-Identifier: MIT
// Camera model implementation. Plain C++ and Eigen only: the undistortion runs per keypoint in
// the hot path, so everything here is allocation-free and branch-light, with one switch on the
// model per call and no virtual dispatch.
#include "core/camera.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rpt {

namespace {

// Iteration limits shared by the 2D and 1D Newton solvers. Newton converges quadratically for
// realistic lenses (3-5 iterations to machine precision), so 20 is only reached for inputs far
// outside the calibrated field of view; the cap keeps the worst case bounded.
constexpr int kMaxNewtonIterations = 20;
constexpr double kStepTolerance = 1e-14;
// Step halvings tried when a full Newton step does not reduce the residual (strong distortion
// near the edge of the field of view, where the Jacobian changes quickly).
constexpr int kMaxStepHalvings = 8;
// Below this radius the fisheye factor theta_d / r is replaced by its limit 1, as OpenCV does.
// The relative error of that substitution is O(r^2) = 1e-16, i.e. below double precision.
constexpr double kFisheyeMinRadius = 1e-8;
// Largest incidence angle the fisheye inverse may return: just below 90 degrees, so tan(theta)
// stays finite (~1e9) instead of overflowing or flipping sign.
constexpr double kFisheyeMaxTheta = 1.5707963267948966 - 1e-9;

// Radial-tangential lens (kOpenCV and kH36M) with its Jacobian d(x_d, y_d) / d(x, y).
// `h36m` selects the Human3.6M tangential term (no factor 2, see camera.h).
inline Eigen::Vector2d DistortRadTan(const std::array<double, 5>& d, bool h36m, double x, double y,
                                     Eigen::Matrix2d* jacobian) {
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4];
  const double x2 = x * x, y2 = y * y, xy = x * y;
  const double r2 = x2 + y2;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  Eigen::Vector2d out;
  if (!h36m) {
    out.x() = x * radial + 2.0 * p1 * xy + p2 * (r2 + 2.0 * x2);
    out.y() = y * radial + p1 * (r2 + 2.0 * y2) + 2.0 * p2 * xy;
  } else {
    // Human3.6M (cameras.py of the dataset tools): tan = p1*y + p2*x,
    // x_d = x * (radial + tan) + p2 * r2, y_d = y * (radial + tan) + p1 * r2.
    const double tan = p1 * y + p2 * x;
    out.x() = x * (radial + tan) + p2 * r2;
    out.y() = y * (radial + tan) + p1 * r2;
  }
  if (jacobian != nullptr) {
    // d(radial)/d(r2); d(r2)/dx = 2x, d(r2)/dy = 2y.
    const double dradial = k1 + r2 * (2.0 * k2 + 3.0 * k3 * r2);
    const double common = 2.0 * xy * dradial;
    Eigen::Matrix2d& j = *jacobian;
    if (!h36m) {
      j(0, 0) = radial + 2.0 * x2 * dradial + 2.0 * p1 * y + 6.0 * p2 * x;
      j(0, 1) = common + 2.0 * p1 * x + 2.0 * p2 * y;
      j(1, 0) = common + 2.0 * p1 * x + 2.0 * p2 * y;
      j(1, 1) = radial + 2.0 * y2 * dradial + 6.0 * p1 * y + 2.0 * p2 * x;
    } else {
      const double tan = p1 * y + p2 * x;
      j(0, 0) = radial + tan + 2.0 * x2 * dradial + 3.0 * p2 * x;
      j(0, 1) = common + p1 * x + 2.0 * p2 * y;
      j(1, 0) = common + p2 * y + 2.0 * p1 * x;
      j(1, 1) = radial + tan + 2.0 * y2 * dradial + 3.0 * p1 * y;
    }
  }
  return out;
}

// Fisheye polynomial theta_d(theta) = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8)
// and, optionally, its derivative.
inline double FisheyeThetaD(const std::array<double, 5>& d, double theta, double* derivative) {
  const double t2 = theta * theta;
  const double poly = 1.0 + t2 * (d[0] + t2 * (d[1] + t2 * (d[2] + t2 * d[3])));
  if (derivative != nullptr) {
    *derivative = 1.0 + t2 * (3.0 * d[0] + t2 * (5.0 * d[1] + t2 * (7.0 * d[2] + t2 * 9.0 * d[3])));
  }
  return theta * poly;
}

inline bool IsFinite(const Eigen::Vector2d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// Residual norm used to compare iterates; +inf for non-finite values so they never win.
inline double ResidualNorm(const Eigen::Vector2d& r) {
  const double n = r.squaredNorm();
  return std::isfinite(n) ? n : std::numeric_limits<double>::infinity();
}

// Inverts the radial-tangential model by Newton's method on F(p) = Distort(p) - target, starting
// at the distorted point. A step that does not reduce |F| is halved (simple backtracking) so the
// solver cannot run away at the edge of the field of view, and the best iterate seen is returned,
// which keeps the result finite for any finite input.
Eigen::Vector2d UndistortRadTan(const std::array<double, 5>& d, bool h36m, const Eigen::Vector2d& target) {
  Eigen::Vector2d p = target;
  Eigen::Matrix2d jacobian;
  Eigen::Vector2d residual = DistortRadTan(d, h36m, p.x(), p.y(), &jacobian) - target;
  double residual_norm = ResidualNorm(residual);
  if (!std::isfinite(residual_norm)) return target;  // coefficients overflow here: nothing better
  for (int iteration = 0; iteration < kMaxNewtonIterations && residual_norm > 0.0; ++iteration) {
    // Explicit 2x2 inverse (cheaper and clearer than a generic decomposition).
    const double det = jacobian(0, 0) * jacobian(1, 1) - jacobian(0, 1) * jacobian(1, 0);
    if (!(std::abs(det) > 1e-300)) break;  // singular (or NaN) Jacobian: keep the best iterate
    Eigen::Vector2d step((jacobian(1, 1) * residual.x() - jacobian(0, 1) * residual.y()) / det,
                         (jacobian(0, 0) * residual.y() - jacobian(1, 0) * residual.x()) / det);
    if (!IsFinite(step)) break;

    bool improved = false;
    for (int halving = 0; halving <= kMaxStepHalvings; ++halving, step *= 0.5) {
      const Eigen::Vector2d candidate = p - step;
      Eigen::Matrix2d candidate_jacobian;
      const Eigen::Vector2d candidate_residual =
          DistortRadTan(d, h36m, candidate.x(), candidate.y(), &candidate_jacobian) - target;
      const double candidate_norm = ResidualNorm(candidate_residual);
      if (candidate_norm < residual_norm) {
        p = candidate;
        jacobian = candidate_jacobian;
        residual = candidate_residual;
        residual_norm = candidate_norm;
        improved = true;
        break;
      }
      // Already at the resolution of double precision: no smaller step can help.
      if (step.lpNorm<Eigen::Infinity>() < kStepTolerance) break;
    }
    if (!improved || step.lpNorm<Eigen::Infinity>() < kStepTolerance) break;
  }
  return p;
}

// Inverts the fisheye model: the distortion only rescales the radius, so solve the scalar
// equation theta_d(theta) = |target| for theta in [0, pi/2) by Newton (bisection towards the
// bound if a step leaves the interval), then rescale the point to radius tan(theta).
Eigen::Vector2d UndistortFisheye(const std::array<double, 5>& d, const Eigen::Vector2d& target) {
  const double rd = std::hypot(target.x(), target.y());  // hypot: no overflow for huge inputs
  if (!(rd >= kFisheyeMinRadius)) return target;  // centre (factor 1), also catches NaN
  double theta = std::min(rd, kFisheyeMaxTheta);
  double derivative = 0.0;
  double residual = FisheyeThetaD(d, theta, &derivative) - rd;
  double best_theta = theta;
  double best_residual = std::abs(residual);
  for (int iteration = 0; iteration < kMaxNewtonIterations && best_residual > 0.0; ++iteration) {
    if (!(derivative > 0.0)) break;  // the polynomial folds back: no unique inverse beyond here
    const double step = residual / derivative;
    if (!std::isfinite(step)) break;
    double next = theta - step;
    if (next < 0.0) next = 0.5 * theta;
    if (next > kFisheyeMaxTheta) next = 0.5 * (theta + kFisheyeMaxTheta);
    const double actual_step = theta - next;
    theta = next;
    residual = FisheyeThetaD(d, theta, &derivative) - rd;
    if (std::abs(residual) < best_residual) {
      best_residual = std::abs(residual);
      best_theta = theta;
    }
    if (std::abs(actual_step) < kStepTolerance) break;
  }
  const double r = std::tan(best_theta);
  return target * (r / rd);
}

}  // namespace

const char* DistortionModelName(DistortionModel model) {
  switch (model) {
    case DistortionModel::kNone:
      return "none";
    case DistortionModel::kOpenCV:
      return "opencv";
    case DistortionModel::kH36M:
      return "h36m";
    case DistortionModel::kFisheye:
      return "fisheye";
  }
  return "unknown";
}

Camera Camera::FromCenter(const Eigen::Matrix3d& R_cam_from_world, const Eigen::Vector3d& center_in_world) {
  Camera camera;
  camera.R = R_cam_from_world;
  camera.t = -R_cam_from_world * center_in_world;
  return camera;
}

Camera Camera::FromCamToWorld(const Eigen::Matrix3d& R_world_from_cam, const Eigen::Vector3d& center_in_world) {
  // The transpose is the inverse only for a proper rotation; Validate() reports anything else.
  return FromCenter(R_world_from_cam.transpose(), center_in_world);
}

bool Camera::HasDistortion() const {
  switch (model) {
    case DistortionModel::kNone:
      return false;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M:
      return std::any_of(dist.begin(), dist.end(), [](double c) { return c != 0.0; });
    case DistortionModel::kFisheye:
      // Even with k1..k4 = 0 the fisheye model is the equidistant projection r_d = atan(r),
      // which is not the pinhole model.
      return true;
  }
  return false;
}

Eigen::Vector2d Camera::Distort(const Eigen::Vector2d& xy) const {
  switch (model) {
    case DistortionModel::kNone:
      return xy;
    case DistortionModel::kOpenCV:
      return DistortRadTan(dist, /*h36m=*/false, xy.x(), xy.y(), nullptr);
    case DistortionModel::kH36M:
      return DistortRadTan(dist, /*h36m=*/true, xy.x(), xy.y(), nullptr);
    case DistortionModel::kFisheye: {
      const double r = std::hypot(xy.x(), xy.y());
      if (r < kFisheyeMinRadius) return xy;
      const double theta_d = FisheyeThetaD(dist, std::atan(r), nullptr);
      return xy * (theta_d / r);
    }
  }
  return xy;
}

Eigen::Vector2d Camera::UndistortNormalized(const Eigen::Vector2d& xy_distorted) const {
  switch (model) {
    case DistortionModel::kNone:
      return xy_distorted;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M:
      if (!HasDistortion()) return xy_distorted;  // all-zero coefficients: pinhole fast path
      return UndistortRadTan(dist, model == DistortionModel::kH36M, xy_distorted);
    case DistortionModel::kFisheye:
      return UndistortFisheye(dist, xy_distorted);
  }
  return xy_distorted;
}

// K is assumed upper triangular with K(2,:) = (0, 0, 1) (checked by Validate()), so its inverse
// is applied by back substitution instead of a general 3x3 solve; the skew K(0,1) is honoured.
Eigen::Vector2d Camera::PixelToNormalized(const Eigen::Vector2d& uv_px) const {
  const double y = (uv_px.y() - K(1, 2)) / K(1, 1);
  const double x = (uv_px.x() - K(0, 2) - K(0, 1) * y) / K(0, 0);
  return UndistortNormalized(Eigen::Vector2d(x, y));
}

Eigen::Vector2d Camera::UndistortPixel(const Eigen::Vector2d& uv_px) const {
  const Eigen::Vector2d xy = PixelToNormalized(uv_px);
  return Eigen::Vector2d(K(0, 0) * xy.x() + K(0, 1) * xy.y() + K(0, 2), K(1, 1) * xy.y() + K(1, 2));
}

bool Camera::Project(const Eigen::Vector3d& point_in_world, Eigen::Vector2d* uv_px) const {
  const Eigen::Vector3d p = R * point_in_world + t;
  // z == 0 has no projection; leave the output untouched rather than writing inf/NaN.
  if (p.z() == 0.0) return false;
  const Eigen::Vector2d xy = Distort(Eigen::Vector2d(p.x() / p.z(), p.y() / p.z()));
  *uv_px = Eigen::Vector2d(K(0, 0) * xy.x() + K(0, 1) * xy.y() + K(0, 2), K(1, 1) * xy.y() + K(1, 2));
  return p.z() > 0.0;
}

std::string Camera::Validate() const {
  std::ostringstream problems;
  int count = 0;
  auto report = [&](const std::string& what) { problems << (count++ == 0 ? "" : "; ") << what; };

  if (width <= 0 || height <= 0) {
    report("image size must be positive, got " + std::to_string(width) + "x" + std::to_string(height));
  }

  if (!R.allFinite()) {
    report("R has non-finite entries");
  } else {
    const double orthonormality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    const double det = R.determinant();
    if (orthonormality_error > 1e-6) {
      std::ostringstream s;
      s << "R is not orthonormal (max |R^T R - I| = " << orthonormality_error << ")";
      report(s.str());
    } else if (std::abs(det - 1.0) > 1e-6) {
      std::ostringstream s;
      s << "R is not a proper rotation (det = " << det << ", expected +1)";
      report(s.str());
    }
  }
  if (!t.allFinite()) report("t has non-finite entries");

  if (!K.allFinite()) {
    report("K has non-finite entries");
  } else {
    // The pixel <-> normalised conversions rely on the last row being exactly (0, 0, 1); a
    // tolerance only absorbs text round-off from the readers.
    const bool last_row_ok =
        std::abs(K(2, 0)) <= 1e-12 && std::abs(K(2, 1)) <= 1e-12 && std::abs(K(2, 2) - 1.0) <= 1e-12;
    const bool lower_ok = std::abs(K(1, 0)) <= 1e-12;
    if (!last_row_ok) {
      std::ostringstream s;
      s << "K last row must be (0, 0, 1), got (" << K(2, 0) << ", " << K(2, 1) << ", " << K(2, 2) << ")";
      report(s.str());
    }
    if (!lower_ok) report("K(1,0) must be 0 (K is upper triangular)");
    // With the structure above det(K) = fx * fy; a zero focal length makes K singular.
    if (!(std::abs(K(0, 0)) > 1e-12) || !(std::abs(K(1, 1)) > 1e-12)) {
      std::ostringstream s;
      s << "K is singular (fx = " << K(0, 0) << ", fy = " << K(1, 1) << ")";
      report(s.str());
    } else if (K(0, 0) < 0 || K(1, 1) < 0) {
      // A negative focal length mirrors the image: no calibration tool writes one.
      std::ostringstream s;
      s << "focal lengths must be positive (fx = " << K(0, 0) << ", fy = " << K(1, 1) << ")";
      report(s.str());
    }
  }

  for (size_t i = 0; i < dist.size(); ++i) {
    if (!std::isfinite(dist[i])) {
      report("distortion coefficient " + std::to_string(i) + " is not finite");
    }
  }

  if (count == 0) return {};
  std::ostringstream out;
  out << "camera '" << name << "' (lens " << DistortionModelName(model) << "): " << problems.str();
  return out.str();
}

}  // namespace rpt
