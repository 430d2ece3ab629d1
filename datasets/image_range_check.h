// SPDX-License-Identifier: MIT
// Do the detected joints of each camera lie in its calibrated image? Detectors place joints inside
// the image or a little beyond its edge; joints far outside, all in the top-left quarter, all
// within a pixel of the origin or at negative coordinates in numbers say the detections are in
// another pixel frame than the calibration's: a wrong image size, detections of a resized image,
// normalised coordinates (OpenPose --keypoint_scale 3 or 4, MediaPipe), the origin at the image
// centre. Counted frame by frame (a file, or a live stream line by line), said per camera at the end.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/poses.h"
#include "datasets/input_warnings.h"

namespace rpt {

class ImageRangeCheck {
 public:
  explicit ImageRangeCheck(const std::vector<Camera>& cameras);
  // The detections of camera `camera` in one frame. Allocates nothing.
  void Add(int camera, const Poses2D& view);
  // One warning per camera and finding, under `source`.
  void AddWarnings(const std::string& source, InputWarnings* warnings) const;
  long detected() const;  // joints with a score above 0, over every camera

 private:
  struct Counts {
    long detected = 0;  // joints with a score above 0
    long outside = 0;   // of those: beyond the image by more than kMaxOutsideShare of a side
    long negative = 0;  // of those: u < 0 or v < 0 by more than that share
    double farthest = 0, max_u = 0, max_v = 0, max_abs = 0;
  };
  std::vector<Camera> cameras_;
  std::vector<Counts> counts_;
};

}  // namespace rpt
