// SPDX-License-Identifier: MIT
// Per camera, precomputed once when the Triangulator is built: the undistorted pinhole model and
// the pose (ViewGeometry, pipeline_types.h).
#pragma once

#include "core/camera.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

ViewGeometry MakeViewGeometry(const Camera& camera);

}  // namespace rpt
