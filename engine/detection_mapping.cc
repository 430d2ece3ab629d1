// SPDX-License-Identifier: MIT
#include "engine/detection_mapping.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_common.h"

namespace rpt::engine {
namespace {

constexpr const char* kMappingFlags = "--map-pattern/--map-frame-id/--map-camera";

const std::vector<std::pair<std::string, OpenPoseJointSet>>& OpenPoseJointSets() {
  static const std::vector<std::pair<std::string, OpenPoseJointSet>> sets = {
      {"auto", OpenPoseJointSet::kAuto},
      {"body", OpenPoseJointSet::kBody},
      {"body-feet", OpenPoseJointSet::kBodyFeet},
      {"whole-body", OpenPoseJointSet::kWholeBody}};
  return sets;
}

bool UsesPathMapping(const DetectionMapping& m) {
  return !m.pattern.empty() || !m.frame_id.empty() || !m.camera.empty();
}

// The first flag of `m` that is given, for the message when there are no detections.
std::string FirstFlag(const DetectionMapping& m) {
  if (!m.pattern.empty()) return "--map-pattern";
  if (!m.frame_id.empty()) return "--map-frame-id";
  if (!m.camera.empty()) return "--map-camera";
  if (!m.openpose_joints.empty()) return "--openpose-joints";
  if (!m.coco_images.empty()) return "--coco-images";
  if (!m.coco_image_ids.empty()) return "--coco-image-ids";
  if (m.coco_min_score) return "--coco-min-score";
  if (!m.coco_keypoints.empty()) return "--coco-keypoints";
  if (!m.voxelpose_prefix.empty()) return "--voxelpose-prefix";
  return "--rename-camera";
}

// --coco-image-ids resolved: annotation images with --coco-images unless told "mvor".
bool AnnotationImageIds(const DetectionMapping& m) {
  return m.coco_image_ids.empty() ? !m.coco_images.empty() : m.coco_image_ids == "images";
}

// The --rename-camera pairs, FROM -> TO, checked.
std::map<std::string, std::string> Renames(const DetectionMapping& m) {
  std::map<std::string, std::string> renames;
  std::set<std::string> targets;
  for (const std::string& rename : m.rename_cameras) {
    const size_t eq = rename.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == rename.size()) {
      throw ConfigError("--rename-camera " + rename +
                        ": expected FROM=TO (the detections' camera name = the calibration's)");
    }
    const std::string from = rename.substr(0, eq), to = rename.substr(eq + 1);
    if (!renames.emplace(from, to).second) throw ConfigError("--rename-camera: camera " + QuoteName(from) + " renamed twice");
    if (!targets.insert(to).second) {
      throw ConfigError("--rename-camera: two cameras renamed to " + QuoteName(to) + " (one calibration camera each)");
    }
  }
  return renames;
}

// Refuses a flag of `m` that does not apply to `format`.
void CheckApplies(const DetectionMapping& m, DetectionsFormat format, const std::string& detections) {
  const auto refuse = [&](const std::string& flag, const std::string& applies_to) {
    throw ConfigError(flag + " applies to " + applies_to + ", but --detections " + detections + " is " +
                      DetectionsFormatName(format));
  };
  const bool openpose = format == DetectionsFormat::kOpenPoseFolder, coco = format == DetectionsFormat::kCocoResults;
  if (!m.openpose_joints.empty() && !openpose) refuse("--openpose-joints", "an OpenPose folder");
  if (!coco) {
    if (!m.coco_images.empty()) refuse("--coco-images", "a COCO result list");
    if (!m.coco_image_ids.empty()) refuse("--coco-image-ids", "a COCO result list");
    if (m.coco_min_score) refuse("--coco-min-score", "a COCO result list");
    if (!m.coco_keypoints.empty()) refuse("--coco-keypoints", "a COCO result list");
  }
  if (!m.voxelpose_prefix.empty() && format != DetectionsFormat::kVoxelPosePickle) {
    refuse("--voxelpose-prefix", "a VoxelPose .pkl cache");
  }
  if (UsesPathMapping(m)) {
    const std::string flag = FirstFlag(m);
    if (!openpose && !coco) refuse(flag, "an OpenPose folder or the images of --coco-images");
    if (coco && !AnnotationImageIds(m)) {
      throw ConfigError(flag + " maps the file names of the images of --coco-images (--coco-image-ids images); " +
                        (m.coco_images.empty() ? std::string("no --coco-images given")
                                               : std::string("--coco-image-ids mvor places them by their ids")));
    }
  }
}

// The reader options `m` sets for `format`, starting from the readers' defaults.
DetectionsFileOptions FileOptionsOf(const DetectionMapping& m, DetectionsFormat format) {
  DetectionsFileOptions options;
  PathMapping* mapping =
      format == DetectionsFormat::kCocoResults ? &options.coco.file_name_mapping : &options.openpose.mapping;
  if (!m.pattern.empty()) mapping->pattern = m.pattern;
  if (!m.frame_id.empty()) mapping->frame_id = m.frame_id;
  if (!m.camera.empty()) mapping->camera = m.camera;
  for (const auto& [name, set] : OpenPoseJointSets()) {
    if (name == m.openpose_joints) options.openpose.joints = set;
  }
  options.coco.annotation_file = m.coco_images;
  options.coco.mapping = AnnotationImageIds(m) ? CocoImageMapping::kAnnotationImages : CocoImageMapping::kMvor;
  if (m.coco_min_score) options.coco.min_score = *m.coco_min_score;
  options.coco.keypoints_key = m.coco_keypoints;
  return options;
}

}  // namespace

bool DetectionMapping::empty() const {
  return pattern.empty() && frame_id.empty() && camera.empty() && openpose_joints.empty() && coco_images.empty() &&
         coco_image_ids.empty() && !coco_min_score && coco_keypoints.empty() && voxelpose_prefix.empty() &&
         rename_cameras.empty();
}

const std::vector<std::string>& OpenPoseJointsNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, set] : OpenPoseJointSets()) out.push_back(name);
    return out;
  }();
  return names;
}

const std::vector<std::string>& CocoImageIdsNames() {
  static const std::vector<std::string> names = {"mvor", "images"};
  return names;
}

void CheckDetectionMapping(const DetectionMapping& mapping, const std::string& detections) {
  if (mapping.empty()) return;
  if (detections.empty()) {
    throw ConfigError(FirstFlag(mapping) + " maps the entries of a detections file: it needs --detections FILE");
  }
  const auto check_name = [](const std::string& flag, const std::string& value, const std::vector<std::string>& names) {
    if (!value.empty() && std::find(names.begin(), names.end(), value) == names.end()) {
      throw ConfigError(flag + " " + value + ": expected one of " + Join(names, ", ") + DidYouMean(value, names));
    }
  };
  check_name("--openpose-joints", mapping.openpose_joints, OpenPoseJointsNames());
  check_name("--coco-image-ids", mapping.coco_image_ids, CocoImageIdsNames());
  if (mapping.coco_min_score && !(*mapping.coco_min_score >= 0)) {
    throw ConfigError("--coco-min-score: expected a score >= 0");
  }
  Renames(mapping);
  const DetectionsFormat format = DetectionsFormatOf(detections);
  CheckApplies(mapping, format, detections);
  if (AnnotationImageIds(mapping) && mapping.coco_images.empty()) {
    throw ConfigError("--coco-image-ids images needs --coco-images FILE (a COCO annotation file with \"images\")");
  }
  if (UsesPathMapping(mapping)) {
    const DetectionsFileOptions options = FileOptionsOf(mapping, format);
    const PathMapper check(
        format == DetectionsFormat::kCocoResults ? options.coco.file_name_mapping : options.openpose.mapping,
        kMappingFlags);
  }
}

void CheckRenameTargets(const DetectionMapping& mapping, const std::vector<std::string>& cameras,
                        const std::string& calibration_file) {
  for (const auto& [from, to] : Renames(mapping)) {
    if (std::find(cameras.begin(), cameras.end(), to) != cameras.end()) continue;
    throw ConfigError("--rename-camera " + from + "=" + to + ": the calibration " + calibration_file +
                      " has no camera " + QuoteName(to) + " (cameras: " + JoinNames(cameras, ", ") + ")" +
                      DidYouMeanSpelling(to, cameras));
  }
}

Detections ReadMappedDetections(const std::string& path, const DetectionMapping& mapping,
                                const VoxelPoseDetectionsOptions& voxelpose) {
  CheckDetectionMapping(mapping, path);
  const std::map<std::string, std::string> renames = Renames(mapping);
  const DetectionsFormat format = DetectionsFormatOf(path);
  DetectionsFileOptions options = FileOptionsOf(mapping, format);
  options.voxelpose = voxelpose;
  if (!mapping.voxelpose_prefix.empty()) options.voxelpose.frame_id_prefix = mapping.voxelpose_prefix;
  for (std::string& camera : options.voxelpose.cameras) {  // the calibration's names -> the file's
    for (const auto& [from, to] : renames) {
      if (to == camera) {
        camera = from;
        break;
      }
    }
  }
  if (format == DetectionsFormat::kVoxelPosePickle && options.voxelpose.frame_id_prefix.empty()) {
    throw ConfigError(path +
                      ": a VoxelPose cache is keyed \"<camera>_<frame>\": name its frames with "
                      "--voxelpose-prefix NAME (frame ids NAME_000300)");
  }
  Detections detections = ReadDetectionsFile(path, options);
  if (renames.empty()) return detections;
  std::set<std::string> used, names;
  for (FrameDetections& frame : detections.frames) {
    for (std::string& camera : frame.cameras) {
      const auto it = renames.find(camera);
      if (it == renames.end()) continue;
      used.insert(camera);
      camera = it->second;
    }
    const std::set<std::string> unique(frame.cameras.begin(), frame.cameras.end());
    if (unique.size() != frame.cameras.size()) {
      throw InputError(path + ": frame " + QuoteName(frame.frame_id) + ": --rename-camera gives two views the same camera (" +
                       JoinNames(frame.cameras, ", ") + ")");
    }
    names.insert(unique.begin(), unique.end());
  }
  for (const auto& [from, to] : renames) {
    if (used.count(from) == 0) {
      throw ConfigError("--rename-camera " + from + "=" + to + ": " + path + " names no camera " + QuoteName(from) +
                        " (its cameras after renaming: " + JoinNames(std::vector<std::string>(names.begin(), names.end())) +
                        ")");
    }
  }
  return detections;
}

}  // namespace rpt::engine
