// SPDX-License-Identifier: MIT
// VoxelPose 2D detection caches for Shelf and Campus: pred_shelf_maskrcnn_hrnet_coco.pkl,
// pred_campus_maskrcnn_hrnet_coco.pkl (Mask R-CNN boxes + HRNet-W48 COCO keypoints).
//
// File format (VoxelPose lib/dataset/shelf.py, campus.py): a pickled
// collections.defaultdict mapping the key "{camera}_{frame}" (camera id of the calibration json,
// absolute image index) to a list of detections, each a dict {"pred": 17x3 float array} with
// rows in COCO-17 order and columns (x, y, score): pixels of the original (distorted) image and
// the heatmap confidence. No box and no person score. An empty list = nothing detected.
//
// Keys are checked when the file is opened: a key that is not "<camera>_<frame>" is an
// InputError naming the file and the key; keys of cameras the caller does not have are ignored
// and counted as unused input (the mmpose Campus subset lists cameras 3 and 4 that Campus does not
// have). A frame's detections are converted when asked for: a value that is not a list of
// {"pred": 17x3 array}, non-finite numbers, and negative scores or scores above 1.5 are
// InputErrors naming the file and the key; scores in (1, 1.5] are clamped to 1 and counted.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/poses.h"
#include "datasets/detections.h"
#include "datasets/input_warnings.h"
#include "datasets/io/py_value.h"

namespace rpt {

// The cache parsed once, its keys indexed by frame number and camera.
class VoxelPoseDetectionsFile {
 public:
  // `cameras`: the camera names of the calibration, in its order; empty = every camera named in
  // the file's keys (sorted).
  VoxelPoseDetectionsFile(const std::filesystem::path& path, std::vector<std::string> cameras);

  const std::string& source() const { return source_; }
  const std::vector<std::string>& cameras() const { return cameras_; }
  // The frame numbers with a key of at least one of cameras(), ascending.
  std::vector<long> frames() const;
  bool HasFrame(long frame) const { return keys_.count(frame) > 0; }
  // The detections of `frame`, one Poses2D (CocoBodyJoints()) per camera of cameras(): no person
  // where the file has no key. Corrections go to `warnings` under source().
  void ReadFrame(long frame, std::vector<Poses2D>* views, InputWarnings* warnings) const;
  // Only the cameras with a key for `frame`: their names and views (the generic Detections form).
  void ReadFrame(long frame, std::vector<std::string>* cameras, std::vector<Poses2D>* views,
                 InputWarnings* warnings) const;
  // The keys of cameras not in cameras() (unused input, counted under source()).
  const InputWarnings& warnings() const { return warnings_; }

 private:
  std::string source_;
  std::vector<std::string> cameras_;
  std::vector<std::pair<io::PyView, io::PyView>> items_;  // the file's (key, value) pairs
  std::map<long, std::vector<int>> keys_;                 // frame -> per camera the item index, -1 = none
  InputWarnings warnings_;
};

// What ReadVoxelPoseDetections needs besides the file: the cameras it is read for and how frame
// numbers become frame ids.
struct VoxelPoseDetectionsOptions {
  std::vector<std::string> cameras;  // as VoxelPoseDetectionsFile; empty = every camera of the file
  std::string frame_id_prefix;       // frame ids "<prefix>_<frame, 6 digits>", e.g. "shelf" -> "shelf_000300"
};

// Every frame of the cache as Detections: joints CocoBodyJoints(), one FrameDetections per frame
// number with a key (ascending; the cameras with a key, in camera order, an empty Poses2D for an
// empty list), frame ids "<frame_id_prefix>_<frame, 6 digits>". Throws ConfigError when the
// prefix is empty, and the InputErrors above.
Detections ReadVoxelPoseDetections(const std::filesystem::path& path, const VoxelPoseDetectionsOptions& options);

}  // namespace rpt
