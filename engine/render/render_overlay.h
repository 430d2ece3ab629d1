// SPDX-License-Identifier: MIT
// One camera's overlay for `rpt render`: the 2D detections against the reprojected 3D result
// (engine/reprojection.h), drawn with OpenCV onto the camera's image or a blank canvas of its size.
//
// Drawing conventions (the legend in the image repeats them):
//  * reprojected 3D persons: thick limbs and filled dots, one colour per track id (per person
//    when untracked), labelled with the track id and the mean reprojection error in pixels;
//  * 2D detections: thin limbs and crosses, in the colour of the 3D person they were matched to,
//    grey when unmatched; a thin line joins each measured joint to its projection (the error);
//  * reprojected ground truth (optional): thin black limbs and small squares;
//  * the legend in the corner whose box holds the fewest drawn points and labels (top left of equals).
// Limbs are those of core/joints.h (LimbsFor) that exist in each joint set.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "engine/reprojection.h"
#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"

namespace rpt::engine {

struct OverlayInput {
  const Camera* camera = nullptr;
  const Poses2D* detections = nullptr;  // this view's detections; nullptr = none
  const JointNames* detection_joints = nullptr;
  const ViewReprojection* reprojection = nullptr;
  const JointNames* prediction_joints = nullptr;
  const JointNames* gt_joints = nullptr;  // nullptr = the GT is not drawn
  std::vector<std::string> title;         // the legend's title, e.g. {"shelf", "camera Camera0", "frame 300"}: one
                                          // line where it fits, else a line each, cut in the middle to fit
};

// The colour (BGR) of a reprojected person: by track id when it has one, else by its index.
cv::Scalar PersonColour(int track_id, int person_idx);

// White canvas of the camera's image size (BGR, 8 bit).
cv::Mat BlankCanvas(const Camera& camera);

// Draws the overlay and the legend onto `canvas` (BGR, 8 bit, the camera's image size).
void DrawOverlay(const OverlayInput& input, cv::Mat* canvas);

}  // namespace rpt::engine
