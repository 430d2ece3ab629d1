// SPDX-License-Identifier: MIT
// MVOR (Srivastav et al., "MVOR: A Multi-view RGB-D Operating Room Dataset for 2D and 3D Human
// Pose Estimation", MICCAI-LABELS 2018), read from the layout of its repository:
//
//   <root>/annotations/camma_mvor_2018.json      cameras, 2D and 3D labels (or <root>/camma_mvor_2018.json)
//   <root>/detections_results/openpose_kps.json  the shipped OpenPose detections (or <root>/openpose_kps.json)
//
// camma_mvor_2018.json: `multiview_images` lists the 732 multi-view frames (3 images each, day
// 1-4, 640x480); `annotations3D` the 1061 3D persons, keyed by the three image ids joined with
// "_", 12 points x [x, y, z, flag] in millimetres in the frame of camera 1 (whatever
// `ref_camera` says); `cameras_info.camParams` the intrinsics (focal length, principal point,
// 5 distortion numbers) and `extrinsics[i]`, 4x4 maps from camera-i to camera-1 coordinates
// (mm), plus `firstCamToRoomRef`, camera 1 -> room (mm).
//
// World frame: the room frame in metres, shifted up by 1 m so that the floor is near z = 0 (the
// room frame's origin is about 1 m above the floor), z up. Cameras: cam1, cam2, cam3.
// Distortion: ignored by default. Projecting the 3D labels into the 2D labels fits best without
// it (median 7.7 / 8.9 / 7.9 px for cam1-3) and with the 5 numbers read as k1, k2, k3, p1, p2 it
// is slightly worse (8.7 / 9.0 / 9.1 px); read in OpenCV order it is far off. The official
// visualiser ignores it too. `distortion=file` applies it as k1, k2, k3, p1, p2.
//
// GT joints (MvorJoints()): head, shoulder_middle (MVOR's neck), shoulder_left,
// shoulder_right, hip_left, hip_right, elbow_left, elbow_right, wrist_left, wrist_right,
// hand_left, hand_right (points 10 and 11: undocumented, 5-8 cm from the wrists), then "nose",
// a copy of the head (the RPT authors score the predicted nose against MVOR's head).
// Evaluated joints (Sequence::evaluated_joints): the 8 arm and torso joints, or with
// evaluated=paper also the nose (the head).
//
// 2D labels (`annotations`: per image, 10 points with COCO visibility flags 0 not labelled /
// 1 occluded / 2 visible, and a box; person_id -1 for persons labelled by a box only) become
// SequenceFrame::labels_2d, linked to the 3D person with the same person_id (the nose takes the
// head's flag, the hands are never labelled). Only the detector statistics use them.
//
// One sequence per day ("mvor/day1" ...), frames in file order with ids
// "mvor_day<day>_<frame, 6 digits>" (the convention of ReadCocoDetections' MVOR mapping) and
// timestamps from the images' `date_captured` (seconds since the day's first frame): MVOR's
// frames are about 75 s apart, so nothing carries over from one frame to the next.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

const JointNames& MvorJoints();

// Params:
//   days        days to read, e.g. "1,3" (default "1,2,3,4")
//   detections  openpose (default: the shipped openpose_kps.json) | none
//   distortion  none (default) | file (the file's 5 numbers as k1, k2, k3, p1, p2)
//   evaluated   arms_torso (default: shoulders, elbows, wrists, hips) | paper (plus nose = head)
enum class MvorDetections { kOpenPose, kNone };
enum class MvorDistortion { kNone, kFile };
enum class MvorEvaluated { kArmsTorso, kPaper };
template <>
struct EnumNames<MvorDetections> {
  static constexpr std::array<std::pair<MvorDetections, std::string_view>, 2> values = {
      {{MvorDetections::kOpenPose, "openpose"}, {MvorDetections::kNone, "none"}}};
};
template <>
struct EnumNames<MvorDistortion> {
  static constexpr std::array<std::pair<MvorDistortion, std::string_view>, 2> values = {
      {{MvorDistortion::kNone, "none"}, {MvorDistortion::kFile, "file"}}};
};
template <>
struct EnumNames<MvorEvaluated> {
  static constexpr std::array<std::pair<MvorEvaluated, std::string_view>, 2> values = {
      {{MvorEvaluated::kArmsTorso, "arms_torso"}, {MvorEvaluated::kPaper, "paper"}}};
};

struct MvorParams {
  std::string days = "1,2,3,4";
  MvorDetections detections = MvorDetections::kOpenPose;
  MvorDistortion distortion = MvorDistortion::kNone;
  MvorEvaluated evaluated = MvorEvaluated::kArmsTorso;
};

template <class Visitor, OptionsOf<MvorParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("days", o.days, OptionSpec{.help = "days to read, comma-separated 1-4 (one sequence each)"});
  v("detections", o.detections, OptionSpec{.help = "openpose = the OpenPose detections shipped with MVOR"});
  v("distortion", o.distortion,
    OptionSpec{.help = "none fits the 2D labels best; file applies the 5 numbers as k1 k2 k3 p1 p2"});
  v("evaluated", o.evaluated,
    OptionSpec{.help = "arms_torso = shoulders, elbows, wrists, hips; paper = plus nose (MVOR's head)"});
}

DatasetInfo MvorInfo();
// One source per day. The annotation file (and the detections) are parsed and indexed when they
// open; each frame's persons, 2D labels and views are converted when it is pulled. Without the
// ground truth (DatasetRequest::ground_truth false) the annotation file still gives the cameras,
// frames and times, but no persons and no 2D labels are read (detections=openpose needed).
std::vector<std::unique_ptr<FrameSource>> OpenMvor(const DatasetRequest& request);

}  // namespace rpt
