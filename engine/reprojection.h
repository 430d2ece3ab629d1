// SPDX-License-Identifier: MIT
// The 3D result of one frame seen from each camera: every 3D person (the predictions, and the GT
// when given) projected into every view with the camera's lens model (Camera::Project), matched
// one-to-one to a 2D detection of that view, and per joint the pixel distance between the
// projection and the matched detection. The matching is the detector statistics' association
// (datasets/detector_stats/association.h): greedy by the mean joint distance in pixels, a pair
// needing a mean distance within `gate_relative` x the diagonal of the projected person's box.
// What `rpt render` draws; a pure function of one frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"

namespace rpt::engine {

// Per joint of a projected person.
enum class JointReprojection : int8_t {
  kMeasured,      // projected and present in the matched detection: error_px holds the distance
  kMissing3D,     // the 3D joint is missing (score at or below the person's minimum score, or not finite)
  kBehindCamera,  // the 3D joint is behind the camera (no pixel)
  kNotDetected,   // projected, but no detection matched the person, the detection misses the joint
                  // (score 0), or the detector does not report this joint at all
};

// One 3D person in one camera.
struct ReprojectedPerson {
  int person_idx = -1;                    // index into the frame's Poses3D
  int track_id = -1;                      // Poses3D::track_ids; -1 for GT and untracked predictions
  Eigen::Matrix2Xd uv_px;                 // per 3D joint: distorted image pixel; set unless kMissing3D / kBehindCamera
  std::vector<JointReprojection> status;  // per 3D joint
  std::vector<double> error_px;           // per 3D joint: |projection - detection|; NaN unless kMeasured
  int detection_idx = -1;                 // the matched detection of this view, or -1
  int num_measured = 0;                   // joints with status kMeasured
  double mean_error_px = 0;               // mean of error_px over the measured joints; NaN when none
  bool in_image = false;                  // at least one projected joint lies inside the image
};

// One camera.
struct ViewReprojection {
  std::vector<ReprojectedPerson> predictions;  // one per predicted person, in Poses3D order
  std::vector<ReprojectedPerson> gt;           // one per GT person; empty when no GT was given
  std::vector<int> prediction_of_detection;    // per detection: the matched prediction (person_idx) or -1
  std::vector<int> gt_of_detection;            // per detection: the matched GT person or -1 (all -1 without GT)
};

// The mean reprojection error of a view: over every measured joint of its predictions (not the
// mean of the persons' means). `rpt render`'s legend and report.html's caption both show it.
struct ViewError {
  double mean_px = 0;  // NaN when no joint was measured
  long joints = 0;
};
ViewError MeanPredictionError(const ViewReprojection& view);

struct ReprojectionOptions {
  double gate_relative = 0.5;         // a match needs a mean joint distance <= this x the projected box diagonal
  int min_common_joints = 2;          // joints present in both the projection and the detection
  double prediction_min_score = 0.0;  // predicted joints with a score above this are present
  double gt_min_score = 0.1;          // GT joints with a score (visibility) above this are present (as the metrics)
};

// The 3D persons of one frame with their joint names.
struct PersonsWithJoints {
  const Poses3D* persons = nullptr;  // nullptr = none (e.g. no GT)
  const JointNames* joints = nullptr;
};

// One ViewReprojection per camera. `views` holds the detections per camera (joints in the order
// of `detection_joints`; may be shorter than `cameras` or empty: those cameras have no
// detections). 3D joints are paired with detection joints by name, so the 3D joint sets may
// differ from the detector's (derived joints such as hip_middle, a dataset's GT joints). The
// predictions and GT are matched to the detections independently.
std::vector<ViewReprojection> ReprojectFrame(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                                             const JointNames& detection_joints, const PersonsWithJoints& predictions,
                                             const PersonsWithJoints& gt, const ReprojectionOptions& options = {});

}  // namespace rpt::engine
