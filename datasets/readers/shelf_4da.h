// SPDX-License-Identifier: MIT
// Shelf as bundled by 4D-Association (Zhang et al., CVPR 2020, data/shelf/ of
// github.com/zhangyux15/4d_association): 301 frames x 5 cameras with real OpenPose BODY_25
// detections, time-aligned with a 3D ground truth.
//
//   <root>/calibration.json        cameras (fourda_calibration.h)
//   <root>/gt.txt                  ground truth, SHELF15 joints in metres (fourda_text.h)
//   <root>/detection/<camera>.txt  OpenPose candidates and PAF scores per camera (fourda_text.h)
//
// Cameras: named by their json id ("0".."4", as the regular Shelf reader); the world frame is
// the one of VoxelPose's calibration_shelf.json (same R, t = -R T / 1000; checked by the tests),
// so the room is ShelfRoom(). Rotations are re-orthonormalised and counted in
// Sequence::warnings.
//
// Ground truth (Shelf4daJoints()): the Shelf-14 joints named as ShelfCampusJoints(), the
// file's 15th joint (pelvis = mean of the hips) as hip_middle, then a derived nose from the head
// segment as in the Shelf reader (param nose_proxy). Score = the file's validity row (1 here).
// Track id = the file's identity (0-3). Frames without persons stay, with no ground truth.
//
// Frames: the 0-based index in the files; id "shelf4da_000000"; timestamp = index / 25 (the
// Shelf reader's rate). The files are assumed to be Shelf images 300-600, which nothing in the
// origin states; the index is therefore not renamed to a Shelf image number.
//
// Detections (detections=openpose): the candidates of the selected frames are packed when the
// source opens (PafCandidateStore, frame by frame); per camera and frame a PafAssociator
// (openpose_paf_association.h) assembles the BODY_25 candidates into persons, timed per frame
// (SequenceFrame::paf_grouping_us, the step table's "paf_grouping (reader)"), which become
// COCO-17 (CocoBodyJoints(); neck, mid-hip and feet dropped; a person without any COCO joint is
// dropped) with the candidate score as confidence. x, y are stored normalised: pixels =
// x * (width - 1), y * (height - 1), as 4D-Association does.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/readers/openpose_body25.h"
#include "datasets/readers/openpose_paf_association.h"
#include "datasets/readers/shelf_campus.h"
#include "datasets/sequence.h"

namespace rpt {

// ankle_right, knee_right, hip_right, hip_left, knee_left, ankle_left, wrist_right, elbow_right,
// shoulder_right, shoulder_left, elbow_left, wrist_left, head_bottom, head_top, hip_middle, nose.
const JointNames& Shelf4daJoints();

// Params:
//   frames         frame selection (ParseFrameRanges syntax) or "all" (default, 0-300).
//   detections     openpose (default): assemble the detection files; none: ground truth only.
//   nose_proxy     center (default) | top | bottom, as the Shelf reader.
//   min_paf_score  PafAssociationOptions::min_paf_score (default 0.05).
//   min_joints     PafAssociationOptions::min_joints, BODY_25 joints (default 5).
// Throws ConfigError for malformed params (and for detections=none without the ground truth),
// InputError for missing or malformed files (naming file, line and token), frames outside the
// files and detection files whose frame count differs from gt.txt (or, without it, from the
// first detection file).
enum class Shelf4daDetections { kOpenPose, kNone };
template <>
struct EnumNames<Shelf4daDetections> {
  static constexpr std::array<std::pair<Shelf4daDetections, std::string_view>, 2> values = {
      {{Shelf4daDetections::kOpenPose, "openpose"}, {Shelf4daDetections::kNone, "none"}}};
};

struct Shelf4daParams {
  std::string frames = "all";  // "all" or ParseFrameRanges syntax
  Shelf4daDetections detections = Shelf4daDetections::kOpenPose;
  HeadNoseProxy nose_proxy = HeadNoseProxy::kCenter;
  double min_paf_score = PafAssociationOptions{}.min_paf_score;
  int min_joints = PafAssociationOptions{}.min_joints;
};

template <class Visitor, OptionsOf<Shelf4daParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("frames", o.frames, OptionSpec{.help = "frame indices in the files, e.g. 0-300 or 0-300:10 (all = every frame)"});
  v("detections", o.detections, OptionSpec{.help = "openpose = assemble detection/<camera>.txt into persons"});
  v("nose_proxy", o.nose_proxy, OptionSpec{.help = "GT point named nose: center (mean of head_bottom, head_top), top or bottom"});
  v("min_paf_score", o.min_paf_score,
    OptionSpec{.help = "PAF association: ignore links with a lower PAF score (file values)", .min = 0});
  v("min_joints", o.min_joints,
    OptionSpec{.help = "PAF association: drop persons with fewer BODY_25 joints", .min = 2, .max = kBody25Joints});
}

DatasetInfo Shelf4daInfo();
// One source "shelf-4da": calibration.json, gt.txt and the detection files are read when it opens
// (every file and frame-count error shows there); each frame's persons are converted and its views
// assembled when it is pulled. Without the ground truth (DatasetRequest::ground_truth false)
// gt.txt is not read: the frames are those of the detection files, with no persons.
std::vector<std::unique_ptr<FrameSource>> OpenShelf4da(const DatasetRequest& request);

}  // namespace rpt
