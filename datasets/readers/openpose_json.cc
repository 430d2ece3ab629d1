// SPDX-License-Identifier: MIT
#include "datasets/readers/openpose_json.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_internal.h"
#include "datasets/readers/openpose_body25.h"

namespace rpt {
namespace {

using nlohmann::json;
using generic_internal::Source;

const std::vector<std::pair<int, std::string>>& Coco18Map() {
  static const std::vector<std::pair<int, std::string>> map = {
      {0, "nose"},       {2, "shoulder_right"}, {3, "elbow_right"}, {4, "wrist_right"}, {5, "shoulder_left"},
      {6, "elbow_left"}, {7, "wrist_left"},     {8, "hip_right"},   {9, "knee_right"},  {10, "ankle_right"},
      {11, "hip_left"},  {12, "knee_left"},     {13, "ankle_left"}, {14, "eye_right"},  {15, "eye_left"},
      {16, "ear_right"}, {17, "ear_left"}};
  return map;
}

// OpenPose hand order (wrist, thumb 1-4, index 1-4, middle, ring, pinky) = COCO-WholeBody order.
std::vector<std::string> HandNames(const std::string& side) {
  std::vector<std::string> names = {"hand_root_" + side};
  for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
    for (int k = 1; k <= 4; ++k) names.push_back(std::string("hand_") + finger + "_" + std::to_string(k) + "_" + side);
  }
  return names;
}

struct RawPerson {
  int body_points = 0;  // 25, 18 or 0 (no body)
  std::vector<double> body, face, hand_left, hand_right;
};

struct RawFile {
  std::filesystem::path path;
  std::string frame_id;
  std::string camera;
  std::vector<RawPerson> people;
};

// A flat x, y, confidence list; confidences in (1, 1.5] are clamped to 1 and counted under
// `folder` (one warning line per folder, not per file).
std::vector<double> ReadKeypoints(const json& root, const std::string& pointer, const std::string& source,
                                  const std::vector<size_t>& allowed_points, const std::string& what,
                                  const std::string& folder, InputWarnings* warnings) {
  const json* j = io::JsonFind(root, pointer);
  if (!j || j->is_null()) return {};
  std::vector<double> values = io::JsonNumbers(root, pointer, source);
  if (values.empty()) return values;
  const bool ok = values.size() % 3 == 0 &&
                  std::find(allowed_points.begin(), allowed_points.end(), values.size() / 3) != allowed_points.end();
  if (!ok) {
    std::string allowed;
    for (size_t n : allowed_points) allowed += (allowed.empty() ? "" : " or ") + std::to_string(3 * n);
    throw InputError(source + ": " + pointer + ": " + std::to_string(values.size()) + " numbers, expected " + allowed +
                     " (" + what + ")");
  }
  for (double v : values) {
    if (!std::isfinite(v)) throw InputError(source + ": " + pointer + ": value is not finite");
  }
  for (size_t i = 2; i < values.size(); i += 3) {
    values[i] = AcceptScore(values[i], folder, warnings, [&] {
      return source + ": " + io::JsonPointerJoin(pointer, i) + " (point " + std::to_string(i / 3) + ")";
    });
  }
  return values;
}

std::vector<RawPerson> ReadOpenPoseFile(const std::filesystem::path& path, const std::string& folder,
                                        InputWarnings* warnings) {
  const std::string source = Source(path);
  const json root = io::LoadJsonFile(path);
  if (!root.is_object()) throw InputError(source + ": /: expected an OpenPose object with \"people\"");
  const json& people = io::JsonAt(root, "/people", source);
  if (!people.is_array()) throw InputError(source + ": /people: expected a list");
  std::vector<RawPerson> out;
  for (size_t p = 0; p < people.size(); ++p) {
    const std::string pointer = io::JsonPointerJoin("/people", p);
    RawPerson person;
    person.body = ReadKeypoints(root, pointer + "/pose_keypoints_2d", source, {25, 18},
                                "BODY_25 has 25 points, COCO-18 has 18; MPI models are not supported", folder, warnings);
    person.body_points = static_cast<int>(person.body.size() / 3);
    person.face = ReadKeypoints(root, pointer + "/face_keypoints_2d", source, {70}, "70 face points", folder, warnings);
    person.hand_left =
        ReadKeypoints(root, pointer + "/hand_left_keypoints_2d", source, {21}, "21 hand points", folder, warnings);
    person.hand_right =
        ReadKeypoints(root, pointer + "/hand_right_keypoints_2d", source, {21}, "21 hand points", folder, warnings);
    out.push_back(std::move(person));
  }
  return out;
}

JointNames JointsOf(OpenPoseJointSet set) {
  const JointNames& all = CocoWholeBodyJoints();
  switch (set) {
    case OpenPoseJointSet::kBody:
      return CocoBodyJoints();
    case OpenPoseJointSet::kBodyFeet:
      return JointNames(all.begin(), all.begin() + 23);
    case OpenPoseJointSet::kWholeBody:
    case OpenPoseJointSet::kAuto:
      break;
  }
  return all;
}

// Copies `count` points of a flat x, y, c list into the joints at `targets` (-1 = dropped).
void CopyPoints(const std::vector<double>& flat, const std::vector<int>& targets, Eigen::Map<Eigen::Matrix3Xd>* joints) {
  if (flat.empty()) return;
  for (size_t i = 0; i < targets.size() && 3 * i + 2 < flat.size(); ++i) {
    const int j = targets[i];
    if (j < 0) continue;
    (*joints)(0, j) = flat[3 * i];
    (*joints)(1, j) = flat[3 * i + 1];
    (*joints)(2, j) = flat[3 * i + 2];  // checked and clamped by ReadKeypoints
  }
}

std::vector<int> Targets(const std::vector<std::pair<int, std::string>>& map, int points, const JointNames& joints) {
  std::vector<int> targets(points, -1);
  for (const auto& [index, name] : map) targets[index] = FindJoint(joints, name);
  return targets;
}

std::vector<int> Targets(const std::vector<std::string>& names, const JointNames& joints) {
  std::vector<int> targets;
  for (const std::string& name : names) targets.push_back(FindJoint(joints, name));
  return targets;
}

// OpenPose writes a file per camera and frame, also when it sees nobody: a camera with no file
// for a frame that other cameras have is counted per camera (it has no data there: dropped or not
// processed, Detections::unlisted_cameras_unavailable).
void CountMissingFiles(Detections& detections, const std::string& source) {
  std::set<std::string> cameras;
  for (const FrameDetections& frame : detections.frames) cameras.insert(frame.cameras.begin(), frame.cameras.end());
  for (const std::string& camera : cameras) {
    long missing = 0;
    for (const FrameDetections& frame : detections.frames) {
      missing += std::find(frame.cameras.begin(), frame.cameras.end(), camera) == frame.cameras.end() ? 1 : 0;
    }
    detections.warnings.AddMissing(
        source, "frames without a file of camera " + QuoteName(camera) +
                    " (other cameras have one; no data from it there: it neither supports nor contradicts a person)",
        missing);
  }
}

}  // namespace

Detections ReadOpenPoseFolder(const std::filesystem::path& dir, const OpenPoseFolderOptions& options) {
  const std::string source = Source(dir);
  const PathMapper mapper(options.mapping, "OpenPose folder mapping");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw InputError(source + ": folder not found");

  // Collect and map the file names.
  std::vector<RawFile> files;
  long unmatched = 0, not_regular = 0;
  std::string first_unmatched, first_not_regular;
  // Camera folders may be links (cameras gathered from several disks); a folder reached a second
  // time (a link loop, or two links to one folder) is not read again, but counted; depth is bounded.
  constexpr int kMaxFolderDepth = 8;
  std::set<std::filesystem::path> folders = {std::filesystem::weakly_canonical(dir, ec)};
  long repeated_folders = 0;
  std::string first_repeated;
  std::filesystem::path last_folder;
  for (auto it = std::filesystem::recursive_directory_iterator(
           dir, std::filesystem::directory_options::follow_directory_symlink, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec)) {
      last_folder = it->path();  // the one the iterator enters next: named should listing it fail
      std::error_code canonical_error;
      const std::filesystem::path folder = std::filesystem::canonical(it->path(), canonical_error);
      if (canonical_error || !folders.insert(folder).second || it.depth() >= kMaxFolderDepth) {
        it.disable_recursion_pending();
        const std::string relative = it->path().lexically_relative(dir).generic_string();
        if (repeated_folders++ == 0 || relative < first_repeated) first_repeated = relative;
      }
      continue;
    }
    const std::string relative = it->path().lexically_relative(dir).generic_string();
    if (!it->is_regular_file(ec)) {  // a FIFO, a device, a dangling link: never opened, but said
      if (not_regular++ == 0 || relative < first_not_regular) first_not_regular = relative;
      continue;
    }
    RawFile file;
    file.path = it->path();
    if (mapper.Apply(relative, source, &file.frame_id, &file.camera)) {
      files.push_back(std::move(file));
    } else if (unmatched++ == 0 || relative < first_unmatched) {
      first_unmatched = relative;  // the first by name: the same line whatever the listing order
    }
  }
  if (ec) {
    throw InputError(source + ": cannot list " +
                     (last_folder.empty() ? std::string("the folder")
                                          : "its folder " + QuoteName(last_folder.lexically_relative(dir).generic_string())) +
                     ": " + ec.message());
  }
  if (files.empty()) {
    throw InputError(source + ": no file matches the pattern " + QuoteName(options.mapping.pattern) +
                     " (paths relative to the folder, e.g. <camera>/<video>_000000000000_keypoints.json; every "
                     "camera's files in one folder, named <camera>_000000000012_keypoints.json, need --map-pattern "
                     "'([a-z0-9]+)_(\\d+)_keypoints\\.json')");
  }
  std::sort(files.begin(), files.end(), [](const RawFile& a, const RawFile& b) {
    return std::tie(a.frame_id, a.camera, a.path) < std::tie(b.frame_id, b.camera, b.path);
  });
  for (size_t i = 1; i < files.size(); ++i) {
    if (files[i].frame_id == files[i - 1].frame_id && files[i].camera == files[i - 1].camera) {
      throw InputError(source + ": files " + QuoteName(files[i - 1].path.string()) + " and " + QuoteName(files[i].path.string()) +
                       " both map to frame " + QuoteName(files[i].frame_id) + ", camera " + QuoteName(files[i].camera));
    }
  }

  // Parse, then decide the joint set over all files.
  InputWarnings warnings;
  warnings.AddUnused(
      source,
      "files not matching the pattern " + QuoteName(options.mapping.pattern) + " ignored (e.g. " + QuoteName(first_unmatched) + ")",
      unmatched);
  warnings.AddUnused(source,
                     "entries that are not regular files (FIFOs, devices, dangling links) skipped (e.g. " +
                         QuoteName(first_not_regular) + ")",
                     not_regular);
  warnings.AddUnused(source,
                     "folders reached a second time through a link (a loop, or two links to one folder) not read "
                     "again (e.g. " + QuoteName(first_repeated) + ")",
                     repeated_folders);
  bool any_body25 = false;
  long persons = 0, with_face_or_hand = 0;
  for (RawFile& file : files) {
    file.people = ReadOpenPoseFile(file.path, source, &warnings);
    for (const RawPerson& person : file.people) {
      ++persons;
      with_face_or_hand += !person.face.empty() || !person.hand_left.empty() || !person.hand_right.empty() ? 1 : 0;
      any_body25 |= person.body_points == 25;
    }
  }
  OpenPoseJointSet set = options.joints;
  if (set == OpenPoseJointSet::kAuto) {
    set = with_face_or_hand > 0 ? OpenPoseJointSet::kWholeBody
          : any_body25          ? OpenPoseJointSet::kBodyFeet
                                : OpenPoseJointSet::kBody;
    // Whole-body chosen for all because some persons have face or hand points: said, with how few
    // (one stray face made every person 133 joints, most of them missing, without a word).
    if (set == OpenPoseJointSet::kWholeBody && with_face_or_hand < persons) {
      warnings.AddMissing(source,
                          "persons without face or hand points, while " + std::to_string(with_face_or_hand) +
                              " others have them: --openpose-joints auto read every person as 133 COCO-WholeBody "
                              "joints, theirs missing (--openpose-joints body-feet reads the body only)",
                          persons - with_face_or_hand);
    }
  }
  Detections detections;
  detections.unlisted_cameras_unavailable = true;  // a file per camera and frame: no file, no data
  detections.joints = JointsOf(set);
  detections.warnings = std::move(warnings);
  const JointNames& joints = detections.joints;
  const std::vector<int> body25 = Targets(Body25Joints(), joints);  // neck, hip_middle: not in `joints`, dropped
  const std::vector<int> coco18 = Targets(Coco18Map(), 18, joints);
  std::vector<std::string> face_names;
  for (int i = 0; i < 68; ++i) face_names.push_back((i < 10 ? "face_0" : "face_") + std::to_string(i));
  face_names.push_back("");  // pupils: dropped
  face_names.push_back("");
  const std::vector<int> face = Targets(face_names, joints);
  const std::vector<int> hand_left = Targets(HandNames("left"), joints);
  const std::vector<int> hand_right = Targets(HandNames("right"), joints);

  const int num_joints = static_cast<int>(joints.size());
  for (const RawFile& file : files) {
    if (detections.frames.empty() || detections.frames.back().frame_id != file.frame_id) {
      detections.frames.emplace_back().frame_id = file.frame_id;
    }
    FrameDetections& frame = detections.frames.back();
    frame.cameras.push_back(file.camera);
    Poses2D& view = frame.views.emplace_back();
    view.Clear(num_joints);
    for (const RawPerson& person : file.people) {
      auto person_joints = view.AddPerson();
      CopyPoints(person.body, person.body_points == 25 ? body25 : coco18, &person_joints);
      CopyPoints(person.face, face, &person_joints);
      CopyPoints(person.hand_left, hand_left, &person_joints);
      CopyPoints(person.hand_right, hand_right, &person_joints);
      if (!(person_joints.row(2).array() > 0).any()) view.data.resize(view.data.size() - 3 * num_joints);
    }
  }
  CountMissingFiles(detections, source);
  ValidateDetections(detections, source);
  return detections;
}

}  // namespace rpt
