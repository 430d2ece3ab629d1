// SPDX-License-Identifier: MIT
// Ground-truth persons projected into one camera, and their one-to-one association with the 2D
// detections of that view: the basis of the detector statistics (statistics.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "core/poses.h"

namespace rpt::detector_stats {

// One GT person in one camera, over a list of joints ("statistic joints").
struct ProjectedPerson {
  int gt_person = -1;
  Eigen::Matrix2Xd uv;              // px per joint (distorted image, Camera::Project); valid where present
  std::vector<char> present;        // the GT joint exists (score > 0.1) and is in front of the camera
  std::vector<char> in_image;       // present and inside the image
  int num_in_image = 0;
  bool truncated = false;           // a GT joint exists but is outside the image or behind the camera
  Eigen::Vector4d box = Eigen::Vector4d::Zero();  // x0 y0 x1 y1: box of the present joints, clipped to the image
  double diagonal = 0;              // px, diagonal of the clipped box
};

// Projects GT person `p` of `gt`; `gt_index` gives per statistic joint its GT joint (-1: none).
ProjectedPerson ProjectPerson(const Camera& camera, const Poses3D& gt, int p, const std::vector<int>& gt_index);

struct AssociationOptions {
  double gate_relative = 0.5;  // a pair needs a mean joint distance <= this x the GT box diagonal
  int min_common_joints = 2;   // joints present in both the projection and the detection
};

// Mean pixel distance between the projection and detection `d` of `view` over the joints both
// have (`det_index`: per statistic joint its detection joint, -1: none; score > 0 = reported);
// -1 when fewer than `min_common_joints` are comparable.
double MeanDistance(const ProjectedPerson& person, const Poses2D& view, int d, const std::vector<int>& det_index,
                    int min_common_joints);

struct Association {
  std::vector<int> detection_of_person;  // per projected person: detection index or -1
  std::vector<int> person_of_detection;  // per detection: index into the persons or -1
  std::vector<double> distance_px;       // per projected person: mean distance to its detection, -1 if none
};

// One-to-one, greedy by mean distance (smallest first), pairs beyond the gate never match.
Association Associate(const std::vector<ProjectedPerson>& persons, const Poses2D& view,
                      const std::vector<int>& det_index, const AssociationOptions& options);

}  // namespace rpt::detector_stats
