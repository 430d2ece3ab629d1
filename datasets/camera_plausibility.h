// SPDX-License-Identifier: MIT
// Cameras that are valid but implausible: further than 1 km from the world origin (a unit mix-up,
// millimetres read as metres, or a corrupt file: T = 1e300) or with a lens distortion coefficient
// beyond +-100. They are kept (a huge outdoor scene is not impossible) and counted per file as
// input warnings (datasets/input_warnings.h), so `rpt eval` and `inspect` print one line per file.
#pragma once

#include <string>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

inline constexpr double kMaxPlausibleCameraDistanceM = 1000.0;  // |T| = |centre|, metres
inline constexpr double kMaxPlausibleDistortion = 100.0;        // any coefficient, in magnitude

// Counts `camera` under `source` when its centre or a distortion coefficient is beyond the bounds
// above ("cameras more than 1 km from the origin (check the units of T)", "cameras with a
// distortion coefficient beyond +-100"); does nothing when `warnings` is null.
void CountImplausibleCamera(const Camera& camera, const std::string& source, InputWarnings* warnings);

}  // namespace rpt
