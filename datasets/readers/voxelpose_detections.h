// SPDX-License-Identifier: MIT
// VoxelPose 2D detection caches for Shelf and Campus: pred_shelf_maskrcnn_hrnet_coco.pkl,
// pred_campus_maskrcnn_hrnet_coco.pkl (Mask R-CNN boxes + HRNet-W48 COCO keypoints).
//
// File format (VoxelPose lib/dataset/shelf.py, campus.py): a pickled
// collections.defaultdict mapping the key "{camera}_{frame}" (camera id of the calibration json,
// absolute image index) to a list of detections, each a dict {"pred": 17x3 float array} with
// rows in COCO-17 order and columns (x, y, score): pixels of the original (distorted) image and
// the heatmap confidence. No box and no person score. An empty list = nothing detected.
#pragma once

#include <filesystem>
#include <string>

#include "datasets/detections.h"
#include "datasets/sequence.h"

namespace rpt {

// Reads the cache for the frames and cameras of `sequence`, whose frame ids must have the form
// "<dataset_prefix>_<frame, 6 digits>" (e.g. prefix "shelf" -> "shelf_000300"). The result has
// joints CocoBodyJoints() and one FrameDetections per sequence frame that has at least one key
// (with an empty Poses2D for an empty list), cameras in sequence order. Keys of frames that are
// not in the sequence are ignored (the full caches cover every image); keys of cameras that are
// not in it are ignored and counted in Detections::warnings as unused input (the mmpose Campus
// subset lists cameras 3 and 4 that Campus does not have). Scores in (1, 1.5] are clamped to 1
// and counted in Detections::warnings. Throws InputError naming the file and the key for a key
// that is not "<camera>_<frame>", a value that is not a list of {"pred": 17x3 array}, non-finite
// numbers, and negative scores or scores above 1.5.
Detections ReadVoxelPoseDetections(const std::filesystem::path& path, const Sequence& sequence,
                                   const std::string& dataset_prefix);

}  // namespace rpt
