// SPDX-License-Identifier: MIT
// Pieces shared by the generic interchange readers (labels, detections, OpenPose folders, COCO
// result lists): which joint names are accepted, and how file names become frame ids and
// camera names. Schemas and examples: docs/datasets/generic_formats.md.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "core/joints.h"

namespace rpt {

// Joint names accepted in files besides COCO-WholeBody (core/joints.h) and the derived joints
// (hip_middle, shoulder_middle, head): head_top, head_bottom, neck, neck_nose, pelvis,
// body_center, spine, thorax, hand_left, hand_right. Any name starting with "extra_" is accepted
// too (carried along, never evaluated).
const JointNames& ExtraJointNames();
bool IsKnownJointName(std::string_view name);
// Throws InputError "<where>: unknown joint name 'left_shoulder' (did you mean
// 'shoulder_left'?)" for the first unknown name, and on an empty list, empty or duplicate names.
void CheckJointNames(const JointNames& names, const std::string& where);

// Maps a relative file path (OpenPose folders) or an image file name (COCO "images") to a frame
// id and a camera name: `pattern` must match the whole text ('/' separates folders), and two
// templates build the results from its capture groups.
//
// Template syntax: text is copied as is; {N} inserts capture group N; {N:W} reads group N as a
// non-negative integer and writes it zero-padded to W digits; {N:W+K} and {N:W-K} add or
// subtract K first; "{{" and "}}" are literal braces. Example: pattern
// "([^/]+)/.*_(\d+)_keypoints\.json", frame_id "shelf_{2:6}", camera "{1}" maps
// "Camera0/shelf_000000000300_keypoints.json" to ("shelf_000300", "Camera0").
struct PathMapping {
  std::string pattern;   // regular expression, RE2 syntax (no backreferences or lookaround)
  std::string frame_id;  // template of the frame id
  std::string camera;    // template of the camera name
};

// A PathMapping checked and compiled once.
class PathMapper {
 public:
  // Throws ConfigError naming `what` when the pattern does not compile, a template is malformed,
  // or a template refers to a capture group the pattern does not have.
  PathMapper(const PathMapping& mapping, const std::string& what);
  ~PathMapper();
  PathMapper(const PathMapper&) = delete;
  PathMapper& operator=(const PathMapper&) = delete;

  // Returns false when the pattern does not match `text`; throws InputError naming `source`
  // when a numeric field is not a number or its offset makes it negative, or when `text` is
  // longer than any path (4096 bytes). Matching takes time linear in `text` (RE2).
  bool Apply(const std::string& text, const std::string& source, std::string* frame_id, std::string* camera) const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

}  // namespace rpt
