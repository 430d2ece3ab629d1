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
}

}  // namespace rpt
