// SPDX-License-Identifier: MIT
// EgoHumans reader (dataset name "egohumans"): the static exo (GoPro) cameras of each sequence and
// the triangulated COCO-17 ground truth of the Aria wearers, one Sequence per sequence directory.
//
// Layout (egohumans assets/DOWNLOAD.md), root = data/ (or one <big_seq>, or one sequence dir):
//   <big_seq>/<seq>/colmap/workplace/{cameras.txt, images.txt, colmap_from_aria_transforms.pkl, camXX.npy}
//   <big_seq>/<seq>/processed_data/{poses3d,refine_poses3d,fit_poses3d}/%05d.npy   dict aria name -> (17, 4)
//   <big_seq>/<seq>/processed_data/poses2d/<camXX>/rgb/%05d.npy                    list of dicts (keypoints 133 x 3)
//
// Cameras: exo = COLMAP cameras whose size is not 1408x1408, named by the first image using them
// ("camXX/%05d.jpg"), OPENCV_FISHEYE -> DistortionModel::kFisheye. Extrinsics: COLMAP image pose
// (world(colmap) -> camera, quaternion + t) of the camera's image with the time stamp nearest to the
// first selected frame, or the manual 4x4 camXX.npy when present, composed with
// colmap_from_aria[anchor] (aria -> colmap, possibly with scale) so that the world is the anchor
// Aria frame of the GT (metres). GT: aria name -> person (track id = its number, aria01 -> 1),
// joint score = the file's valid flag (0/1), CocoBodyJoints() names.
//
// Frame ids: "egohumans_<big_seq>_<seq>_<time stamp>" with the time stamp exactly as in the file
// names (5 digits, starting at 1), e.g. "egohumans_01_tagging_001_tagging_00001". Sequence names:
// "egohumans/<big_seq>/<seq>". Timestamps: (time stamp - 1) / fps.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_params.h"
#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

enum class EgohumansGt { kPoses3d, kRefinePoses3d, kFitPoses3d };
template <>
struct EnumNames<EgohumansGt> {
  static constexpr std::array<std::pair<EgohumansGt, std::string_view>, 3> values = {
      {{EgohumansGt::kPoses3d, "poses3d"}, {EgohumansGt::kRefinePoses3d, "refine_poses3d"}, {EgohumansGt::kFitPoses3d, "fit_poses3d"}}};
};
enum class EgohumansDetections { kNone, kCache };
template <>
struct EnumNames<EgohumansDetections> {
  static constexpr std::array<std::pair<EgohumansDetections, std::string_view>, 2> values = {
      {{EgohumansDetections::kNone, "none"}, {EgohumansDetections::kCache, "cache"}}};
};

struct EgohumansParams {
  ParamList sequences;  // empty = all under root
  ParamList cameras;    // empty = all exo cameras
  std::string anchor = "aria01";
  EgohumansGt gt = EgohumansGt::kPoses3d;
  EgohumansDetections detections = EgohumansDetections::kNone;
  int every = 1;
  int max_frames = 0;
  double fps = 20;
};

template <class Visitor, OptionsOf<EgohumansParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("sequences", o.sequences, OptionSpec{.help = "<big_seq>/<seq> (or <seq>, or <big_seq>); empty = all under root"});
  v("cameras", o.cameras, OptionSpec{.help = "exo cameras (camXX); empty = all"});
  v("anchor", o.anchor, OptionSpec{.help = "Aria camera whose frame is the GT world (CALIBRATION.ANCHOR_EGO_CAMERA)"});
  v("gt", o.gt, OptionSpec{.help = "ground-truth folder"});
  v("detections", o.detections, OptionSpec{.help = "cache = processed_data/poses2d (COCO-WholeBody)"});
  v("every", o.every, OptionSpec{.help = "keep every n-th ground-truth time stamp", .min = 1});
  v("max_frames", o.max_frames, OptionSpec{.help = "at most this many frames per sequence (0 = all)", .min = 0});
  v("fps", o.fps, OptionSpec{.help = "frame rate used for timestamps (time stamp - 1) / fps", .unit = "Hz", .min = 0, .min_exclusive = true});
}

DatasetInfo EgohumansInfo();
// One source per selected sequence: cameras and the ground-truth time stamps are read when it
// opens; per frame pulled, its GT file and, with param detections=cache, the 2D cache
// processed_data/poses2d/<cam>/rgb/%05d.npy (CocoWholeBodyJoints()). Cache scores in (1, 1.5] are
// clamped to 1 and counted in the source's warnings (one line per sequence's poses2d folder);
// negative scores or scores above 1.5 are errors naming the file and joint. The frames are the
// ground-truth time stamps: without the ground truth (DatasetRequest::ground_truth false) a
// ConfigError.
std::vector<std::unique_ptr<FrameSource>> OpenEgohumans(const DatasetRequest& request);

}  // namespace rpt
