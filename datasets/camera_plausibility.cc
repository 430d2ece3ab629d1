// SPDX-License-Identifier: MIT
#include "datasets/camera_plausibility.h"

#include <algorithm>
#include <cmath>

namespace rpt {

void CountImplausibleCamera(const Camera& camera, const std::string& source, InputWarnings* warnings) {
  if (warnings == nullptr) return;
  const double distance = camera.t.stableNorm();  // = |centre| (R is a rotation); no overflow for T = 1e300
  if (!(distance <= kMaxPlausibleCameraDistanceM)) {
    warnings->Add(source, "cameras more than 1 km from the origin (check the units of T)", "max |T| in m", distance);
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
  if (!(span <= kMaxPlausibleRigSpanM)) {
    warnings->Add(source, "camera rigs spanning more than 100 m (millimetres read as metres? check the units)",
                  "span in m", span);
  }
}

}  // namespace rpt
