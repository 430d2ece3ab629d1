// SPDX-License-Identifier: MIT
// COCO-style keypoint detection results: a JSON list of
//   {"image_id", "category_id", "score", "keypoints": [x, y, c] * 17 (COCO order)}
// (133 points = COCO-WholeBody are accepted too). Each image is one view of one multi-view
// frame; how image ids map to (frame id, camera) is chosen with CocoImageMapping.
// Details: docs/datasets/generic_formats.md.
#pragma once

#include <filesystem>
#include <string>

#include "datasets/detections.h"
#include "datasets/readers/generic_common.h"

namespace rpt {

enum class CocoImageMapping {
  // MVOR multi-view ids: image id = day * 1e10 + cam * 1e7 + frame -> frame id
  // "mvor_day<day>_<frame, 6 digits>", camera "cam<cam>".
  kMvor,
  // The "images" list of a COCO annotation file (annotation_file): per image {"id", "file_name"}
  // plus either our fields "frame_id" and "camera", or file_name mapped with `file_name_mapping`.
  kAnnotationImages,
};

struct CocoDetectionsOptions {
  CocoImageMapping mapping = CocoImageMapping::kMvor;
  // Required for kAnnotationImages; optional for kMvor (then every listed image gets a view, empty
  // when it has no detection, e.g. MVOR's camma_mvor_2018.json).
  std::filesystem::path annotation_file;
  // kAnnotationImages without "frame_id"/"camera" fields: default = the folder holding the image
  // is the camera, the last digits of its name the frame number ("cam2/000017.png" -> "000017",
  // "cam2"). Matched against the whole file_name.
  PathMapping file_name_mapping{R"((?:.*/)?([^/]+)/[^/]*?(\d+)\.[A-Za-z0-9]+)", "{2:6}", "{1}"};
  // Which per-detection array holds the keypoints; empty = "coco_keypoints" when present (MVOR's
  // files carry COCO-17 there next to a 10-joint "keypoints"), else "keypoints".
  std::string keypoints_key;
  // Detections with "score" below this are dropped (0 keeps all).
  double min_score = 0;

  // "" when valid, else "coco.key: problem" (core/options_check.h).
  std::string Check() const;
};

// Joint names are COCO-17 (or COCO-WholeBody for 133 points). Joint scores in (1, 1.5] are
// clamped to 1 and counted in Detections::warnings; so are, as unused input, the results skipped:
// another "category_id" than person (1), no keypoints (box only), and with min_score > 0 a
// "score" that is not a number. Frames sorted by id, cameras by name. Throws
// InputError naming the file and the JSON pointer: not a list, wrong keypoint lengths (mixed
// lengths too), negative scores or scores above 1.5, an image id the mapping cannot place (naming
// it), two images mapping to the same frame and camera; ConfigError for bad options.
Detections ReadCocoDetections(const std::filesystem::path& path, const CocoDetectionsOptions& options = {});

}  // namespace rpt
