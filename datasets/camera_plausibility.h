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
// than a quarter of the image from its centre"); does nothing when `warnings` is null. The centre's
// count goes under `extrinsics_source` when given: the file of T where the intrinsics are another
// file (EasyMocap's extri.yml).
void CountImplausibleCamera(const Camera& camera, const std::string& source, InputWarnings* warnings,
                            const std::string& extrinsics_source = "");

// Below this angle between two cameras' rays where their views cross (the widest over a camera's
// partners), the depth along its view rests on too little: a stereo bar 20 cm wide sees a point
// 4 m ahead from 2.9 degrees apart. Real rigs: 30 degrees and more (Shelf, Campus, Panoptic, MVOR).
inline constexpr double kMinPlausibleViewAngleDeg = 10.0;

// Per camera, the widest angle (degrees, 0-180) between its rays and another camera's to the
// point where their views cross
// (midway between the closest points of their optical axes; 4 m ahead for nearly parallel axes);
// -1 when no other camera's view crosses its view in front of both.
std::vector<double> WidestCrossingAnglesDeg(const std::vector<Camera>& cameras);

// Counts, under `source`, each pair of cameras whose centres are less than 1 cm apart ("camera
// pairs at the same spot (centres less than 1 cm apart)") and a rig spanning more than 100 m
// ("camera rigs spanning more than 100 m (millimetres read as metres? check the units)"), and the
// cameras whose widest crossing angle is below kMinPlausibleViewAngleDeg, named; does nothing when
// `warnings` is null.
void CountImplausibleRig(const std::vector<Camera>& cameras, const std::string& source, InputWarnings* warnings);

}  // namespace rpt
