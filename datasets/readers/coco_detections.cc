// SPDX-License-Identifier: MIT
#include "datasets/readers/coco_detections.h"

#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_map>

#include "core/errors.h"
#include "core/options_check.h"
#include "core/printable_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/io/number_text.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_internal.h"

namespace rpt {
namespace {

using nlohmann::json;
using generic_internal::Source;

struct ViewKey {
  std::string frame_id;
  std::string camera;
};

// An image id written as an integer or as a string of digits, inside the int64 range (an id of
// 2^63 + 5 is refused instead of wrapping to a negative number).
std::int64_t ImageId(const json& value, const std::string& source, const std::string& pointer) {
  if (const auto id = io::JsonToInt64(value)) return *id;
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    std::int64_t id = 0;
    if (io::ParseInteger(text, &id)) return id;
  }
  if (value.is_string()) {
    // AlphaPose and other tools write the image's file name as its id: there is no camera in it.
    throw InputError(source + ": " + pointer + ": image id " + io::JsonExcerpt(value) +
                     " is a name, not a number: COCO results name their image by the integer id of an annotation "
                     "file's \"images\" (--coco-images FILE maps its file_name to frame and camera). Results "
                     "that name image files (AlphaPose's) are one camera's each: write them as rpt's generic "
                     "detections JSON, {\"joints\": [...], \"frames\": [{\"id\": ..., \"views\": [{\"camera\": ..., "
                     "\"poses\": [[[x, y, score], ...]]}]}]} (docs/datasets/generic_formats.md)");
  }
  throw InputError(source + ": " + pointer + ": expected an integer image id in the 64-bit signed range, got " + io::JsonExcerpt(value));
}

// COCO's person category is 1; results without "category_id" are taken as persons. Written as a
// number or as a string of digits (MVOR's openpose_kps.json writes "1").
bool IsPerson(const json& item) {
  const auto category = item.find("category_id");
  if (category == item.end() || category->is_null()) return true;
  if (category->is_number()) return category->get<double>() == 1.0;
  return category->is_string() && category->get<std::string>() == "1";
}

std::optional<ViewKey> MvorView(std::int64_t image_id) {
  constexpr std::int64_t kDay = 10'000'000'000LL, kCam = 10'000'000LL;
  const std::int64_t day = image_id / kDay;
  const std::int64_t cam = (image_id % kDay) / kCam;
  const std::int64_t frame = image_id % kCam;
  if (image_id <= 0 || day < 1 || day > 99 || cam < 1) return std::nullopt;
  std::string digits = std::to_string(frame);
  if (digits.size() < 6) digits.insert(0, 6 - digits.size(), '0');
  return ViewKey{"mvor_day" + std::to_string(day) + "_" + digits, "cam" + std::to_string(cam)};
}

// image id -> view, from the "images" list of a COCO annotation file.
std::unordered_map<std::int64_t, ViewKey> AnnotationImages(const CocoDetectionsOptions& options) {
  const std::string source = Source(options.annotation_file);
  const json root = io::LoadJsonFile(options.annotation_file);
  const json& images = io::JsonAt(root, "/images", source);
  if (!images.is_array()) throw InputError(source + ": /images: expected a list of images");
  std::optional<PathMapper> mapper;
  if (options.mapping == CocoImageMapping::kAnnotationImages) {
    mapper.emplace(options.file_name_mapping, "COCO file_name mapping");
  }
  std::unordered_map<std::int64_t, ViewKey> views;
  std::map<std::pair<std::string, std::string>, std::int64_t> image_of_view;
  for (size_t i = 0; i < images.size(); ++i) {
    const std::string pointer = io::JsonPointerJoin("/images", i);
    const std::int64_t id = ImageId(io::JsonAt(root, pointer + "/id", source), source, pointer + "/id");
    ViewKey key;
    if (options.mapping == CocoImageMapping::kMvor) {
      const auto mvor = MvorView(id);
      if (!mvor) throw InputError(source + ": " + pointer + "/id: image id " + std::to_string(id) + " is not an MVOR id (day * 1e10 + cam * 1e7 + frame)");
      key = *mvor;
    } else if (images[i].contains("frame_id") && images[i].contains("camera")) {
      key.frame_id = generic_internal::IdString(root, pointer + "/frame_id", source);
      key.camera = io::JsonString(root, pointer + "/camera", source);
    } else {
      const std::string file_name = io::JsonString(root, pointer + "/file_name", source);
      if (!mapper->Apply(file_name, source + ": " + pointer + "/file_name", &key.frame_id, &key.camera)) {
        throw InputError(source + ": " + pointer + "/file_name: " + QuoteName(file_name) + " does not match the pattern '" +
                         options.file_name_mapping.pattern + "' (or give the image \"frame_id\" and \"camera\")");
      }
    }
    if (!views.emplace(id, key).second) throw InputError(source + ": " + pointer + "/id: image id " + std::to_string(id) + " appears twice");
    const auto [it, fresh] = image_of_view.emplace(std::make_pair(key.frame_id, key.camera), id);
    if (!fresh) {
      throw InputError(source + ": images " + std::to_string(it->second) + " and " + std::to_string(id) +
                       " both map to frame " + QuoteName(key.frame_id) + ", camera " + QuoteName(key.camera));
    }
  }
  return views;
}

}  // namespace

std::string CocoDetectionsOptions::Check() const {
  OptionsChecker checker("coco");
  checker("min_score", min_score, OptionSpec{.min = 0});
  if (mapping == CocoImageMapping::kAnnotationImages && annotation_file.empty()) {
    checker.Require("the annotation-images mapping needs an annotation file with \"images\"", "annotation_file");
  }
  return checker.error();
}

Detections ReadCocoDetections(const std::filesystem::path& path, const CocoDetectionsOptions& options) {
  const std::string source = Source(path);
  ThrowIfInvalid(options);
  if (options.mapping == CocoImageMapping::kAnnotationImages) {
    const PathMapper check(options.file_name_mapping, "COCO file_name mapping");  // ConfigError before reading files
  }
  std::unordered_map<std::int64_t, ViewKey> listed;
  if (!options.annotation_file.empty()) listed = AnnotationImages(options);

  const json root = io::LoadJsonFile(path);
  if (!root.is_array()) {
    throw InputError(source + ": /: expected a list of detection results [{\"image_id\", \"keypoints\", ...}], got " +
                     std::string(root.type_name()));
  }
  Detections detections;
  // frame id -> camera -> flat x, y, c of its persons.
  std::map<std::string, std::map<std::string, std::vector<double>>> frames;
  for (const auto& [id, key] : listed) frames[key.frame_id][key.camera];
  int num_points = 0;
  std::string first_pointer;
  for (size_t i = 0; i < root.size(); ++i) {
    const std::string pointer = "/" + std::to_string(i);
    const json& item = root[i];
    if (!item.is_object()) throw InputError(source + ": " + pointer + ": expected a detection object");
    if (!IsPerson(item)) {
      detections.warnings.AddUnused(source, "results of another category than person (category_id 1) skipped");
      continue;
    }
    if (options.min_score > 0) {
      const auto score = item.find("score");
      if (score != item.end() && !score->is_number()) {
        detections.warnings.AddUnused(source,
                                      "results with a non-numeric \"score\" skipped (min_score needs a number)");
        continue;
      }
      if (score != item.end() && score->get<double>() < options.min_score) continue;  // filtered on purpose
    }
    const std::int64_t image_id = ImageId(io::JsonAt(root, pointer + "/image_id", source), source, pointer + "/image_id");
    ViewKey key;
    if (const auto it = listed.find(image_id); it != listed.end()) {
      key = it->second;
    } else if (options.mapping == CocoImageMapping::kMvor) {
      const auto mvor = MvorView(image_id);
      if (!mvor) {
        throw InputError(source + ": " + pointer + "/image_id: image id " + std::to_string(image_id) +
                         " is not an MVOR multi-view id (day * 1e10 + cam * 1e7 + frame); give the annotation file that lists "
                         "the images (--coco-images FILE) to map image ids to frames and cameras");
      }
      key = *mvor;
    } else {
      throw InputError(source + ": " + pointer + "/image_id: image id " + std::to_string(image_id) + " is not in the \"images\" of " +
                       Source(options.annotation_file));
    }
    std::string keypoints_key = options.keypoints_key;
    if (keypoints_key.empty()) keypoints_key = item.contains("coco_keypoints") ? "coco_keypoints" : "keypoints";
    const std::string keypoints_pointer = io::JsonPointerJoin(pointer, keypoints_key);
    const std::vector<double> values = io::JsonNumbers(root, keypoints_pointer, source);
    if (values.empty()) {  // a box without keypoints
      detections.warnings.AddUnused(source, "results without keypoints (box only) skipped");
      continue;
    }
    if (values.size() != 17 * 3 && values.size() != 133 * 3) {
      throw InputError(source + ": " + keypoints_pointer + ": " + std::to_string(values.size()) +
                       " numbers, expected 51 (17 COCO joints x [x, y, score]) or 399 (COCO-WholeBody)");
    }
    if (num_points == 0) {
      num_points = static_cast<int>(values.size() / 3);
      first_pointer = keypoints_pointer;
    } else if (static_cast<int>(values.size() / 3) != num_points) {
      throw InputError(source + ": " + keypoints_pointer + ": " + std::to_string(values.size() / 3) + " joints, but " +
                       first_pointer + " has " + std::to_string(num_points));
    }
    std::vector<double>& view = frames[key.frame_id][key.camera];
    for (size_t k = 0; k < values.size(); k += 3) {
      if (!std::isfinite(values[k]) || !std::isfinite(values[k + 1]) || !std::isfinite(values[k + 2])) {
        throw InputError(source + ": " + keypoints_pointer + ": value is not finite");
      }
      view.push_back(values[k]);
      view.push_back(values[k + 1]);
      view.push_back(AcceptScore(values[k + 2], source, &detections.warnings, [&] {
        return source + ": " + io::JsonPointerJoin(keypoints_pointer, k + 2) + " (joint " + std::to_string(k / 3) + ")";
      }));
    }
  }

  detections.joints = num_points == 133 ? CocoWholeBodyJoints() : CocoBodyJoints();
  const int num_joints = static_cast<int>(detections.joints.size());
  detections.frames.reserve(frames.size());
  for (auto& [frame_id, cameras] : frames) {
    FrameDetections& frame = detections.frames.emplace_back();
    frame.frame_id = frame_id;
    for (auto& [camera, data] : cameras) {
      frame.cameras.push_back(camera);
      Poses2D& view = frame.views.emplace_back();
      view.Clear(num_joints);
      view.data = std::move(data);
    }
  }
  ValidateDetections(detections, source);
  return detections;
}

}  // namespace rpt
