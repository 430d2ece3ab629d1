// SPDX-License-Identifier: MIT
// Image sizes of cameras whose calibration file stores none (VoxelPose files, OpenCV files
// without image_width / image_height, EasyMocap files without H_ / W_).
#pragma once

#include <string>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt {

// Sets camera->width / height when they are 0: to `width` / `height` when given (> 0), else to
// twice the principal point (cx, cy) rounded, counted in `warnings` under `source` ("image sizes
// missing, taken as twice the principal point"). Throws InputError naming `where` when the
// principal point gives no size in [1, 1000000].
void CompleteImageSize(Camera* camera, int width, int height, const std::string& source, const std::string& where,
                       InputWarnings* warnings);

}  // namespace rpt
