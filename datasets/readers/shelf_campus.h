// SPDX-License-Identifier: MIT
// Shelf and Campus (Belagiannis et al., CVPR 2014), read from the folders VoxelPose uses:
//
//   <root>/calibration_shelf.json | calibration_campus.json   VoxelPose cameras (mm, see
//                                                           voxelpose_calibration.h)
//   <root>/actorsGT.mat                                     ground truth (MAT v5)
//   <root>/pred_shelf_maskrcnn_hrnet_coco.pkl | pred_campus_... (only with detections=voxelpose)
//
// actorsGT.mat: variable actor3D, a 1xP cell (one per actor); actor p is an Fx1 cell over all
// F frames of the recording; entry (p, f) is a 14x3 double matrix (metres, world frame, z up,
// joints in the Shelf-14 order below) or an empty array when actor p is not annotated in frame
// f. The GT person's track id is the actor index p (0-based); all 14 joints get score 1.
//
// GT joints (ShelfCampusJoints()): the 14 file joints renamed to core/joints.h style, then a
// derived "nose". The paper evaluates the predicted nose against the GT head; the GT head is a
// segment (Bottom-Head = top of the neck, Top-Head = crown), so `nose_proxy` picks the point:
//   center (default): mean of head_bottom and head_top;  top: head_top;  bottom: head_bottom.
// With it EvaluationJoints13() all exist in the GT.
//
// Frames: frame ids "shelf_000300" / "campus_000350" with the image index as number (0-based,
// image Camera*/img_000300.png, campus4-c*-00350.png); timestamp = frame / fps.
// Cameras: named by their json id ("0".."4" Shelf, "0".."2" Campus), 1032x776 / 360x288.
// Room (the capture volume in metres, z up): VoxelPose's MULTI_PERSON.SPACE_CENTER/SIZE of
// configs/{shelf,campus}/prn64_cpn80x80x20.yaml: Shelf centre (0.45, -0.32, 0.8), size
// (8, 8, 2); Campus centre (3, 4.5, 1), size (12, 12, 2). It bounds where a person's centre
// (root) can be, not the head.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

// ankle_right, knee_right, hip_right, hip_left, knee_left, ankle_left, wrist_right, elbow_right,
// shoulder_right, shoulder_left, elbow_left, wrist_left, head_bottom, head_top, nose.
const JointNames& ShelfCampusJoints();

// The Shelf capture volume above (world frame of calibration_shelf.json).
Room ShelfRoom();

// Params of both readers:
//   frames      frame selection (ParseFrameRanges syntax). Default Shelf "300-600" (VoxelPose,
//               301 frames; mvpose uses 300-599), Campus "350-470,650-750" (VoxelPose and mvpose).
//   actors      "all" (default) or a list of actor indices, e.g. "0,1,2" (VoxelPose's Shelf PCP
//               averages actors 0-2 only; the 4th Shelf actor is annotated but often ignored).
//   nose_proxy  center | top | bottom, see above.
//   detections  none (default) | voxelpose: attach the VoxelPose 2D cache from the root.
//   fps         frame rate for timestamps, default 25 (Campus: the EPFL recording rate; Shelf:
//               not documented by the authors, 25 assumed).
// Opens one source ("shelf" / "campus"): the calibration, actorsGT.mat and the cache are read and
// checked when it opens, and each frame is converted from them when it is pulled. Without the
// ground truth (DatasetRequest::ground_truth false) actorsGT.mat is not read: the frames are the
// `frames` selection with the cache's detections and no persons (detections=voxelpose needed).
// Throws ConfigError for malformed params and InputError for missing/malformed files and frames
// or actors outside actorsGT.mat (naming the frame/actor count).
// Which point of the head the GT joint "nose" is (Shelf, Campus and the 4D-Association Shelf
// annotate head_bottom and head_top only).
enum class HeadNoseProxy { kCenter, kTop, kBottom };
template <>
struct EnumNames<HeadNoseProxy> {
  static constexpr std::array<std::pair<HeadNoseProxy, std::string_view>, 3> values = {
      {{HeadNoseProxy::kCenter, "center"}, {HeadNoseProxy::kTop, "top"}, {HeadNoseProxy::kBottom, "bottom"}}};
};

enum class ShelfCampusDetections { kNone, kVoxelPose };
template <>
struct EnumNames<ShelfCampusDetections> {
  static constexpr std::array<std::pair<ShelfCampusDetections, std::string_view>, 2> values = {
      {{ShelfCampusDetections::kNone, "none"}, {ShelfCampusDetections::kVoxelPose, "voxelpose"}}};
};

// The parameters of "shelf" and "campus" (their default frames differ: ShelfInfo/CampusInfo).
struct ShelfCampusParams {
  std::string frames;          // ParseFrameRanges syntax
  std::string actors = "all";  // "all" or actor indices
  HeadNoseProxy nose_proxy = HeadNoseProxy::kCenter;
  ShelfCampusDetections detections = ShelfCampusDetections::kNone;
  double fps = 25;
};

template <class Visitor, OptionsOf<ShelfCampusParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("frames", o.frames, OptionSpec{.help = "frame selection, e.g. 300-600 or 350-470,650-750 or 0-3199:10"});
  v("actors", o.actors, OptionSpec{.help = "actor indices to load, e.g. 0,1,2 (all = every actor in actorsGT.mat)"});
  v("nose_proxy", o.nose_proxy, OptionSpec{.help = "GT point named nose: center (mean of head_bottom, head_top), top or bottom"});
  v("detections", o.detections, OptionSpec{.help = "voxelpose = load the VoxelPose 2D cache from the root"});
  v("fps", o.fps, OptionSpec{.help = "frame rate for timestamps (frame / fps)", .unit = "Hz", .min = 0, .min_exclusive = true});
}

DatasetInfo ShelfInfo();
std::vector<std::unique_ptr<FrameSource>> OpenShelf(const DatasetRequest& request);
DatasetInfo CampusInfo();
std::vector<std::unique_ptr<FrameSource>> OpenCampus(const DatasetRequest& request);

}  // namespace rpt
