// SPDX-License-Identifier: MIT
#include "datasets/readers/voxelpose_detections.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <unordered_map>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "core/joints.h"
#include "datasets/input_warnings.h"
#include "datasets/io/pickle.h"

namespace rpt {
namespace {

constexpr int kCocoJoints = 17;

std::string FrameId(const std::string& prefix, long frame) {
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

}  // namespace

Detections ReadVoxelPoseDetections(const std::filesystem::path& path, const Sequence& sequence,
                                   const std::string& dataset_prefix) {
  const io::PyView root = io::ReadPickle(path);
  if (!root.IsDict()) {
    root.Fail(std::string("expected a dict keyed by \"{camera}_{frame}\", got ") + PyKindName(root.kind()));
  }

  std::unordered_map<std::string, size_t> frame_index;
  for (size_t f = 0; f < sequence.frames.size(); ++f) frame_index[sequence.frames[f].id] = f;
  std::unordered_map<std::string, size_t> camera_index;
  for (size_t c = 0; c < sequence.cameras.size(); ++c) camera_index[sequence.cameras[c].name] = c;

  // Per sequence frame, per sequence camera: the view, if the file has its key.
  std::vector<std::vector<const io::PyView*>> found(sequence.frames.size(),
                                                    std::vector<const io::PyView*>(sequence.cameras.size(), nullptr));
  long unknown_camera_keys = 0;
  std::set<std::string> unknown_cameras;
  const auto items = root.Items();
  for (const auto& [key, value] : items) {
    if (!key.IsStr()) root.Fail("key " + io::Repr(key.value()) + " is not a string \"{camera}_{frame}\"");
    std::string camera;
    long frame = 0;
    if (!SplitKey(key.AsStr(), &camera, &frame)) {
      root.Fail("key '" + key.AsStr() + "' is not of the form \"{camera}_{frame}\"");
    }
    const auto f = frame_index.find(FrameId(dataset_prefix, frame));
    const auto c = camera_index.find(camera);
    if (c == camera_index.end()) {  // the whole cache is checked, not only the selected frames
      ++unknown_camera_keys;
      unknown_cameras.insert(camera);
      continue;
    }
    if (f == frame_index.end()) continue;  // a frame not selected: the caches cover every image
    found[f->second][c->second] = &value;
  }

  Detections detections;
  std::string names;
  for (const std::string& camera : unknown_cameras) names += (names.empty() ? "'" : ", '") + camera + "'";
  detections.warnings.AddUnused(root.source(), "keys of cameras not in the calibration ignored (cameras " + names + ")",
                                unknown_camera_keys);
  detections.joints = CocoBodyJoints();
  for (size_t f = 0; f < found.size(); ++f) {
    FrameDetections frame;
    frame.frame_id = sequence.frames[f].id;
    for (size_t c = 0; c < found[f].size(); ++c) {
      const io::PyView* value = found[f][c];
      if (value == nullptr) continue;
      if (!value->IsList() && !value->IsTuple()) {
        value->Fail(std::string("expected a list of detections, got ") + PyKindName(value->kind()));
      }
      Poses2D view;
      view.Clear(kCocoJoints);
      for (const io::PyView& detection : value->Elements()) AddDetection(detection, &view, &detections.warnings);
      frame.cameras.push_back(sequence.cameras[c].name);
      frame.views.push_back(std::move(view));
    }
    if (!frame.cameras.empty()) detections.frames.push_back(std::move(frame));
  }
  return detections;
}

}  // namespace rpt
