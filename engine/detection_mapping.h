// SPDX-License-Identifier: MIT
// How the entries of a detections file (--detections) become frame ids, cameras and joints: the
// mapping flags of every command that reads detections (docs/own_data.md, "Mapping detections to
// frames and cameras"). Each flag applies to some detection formats; a flag given for another
// format, or without --detections, is a ConfigError naming it (never silently ignored).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "datasets/readers/voxelpose_detections.h"

namespace rpt::engine {

// The flags as the user typed them; empty (or unset) = the reader's default.
struct DetectionMapping {
  // --map-pattern, --map-frame-id, --map-camera: a PathMapping (datasets/readers/generic_common.h)
  // over an OpenPose folder's file paths, or over the image file names of --coco-images.
  std::string pattern;
  std::string frame_id;
  std::string camera;
  std::string openpose_joints;           // --openpose-joints auto | body | body-feet | whole-body
  std::string coco_images;               // --coco-images FILE: a COCO annotation file with "images"
  std::string coco_image_ids;            // --coco-image-ids mvor | images; unset: images with --coco-images, else mvor
  std::optional<double> coco_min_score;  // --coco-min-score: results with a lower "score" are dropped
  std::string coco_keypoints;            // --coco-keypoints KEY: the per-result array holding the keypoints
  std::string voxelpose_prefix;          // --voxelpose-prefix NAME: frame ids "<NAME>_<frame, 6 digits>"
  std::vector<std::string> rename_cameras;  // --rename-camera FROM=TO: camera FROM of the file is camera TO

  bool empty() const;
};

// The values of --openpose-joints and --coco-image-ids, for the CLI's checks and help.
const std::vector<std::string>& OpenPoseJointsNames();
const std::vector<std::string>& CocoImageIdsNames();

// Throws ConfigError naming the flag when a flag of `mapping` does not apply to the detections
// at `detections` ("" = none given) or has a bad value (malformed pattern or template, unknown
// joint set, a --rename-camera that is not FROM=TO, ...); InputError when `detections` cannot be
// told apart (missing, unknown extension). Nothing is checked when `mapping` is empty.
void CheckDetectionMapping(const DetectionMapping& mapping, const std::string& detections);

// Throws ConfigError for a --rename-camera FROM=TO whose TO is none of `cameras` (the names of the
// calibration `calibration_file`), naming them: the rename to correct, not one more to add.
void CheckRenameTargets(const DetectionMapping& mapping, const std::vector<std::string>& cameras,
                        const std::string& calibration_file);

// Reads the detections file `path` (ReadDetectionsFile) with `mapping` applied. `voxelpose`: the
// frame-id prefix and the cameras (names of the calibration, in its order) a VoxelPose cache is
// read for; --voxelpose-prefix replaces the prefix, and --rename-camera maps the calibration's
// names back to the file's. Cameras are then renamed (--rename-camera); a FROM no frame names is a
// ConfigError, two cameras of one frame renamed to one name an InputError naming the file and the
// frame. Checks `mapping` first (CheckDetectionMapping).
Detections ReadMappedDetections(const std::string& path, const DetectionMapping& mapping,
                                const VoxelPoseDetectionsOptions& voxelpose = {});

}  // namespace rpt::engine
