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

#include <vector>

#include "datasets/dataset_request.h"
#include "datasets/detections.h"
#include "datasets/sequence.h"

namespace rpt {

DatasetInfo EgohumansInfo();
std::vector<Sequence> ReadEgohumans(const DatasetRequest& request);

// The 2D cache processed_data/poses2d/<cam>/rgb/%05d.npy of the selected sequences, frames and
// cameras as Detections (CocoWholeBodyJoints()). Scores in (1, 1.5] are clamped to 1 and counted
// in Detections::warnings (one line per sequence's poses2d folder); negative scores or scores
// above 1.5 are errors naming the file and joint. Same params as ReadEgohumans; frame ids match
// its frames.
Detections ReadEgohumansDetections(const DatasetRequest& request);

}  // namespace rpt
