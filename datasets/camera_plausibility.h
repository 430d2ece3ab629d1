// SPDX-License-Identifier: MIT
// Cameras that are valid but implausible: further than 1 km from the world origin (a unit mix-up,
// millimetres read as metres, or a corrupt file: T = 1e300), with a lens distortion coefficient
// beyond +-100, with the principal point far from the image centre, or with a focal length whose
// field of view is over 170 or under 1 degree (millimetres for pixels); rigs whose cameras stand
// at the same spot or span more than 100 m. They are kept (a huge outdoor scene is not
// impossible) and counted per file as input warnings (datasets/input_warnings.h), so `rpt eval`,
// `inspect` and `rpt cameras show` print one line per file and kind.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

inline constexpr double kMaxPlausibleCameraDistanceM = 1000.0;  // |T| = |centre|, metres
inline constexpr double kMaxPlausibleDistortion = 100.0;        // any coefficient, in magnitude
// |cx - width / 2| / width and |cy - height / 2| / height (real lenses: a few per cent).
inline constexpr double kMaxPlausiblePrincipalOffset = 0.25;
// The horizontal field of view 2 atan(width / 2 fx): real lenses 5-120 degrees (fisheyes as
// pinholes about 115); a focal length in millimetres gives nearly 180.
inline constexpr double kMaxPlausibleFieldOfViewDeg = 170.0;
inline constexpr double kMinPlausibleFieldOfViewDeg = 1.0;
inline constexpr double kMinPlausibleCameraSeparationM = 0.01;  // between two camera centres
// Between the two farthest camera centres: an indoor capture spans 3-20 m, a stadium ~100 m;
// millimetres read as metres make thousands.
inline constexpr double kMaxPlausibleRigSpanM = 100.0;

// Counts `camera` under `source` when its centre, a distortion coefficient or its principal point
// is beyond the bounds above ("cameras more than 1 km from the origin (check the units of T)",
// "cameras with a distortion coefficient beyond +-100", "cameras with the principal point more
// than a quarter of the image from its centre"); does nothing when `warnings` is null.
void CountImplausibleCamera(const Camera& camera, const std::string& source, InputWarnings* warnings);

// Counts, under `source`, each pair of cameras whose centres are less than 1 cm apart ("camera
// pairs at the same spot (centres less than 1 cm apart)") and a rig spanning more than 100 m
// ("camera rigs spanning more than 100 m (millimetres read as metres? check the units)"); does
// nothing when `warnings` is null.
void CountImplausibleRig(const std::vector<Camera>& cameras, const std::string& source, InputWarnings* warnings);

}  // namespace rpt
