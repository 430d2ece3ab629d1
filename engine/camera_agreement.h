// SPDX-License-Identifier: MIT
// Do a run's 3D persons agree with each camera's detections? Without ground truth this is the one
// check of a calibration against the detections: a person triangulated from several cameras is
// projected into every camera whose image it falls in and compared with that camera's nearest
// detection (the mean pixel distance over the joints both have, over the diagonal of the person's
// projected box). A camera whose detections rarely agree (a wrong calibration, two cameras swapped
// by name) is warned about: its persons were placed by the other cameras, and it adds phantoms.
//
// Measured (`rpt triangulate`, summary.json's camera_agreement): with the right cameras 68-89 % of
// the persons in view agree on MVOR (per day and camera), 93-99 % on Shelf-4DA, 96-98 % on a
// synthetic 5-camera scene; two cameras of that scene swapped by name agree 19 % and 26 %, the
// others 95-96 %.
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt::engine {

// A person counts when at least this many of its joints were triangulated from this frame's views.
inline constexpr int kMinAgreementJoints = 6;
// A person in view agrees with a camera when its nearest detection is within this share of the
// projected box's diagonal (mean over at least 3 shared joints).
inline constexpr double kAgreementDistance = 0.25;
// A camera is warned about with at least kMinAgreementPersons persons in view of which at most
// kMinAgreementShare agree.
inline constexpr long kMinAgreementPersons = 20;
inline constexpr double kMinAgreementShare = 0.5;
// A camera that detected someone in at least kMinAgreementPersons compared frames, while at least
// that many 3D persons were triangulated in them, is warned about when no more than this share of
// those persons falls in its image: its detections are of people it cannot be seeing where it is
// placed (the camera centre given where the world-to-camera t belongs turned two cameras of a
// 4-camera rig round: 3D persons 4 m off, none in their images). With right calibrations the least
// share of any camera was 86 % (persons_in_view / persons_while_detecting of summary.json's
// camera_agreement, `rpt triangulate`: MVOR 94 %, Shelf-4DA 90 %, synthetic ring of 5 cameras 98 %,
// random layouts of 3, 8 and 12 cameras 100, 86 and 93 %, 16 cameras with the hard detector 88 %).
inline constexpr double kMinInViewShare = 0.05;
// At most about this many frames of a sequence are compared (every n-th frame): the comparison is
// a few times the triangulation's cost for the frames it looks at.
inline constexpr long kAgreementFrames = 300;

struct CameraAgreement {
  std::string camera;
  // Persons whose projected box centre is inside the image, in front of it, in frames where the
  // camera has detections (a frame where it detected nobody, or has no data, says nothing about
  // its calibration).
  long in_view = 0;
  long agreeing = 0;   // of those: with a detection within kAgreementDistance
  long in_view_without_detections = 0;  // the same in frames where it detected nobody
  // Persons counted (kMinAgreementJoints) in the frames where it detected someone, in its view or not.
  long while_detecting = 0;
  long frames = 0;                  // frames compared where the camera has data (not Poses2D::unavailable)
  long frames_with_detections = 0;  // of those: with at least one detection of this camera
};

class CameraAgreementCheck {
 public:
  // `num_frames` < 0: unknown (every 10th frame is compared).
  CameraAgreementCheck(const SequenceHeader& header, const JointNames& output_joints, long num_frames);
  // Frame `index` (in order) and the persons triangulated from it.
  void Add(long index, const SequenceFrame& frame, const Poses3D& persons);
  const std::vector<CameraAgreement>& cameras() const { return cameras_; }

 private:
  const SequenceHeader& header_;
  std::vector<int> detection_joint_;  // per output joint: its detection joint, -1 = none
  long stride_ = 1;
  std::vector<CameraAgreement> cameras_;
  std::vector<Eigen::Vector2d> projected_;  // per output joint, reused
  std::vector<char> visible_;
};

// One warning line per camera whose detections rarely agree with the persons (see above).
std::vector<std::string> CameraAgreementWarnings(const std::string& sequence, const std::vector<CameraAgreement>& cameras);

}  // namespace rpt::engine
