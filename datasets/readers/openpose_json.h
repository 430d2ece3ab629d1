// SPDX-License-Identifier: MIT
// OpenPose JSON output folders (--write_json): one file per view and frame with
// people[].pose_keypoints_2d (BODY_25: 75 numbers, COCO-18: 54; told apart by length),
// face_keypoints_2d (70 points) and hand_{left,right}_keypoints_2d (21 points each), all flat
// x, y, confidence lists in pixels.
//
// Default layout: <dir>/<camera>/<anything>_<frame number>_keypoints.json, which is what
// OpenPose writes per video (<video>_<12-digit frame>_keypoints.json) when each camera's output
// goes into its own folder. Other layouts are described with a PathMapping
// (datasets/readers/generic_common.h). Details: docs/datasets/generic_formats.md.
#pragma once

#include <filesystem>

#include "datasets/detections.h"
#include "datasets/readers/generic_common.h"

namespace rpt {

enum class OpenPoseJointSet {
  kAuto,       // kWholeBody when any file has face or hand points, else kBodyFeet when BODY_25, else kBody
  kBody,       // the 17 COCO joints (nose, eye_left, ...)
  kBodyFeet,   // COCO-17 + foot_{big_toe,small_toe,heel}_{left,right} (BODY_25; missing for COCO-18)
  kWholeBody,  // the 133 COCO-WholeBody joints: body, feet, face_00..face_67, hands
};

struct OpenPoseFolderOptions {
  // Matched against each file's path relative to the folder ('/'-separated); files that do not
  // match are ignored and counted (Detections::warnings, unused input). Group 1: camera folder,
  // group 2: frame number.
  PathMapping mapping{R"(([^/]+)/(?:.*_)?(\d+)_keypoints\.json)", "{2:6}", "{1}"};
  OpenPoseJointSet joints = OpenPoseJointSet::kAuto;
};

// Reads every matching file below `dir` (recursively). Frames are sorted by id, cameras by name
// within a frame; a file with no people gives an empty view. Confidences in (1, 1.5] are clamped
// to 1 and counted in Detections::warnings under `dir` (one line for the folder); neck, mid-hip
// and the pupils are dropped. Throws InputError naming the file and the JSON pointer (bad
// lengths, not numbers, negative confidences or confidences above 1.5), when two files map to the
// same frame and camera (naming both), or when no file matches; ConfigError for a malformed
// mapping.
Detections ReadOpenPoseFolder(const std::filesystem::path& dir, const OpenPoseFolderOptions& options = {});

}  // namespace rpt
