// SPDX-License-Identifier: MIT
#include "datasets/camera_plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "core/printable_text.h"

namespace rpt {

void CountImplausibleCamera(const Camera& camera, const std::string& source, InputWarnings* warnings,
                            const std::string& extrinsics_source) {
  if (warnings == nullptr) return;
  const double distance = camera.t.stableNorm();  // = |centre| (R is a rotation); no overflow for T = 1e300
  if (!(distance <= kMaxPlausibleCameraDistanceM)) {
    warnings->Add(extrinsics_source.empty() ? source : extrinsics_source,
                  "cameras more than 1 km from the origin (check the units of T)", "max |T| in m", distance);
  }
  double worst = 0;
  for (const double k : camera.dist) worst = std::max(worst, std::abs(k));
  if (!(worst <= kMaxPlausibleDistortion)) {
    warnings->Add(source, "cameras with a distortion coefficient beyond +-100", "max |coefficient|", worst);
  }
  if (camera.width > 0) {
    // The horizontal field of view a pinhole of this focal length sees over the image width: a
    // focal length in millimetres (4.5 "px" over 1920 px: 179.5 degrees) or a corrupt value
    // (1e12 px: no angle at all) is far outside what lenses give (fisheyes included: their focal
    // length is about width / pi).
    const double fov_deg = 2.0 * std::atan(0.5 * camera.width / camera.K(0, 0)) * 180.0 / std::acos(-1.0);
    if (!(fov_deg <= kMaxPlausibleFieldOfViewDeg)) {
      warnings->Add(source, "cameras whose focal length gives a field of view over 170 degrees (in millimetres, not pixels?)",
                    "widest field of view in degrees", fov_deg);
    } else if (!(fov_deg >= kMinPlausibleFieldOfViewDeg)) {
      warnings->Add(source, "cameras whose focal length gives a field of view under 1 degree (check the focal length)",
                    "largest focal length / image width", camera.K(0, 0) / camera.width);
    }
  }
  if (camera.width > 0 && camera.height > 0) {
    const double offset = std::max(std::abs(camera.K(0, 2) - 0.5 * camera.width) / camera.width,
                                   std::abs(camera.K(1, 2) - 0.5 * camera.height) / camera.height);
    if (!(offset <= kMaxPlausiblePrincipalOffset)) {
      warnings->Add(source, "cameras with the principal point more than a quarter of the image from its centre",
                    "max offset / image side", offset);
    }
  }
}

namespace {

// The angle in degrees between the rays of cameras a and b to the point where their views cross
// (midway between the closest points of their optical axes, in front of both); for axes nearly
// parallel, the point kNominalViewDepthM ahead of them. None when their views do not cross in front
// of them (cameras looking apart): they share no view to compare.
std::optional<double> CrossingAngleDeg(const Camera& a, const Camera& b) {
  constexpr double kNominalViewDepthM = 4.0;
  const Eigen::Vector3d ca = a.Center(), cb = b.Center();
  const Eigen::Vector3d da = a.R.row(2).transpose(), db = b.R.row(2).transpose();  // optical axes in the world
  const Eigen::Vector3d w0 = ca - cb;
  const double cos_axes = da.dot(db), d = da.dot(w0), e = db.dot(w0);
  const double denom = 1.0 - cos_axes * cos_axes;
  Eigen::Vector3d point;
  const double s = denom > 1e-6 ? (cos_axes * e - d) / denom : -1.0;
  const double u = denom > 1e-6 ? (e - cos_axes * d) / denom : -1.0;
  if (s > 0 && u > 0) {  // at any depth: the angle does not change with the rig's units
    point = 0.5 * (ca + s * da + cb + u * db);
  } else {
    const Eigen::Vector3d ahead = da + db;
    if (ahead.norm() < 1.0 || cos_axes < 0) return std::nullopt;  // looking apart (or at each other from afar)
    point = 0.5 * (ca + cb) + kNominalViewDepthM * ahead.normalized();
  }
  const Eigen::Vector3d ra = point - ca, rb = point - cb;
  if (ra.dot(da) <= 0 || rb.dot(db) <= 0) return std::nullopt;
  const double cosine = std::clamp(ra.normalized().dot(rb.normalized()), -1.0, 1.0);
  return std::acos(cosine) * 180.0 / M_PI;
}

}  // namespace

std::vector<double> WidestCrossingAnglesDeg(const std::vector<Camera>& cameras) {
  std::vector<double> widest(cameras.size(), -1.0);
  for (std::size_t a = 0; a < cameras.size(); ++a) {
    for (std::size_t b = a + 1; b < cameras.size(); ++b) {
      const std::optional<double> angle = CrossingAngleDeg(cameras[a], cameras[b]);
      if (!angle) continue;
      // Facing cameras (rays nearly opposite) are not folded in: only people on the line between
      // them are poorly fixed (2 facing cameras: PCP 78.6 on a generated scene, 2 at random azimuths 67.4).
      widest[a] = std::max(widest[a], *angle);
      widest[b] = std::max(widest[b], *angle);
    }
  }
  return widest;
}

void CountImplausibleRig(const std::vector<Camera>& cameras, const std::string& source, InputWarnings* warnings) {
  if (warnings == nullptr) return;
  double span = 0;
  for (std::size_t a = 0; a < cameras.size(); ++a) {
    for (std::size_t b = a + 1; b < cameras.size(); ++b) {
      const double distance = (cameras[a].Center() - cameras[b].Center()).stableNorm();
      if (distance < kMinPlausibleCameraSeparationM) {
        warnings->Add(source, "camera pairs at the same spot (centres less than 1 cm apart)", "", 0);
      }
      span = std::max(span, distance);
    }
  }
  // Cameras whose every partner sees the scene from nearly the same direction: the depth along
  // their view rests on a few degrees (a stereo bar, cameras side by side).
  const std::vector<double> widest = WidestCrossingAnglesDeg(cameras);
  std::string narrow;
  long count = 0;
  double narrowest = 90;
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    if (widest[c] < 0 || widest[c] >= kMinPlausibleViewAngleDeg) continue;
    if (++count <= 4) narrow += (narrow.empty() ? "" : ", ") + QuoteName(cameras[c].name);
    narrowest = std::min(narrowest, widest[c]);
  }
  if (count > 0) {
    char angle[32];
    std::snprintf(angle, sizeof(angle), "%.1f", narrowest);
    warnings->Add(source,
                  "cameras that see the scene from nearly the same direction as every other camera (" + narrow +
                      (count > 4 ? ", ..." : "") + "; " + angle +
                      " degrees at the least between their rays where their views cross): depth along their view "
                      "is poorly fixed; a camera placed 30 degrees or more around the scene from them fixes it",
                  "", 0, count);
  }
  if (!(span <= kMaxPlausibleRigSpanM)) {
    warnings->Add(source, "camera rigs spanning more than 100 m (millimetres read as metres? check the units)",
                  "span in m", span);
  }
}

}  // namespace rpt
