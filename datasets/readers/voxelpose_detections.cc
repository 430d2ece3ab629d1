// SPDX-License-Identifier: MIT
#include "datasets/readers/voxelpose_detections.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <unordered_map>

#include "core/errors.h"
#include "core/joints.h"
#include "core/printable_text.h"
#include "datasets/io/inflate_budget.h"
#include "datasets/io/number_text.h"
#include "datasets/io/pickle.h"

namespace rpt {
namespace {

constexpr int kCocoJoints = 17;

std::string VoxelPoseFrameId(const std::string& prefix, long frame) {
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06ld", frame);
  return prefix + "_" + digits;
}

// Splits "<camera>_<frame>" at the last '_'; false when the frame part is not a number.
bool SplitKey(const std::string& key, std::string* camera, long* frame) {
  const size_t underscore = key.rfind('_');
  if (underscore == std::string::npos || underscore == 0 || underscore + 1 == key.size()) return false;
  if (!io::ParseInteger(std::string_view(key).substr(underscore + 1), frame) || *frame < 0) return false;
  *camera = key.substr(0, underscore);
  return true;
}

// One detection {"pred": 17x3} appended to `view`. Heatmap maxima can overshoot 1 slightly:
// scores in (1, 1.5] are clamped to 1 and counted in `warnings`.
void AddDetection(const io::PyView& detection, Poses2D* view, InputWarnings* warnings) {
  if (!detection.IsDict()) {
    detection.Fail(std::string("expected a dict with key 'pred', got ") + PyKindName(detection.kind()));
  }
  const io::PyView pred = detection.Key("pred");
  const std::vector<double> rows = pred.ToDoubles({kCocoJoints, 3});
  if (!std::all_of(rows.begin(), rows.end(), [](double v) { return std::isfinite(v); })) {
    pred.Fail("contains NaN or infinity");
  }
  auto person = view->AddPerson();
  for (int j = 0; j < kCocoJoints; ++j) {
    person(0, j) = rows[3 * j];
    person(1, j) = rows[3 * j + 1];
    person(2, j) = AcceptScore(rows[3 * j + 2], pred.source(), warnings,
                               [&] { return pred.Where() + ": row " + std::to_string(j); });
  }
}

// The detections of one key's value.
void ReadView(const io::PyView& value, Poses2D* view, InputWarnings* warnings) {
  if (!value.IsList() && !value.IsTuple()) {
    value.Fail(std::string("expected a list of detections, got ") + PyKindName(value.kind()));
  }
  view->Clear(kCocoJoints);
  for (const io::PyView& detection : value.Elements()) AddDetection(detection, view, warnings);
}

}  // namespace

VoxelPoseDetectionsFile::VoxelPoseDetectionsFile(const std::filesystem::path& path, std::vector<std::string> cameras)
    : cameras_(std::move(cameras)) {
  const io::PyView root = io::ReadPickle(path);
  source_ = root.source();
  if (!root.IsDict()) {
    root.Fail(std::string("expected a dict keyed by \"{camera}_{frame}\", got ") + PyKindName(root.kind()));
  }
  items_ = root.Items();
  // Every key is checked, not only those of the frames a reader selects.
  std::vector<std::pair<std::string, long>> parsed(items_.size());
  for (size_t i = 0; i < items_.size(); ++i) {
    const io::PyView& key = items_[i].first;
    if (!key.IsStr()) root.Fail("key " + io::Repr(key.value()) + " is not a string \"{camera}_{frame}\"");
    if (!SplitKey(key.AsStr(), &parsed[i].first, &parsed[i].second)) {
      root.Fail("key " + QuoteName(key.AsStr()) + " is not of the form \"{camera}_{frame}\"");
    }
  }
  if (cameras_.empty()) {
    const std::set<std::string> named = [&] {
      std::set<std::string> names;
      for (const auto& [camera, frame] : parsed) names.insert(camera);
      return names;
    }();
    cameras_.assign(named.begin(), named.end());
  }
  std::unordered_map<std::string, size_t> camera_index;
  for (size_t c = 0; c < cameras_.size(); ++c) camera_index[cameras_[c]] = c;
  long unknown_camera_keys = 0;
  std::set<std::string> unknown_cameras;
  for (size_t i = 0; i < parsed.size(); ++i) {
    const auto c = camera_index.find(parsed[i].first);
    if (c == camera_index.end()) {
      ++unknown_camera_keys;
      unknown_cameras.insert(parsed[i].first);
      continue;
    }
    std::vector<int>& per_camera = keys_[parsed[i].second];
    per_camera.resize(cameras_.size(), -1);
    per_camera[c->second] = static_cast<int>(i);
  }
  // A pickle stores an object once however often it is referenced: a 9 KB file whose keys all
  // refer to one list of 1000 detections decoded to 630 MB. What the keys decode to is charged to
  // the file's inflate budget (64 x its size, at least 64 MiB; --max-inflate-mb) before any is read.
  std::uint64_t detections = 0;
  for (const auto& [key, value] : items_) {
    if (value.IsList() || value.IsTuple()) detections += value.Size();
  }
  std::error_code ec;
  const std::uint64_t file_bytes = std::filesystem::file_size(path, ec);
  io::InflateBudget budget(source_, ec ? 0 : file_bytes);
  budget.Reserve(detections * kCocoJoints * 3 * sizeof(double),
                 source_ + ": its " + std::to_string(detections) + " detections (objects the file stores once may "
                 "be referenced many times)");
  std::string names;
  for (const std::string& camera : unknown_cameras) names += (names.empty() ? "'" : ", '") + camera + "'";
  warnings_.AddUnused(source_, "keys of cameras not in the calibration ignored (cameras " + names + ")",
                      unknown_camera_keys);
}

std::vector<long> VoxelPoseDetectionsFile::frames() const {
  std::vector<long> out;
  out.reserve(keys_.size());
  for (const auto& [frame, items] : keys_) out.push_back(frame);
  return out;
}

void VoxelPoseDetectionsFile::ReadFrame(long frame, std::vector<Poses2D>* views, InputWarnings* warnings) const {
  views->resize(cameras_.size());
  for (Poses2D& view : *views) view.Clear(kCocoJoints);
  const auto it = keys_.find(frame);
  if (it == keys_.end()) return;
  for (size_t c = 0; c < cameras_.size(); ++c) {
    if (it->second[c] >= 0) ReadView(items_[static_cast<size_t>(it->second[c])].second, &(*views)[c], warnings);
  }
}

void VoxelPoseDetectionsFile::ReadFrame(long frame, std::vector<std::string>* cameras, std::vector<Poses2D>* views,
                                        InputWarnings* warnings) const {
  cameras->clear();
  views->clear();
  const auto it = keys_.find(frame);
  if (it == keys_.end()) return;
  for (size_t c = 0; c < cameras_.size(); ++c) {
    if (it->second[c] < 0) continue;
    cameras->push_back(cameras_[c]);
    ReadView(items_[static_cast<size_t>(it->second[c])].second, &views->emplace_back(), warnings);
  }
}

Detections ReadVoxelPoseDetections(const std::filesystem::path& path, const VoxelPoseDetectionsOptions& options) {
  if (options.frame_id_prefix.empty()) {
    throw ConfigError(path.string() +
                      ": a VoxelPose cache is keyed \"{camera}_{frame}\": reading it needs the frame-id "
                      "prefix of the sequence it belongs to (e.g. 'shelf' for frame ids shelf_000300)");
  }
  const VoxelPoseDetectionsFile file(path, options.cameras);
  Detections detections;
  detections.joints = CocoBodyJoints();
  detections.warnings = file.warnings();
  for (const long frame : file.frames()) {
    FrameDetections& out = detections.frames.emplace_back();
    out.frame_id = VoxelPoseFrameId(options.frame_id_prefix, frame);
    file.ReadFrame(frame, &out.cameras, &out.views, &detections.warnings);
  }
  return detections;
}

}  // namespace rpt
