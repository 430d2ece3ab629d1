// SPDX-License-Identifier: MIT
// The frames of a detections file on the cameras of a calibration: what `rpt triangulate --cameras
// FILE --detections FILE` reads when there are no labels (docs/own_data.md). One sequence, one
// frame per detection frame in the file's order, its views in the calibration's camera order;
// no ground truth.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/detections.h"
#include "datasets/frame_source.h"

namespace rpt {

struct DetectionFramesOptions {
  std::string name;  // the sequence's name
  // Frame rate of the detection frames. Where the file gives times (generic JSON's "time"), they
  // are the frames' times (a frame without one: unknown). Else frame i is at time i / fps, or, when every frame id ends
  // in a number, the numbers increase and most steps are 1, at (its number - the first frame's) / fps (frames the
  // file skips leave a gap in time). 0 = the times are unknown (NaN): nothing is carried from
  // frame to frame (no tracking, no smoothing), counted in one warning that says how to give the rate.
  double fps = 0;
};

// `cameras` from the calibration `calibration_file`, `detections` read from `detections_file`
// (both only named in messages). Every camera a detection frame names must be a calibration
// camera (matched by name): else InputError naming the detections file, the frame and the
// camera, listing the calibration's cameras; calibration cameras the detections never name get
// no persons. The detections' own warnings go into the source's warnings.
std::unique_ptr<FrameSource> OpenDetectionFrames(std::vector<Camera> cameras, Detections detections,
                                                 const DetectionFramesOptions& options,
                                                 const std::filesystem::path& calibration_file,
                                                 const std::filesystem::path& detections_file);

}  // namespace rpt
