// SPDX-License-Identifier: MIT
#include "datasets/readers/generic_detections.h"

#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/input_limits.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/text_file.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_common.h"
#include "datasets/readers/generic_internal.h"

namespace rpt {
namespace {

using generic_internal::Fail;
using generic_internal::Source;
using nlohmann::json;

// One view's "poses": persons x joints x [x, y, score]. Scores slightly above 1 are clamped and
// counted in `warnings`.
void ParsePoses(const json& poses, const std::string& pointer, const std::string& source, int num_joints,
                Poses2D* out, InputWarnings* warnings) {
  out->Clear(num_joints);
  if (poses.is_null()) return;
  if (!poses.is_array()) Fail(source, pointer, "expected a list of persons, got " + std::string(poses.type_name()));
  out->data.reserve(poses.size() * 3 * static_cast<size_t>(num_joints));
  for (size_t p = 0; p < poses.size(); ++p) {
    const json& person = poses[p];
    if (!person.is_array() || static_cast<int>(person.size()) != num_joints) {
      Fail(source, io::JsonPointerJoin(pointer, p),
           "expected " + std::to_string(num_joints) + " joints (as many as \"joints\" names), got " +
               (person.is_array() ? std::to_string(person.size()) : std::string(person.type_name())));
    }
    auto joints = out->AddPerson();
    for (int j = 0; j < num_joints; ++j) {
      const json& joint = person[j];
      if (joint.is_null()) continue;  // missing joint: score 0
      // [null, null, 0]: a writer's NaN position of a joint with score 0 (JSON has no NaN): missing.
      if (joint.is_array() && joint.size() == 3 && joint[0].is_null() && joint[1].is_null() && joint[2].is_number() &&
          joint[2].get<double>() == 0) {
        continue;
      }
      if (!joint.is_array() || joint.size() != 3 || !joint[0].is_number() || !joint[1].is_number() ||
          !joint[2].is_number()) {
        Fail(source, io::JsonPointerJoin(io::JsonPointerJoin(pointer, p), j), "expected [x, y, score] or null");
      }
      const double x = joint[0].get<double>(), y = joint[1].get<double>();
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(joint[2].get<double>())) {
        Fail(source, io::JsonPointerJoin(io::JsonPointerJoin(pointer, p), j), "value is not finite");
      }
      const double score = AcceptScore(joint[2].get<double>(), source, warnings, [&] {
        return source + ": " + io::JsonPointerJoin(io::JsonPointerJoin(pointer, p), j);
      });
      joints(0, j) = x;
      joints(1, j) = y;
      joints(2, j) = score;
    }
  }
}

}  // namespace

void ValidateDetections(const Detections& detections, const std::string& source) {
  CheckJointNames(detections.joints, source + ": joints");
  const int num_joints = static_cast<int>(detections.joints.size());
  std::unordered_set<std::string> frame_ids;
  for (const FrameDetections& frame : detections.frames) {
    const std::string where = source + ": frame " + QuoteName(frame.frame_id);
    if (frame.frame_id.empty()) throw InputError(source + ": a frame has an empty id");
    if (!frame_ids.insert(frame.frame_id).second) throw InputError(where + ": duplicate frame id");
    if (frame.cameras.size() != frame.views.size()) {
      throw InputError(where + ": " + std::to_string(frame.views.size()) + " views but " +
                       std::to_string(frame.cameras.size()) + " camera names");
    }
    std::unordered_set<std::string> cameras;
    for (size_t v = 0; v < frame.views.size(); ++v) {
      const std::string view_where = where + ", camera " + QuoteName(frame.cameras[v]);
      if (frame.cameras[v].empty()) throw InputError(where + ": view " + std::to_string(v) + " has no camera name");
      if (!cameras.insert(frame.cameras[v]).second) throw InputError(view_where + ": camera appears twice");
      const Poses2D& view = frame.views[v];
      if (view.data.empty()) continue;
      if (view.num_joints != num_joints || view.data.size() % (3 * static_cast<size_t>(num_joints)) != 0) {
        throw InputError(view_where + ": " + std::to_string(view.num_joints) + " joints, expected " +
                         std::to_string(num_joints));
      }
      for (size_t i = 0; i < view.data.size(); i += 3) {
        const double score = view.data[i + 2];
        const std::string what = view_where + ", person " + std::to_string(i / 3 / num_joints) + ", joint '" +
                                 detections.joints[(i / 3) % num_joints] + "'";
        if (!std::isfinite(view.data[i]) || !std::isfinite(view.data[i + 1]) || !std::isfinite(score)) {
          throw InputError(what + ": NaN or infinity");
        }
        if (score < 0 || score > 1) throw InputError(what + ": score " + std::to_string(score) + " outside [0, 1]");
      }
    }
  }
}

Detections ReadGenericDetections(const std::filesystem::path& path) {
  const std::string source = Source(path);
  const json root = io::LoadJsonFile(path);
  if (!root.is_object()) {
    Fail(source, "/", "expected an object {\"joints\": [...], \"frames\": [...]}, got " + std::string(root.type_name()));
  }
  if (!root.contains("frames") && root.contains("people")) {
    throw InputError(source + ": this is a single OpenPose file; give the folder holding all OpenPose files instead");
  }
  if (!root.contains("joints")) {  // another tool's JSON object: say what is read instead
    const bool mmpose = root.contains("instance_info") || root.contains("meta_info");
    throw InputError(source + ": /joints: missing: not rpt's generic detections {\"joints\", \"frames\"}" +
                     (mmpose ? std::string(" (an MMPose inferencer predictions file? rpt reads MMPose output as a COCO "
                                           "result list [{\"image_id\", \"category_id\", \"keypoints\", "
                                           "\"score\"}]: convert its instance_info to one)")
                            : std::string()) +
                     "; supported:\n" + SupportedDetectionFormats());
  }
  Detections detections;
  detections.unlisted_cameras_unavailable = true;  // "views" lists the cameras processed in the frame
  const json& joints = io::JsonAt(root, "/joints", source);
  if (!joints.is_array()) Fail(source, "/joints", "expected a list of joint names");
  for (size_t j = 0; j < joints.size(); ++j) {
    if (!joints[j].is_string()) Fail(source, io::JsonPointerJoin("/joints", j), "expected a joint name (string)");
    detections.joints.push_back(joints[j].get<std::string>());
  }
  CheckJointNames(detections.joints, source + ": /joints");
  const int num_joints = static_cast<int>(detections.joints.size());

  generic_internal::UnknownKeys unknown_top({"joints", "frames"});
  generic_internal::UnknownKeys unknown_frame({"id", "time", "views"});
  generic_internal::UnknownKeys unknown_view({"camera", "poses"});
  unknown_top.Count(root);
  const json& frames = io::JsonAt(root, "/frames", source);
  if (!frames.is_array()) Fail(source, "/frames", "expected a list of frames, got " + std::string(frames.type_name()));
  detections.frames.reserve(frames.size());
  std::unordered_map<std::string, size_t> frame_of_id;
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::string pointer = io::JsonPointerJoin("/frames", f);
    if (!frames[f].is_object()) Fail(source, pointer, "expected a frame object");
    unknown_frame.Count(frames[f]);
    FrameDetections& frame = detections.frames.emplace_back();
    frame.frame_id = generic_internal::IdString(root, pointer + "/id", source);
    if (const auto [it, fresh] = frame_of_id.emplace(frame.frame_id, f); !fresh) {
      Fail(source, pointer + "/id", "frame id " + QuoteName(frame.frame_id) + " also used by /frames/" + std::to_string(it->second));
    }
    // "time": seconds, as in the live lines; null or absent = not given.
    if (const auto time = frames[f].find("time"); time != frames[f].end() && !time->is_null()) {
      if (!time->is_number()) Fail(source, pointer + "/time", "expected the time in seconds (a number) or null");
      frame.time_s = time->get<double>();
      if (!std::isfinite(frame.time_s)) Fail(source, pointer + "/time", "must be finite");
    }
    const auto views_it = frames[f].find("views");
    if (views_it == frames[f].end()) Fail(source, pointer + "/views", "missing");
    const json& views = *views_it;
    if (!views.is_array()) Fail(source, pointer + "/views", "expected a list of views");
    io::CheckCameraCount(views.size(), source + ": " + pointer + "/views");
    std::unordered_set<std::string> cameras;
    for (size_t v = 0; v < views.size(); ++v) {
      const std::string view_pointer = io::JsonPointerJoin(pointer + "/views", v);
      if (!views[v].is_object()) Fail(source, view_pointer, "expected {\"camera\": ..., \"poses\": [...]}");
      unknown_view.Count(views[v]);
      std::string camera = io::JsonString(root, view_pointer + "/camera", source);
      if (camera.empty()) Fail(source, view_pointer + "/camera", "empty camera name");
      if (!cameras.insert(camera).second) Fail(source, view_pointer + "/camera", "camera " + QuoteName(camera) + " appears twice in this frame");
      const auto poses = views[v].find("poses");
      if (poses == views[v].end()) Fail(source, view_pointer + "/poses", "missing (write [] for no detections)");
      frame.cameras.push_back(std::move(camera));
      ParsePoses(*poses, view_pointer + "/poses", source, num_joints, &frame.views.emplace_back(), &detections.warnings);
    }
  }
  unknown_top.Report(source, "top-level objects", &detections.warnings);
  unknown_frame.Report(source, "frames", &detections.warnings);
  unknown_view.Report(source, "views", &detections.warnings);
  return detections;
}

int WriteGenericDetections(const std::filesystem::path& path, const Detections& given) {
  // "views" lists the cameras processed for a frame: cameras that saw nobody are written with [].
  const std::unique_ptr<Detections> normalised = WithUnlistedCamerasUnavailable(given);
  const Detections& detections = normalised ? *normalised : given;
  const std::string source = Source(path);
  ValidateDetections(detections, source + ": cannot write");
  const int num_joints = static_cast<int>(detections.joints.size());
  // Written by hand: one frame per line, numbers in nlohmann's shortest round-trip form.
  int replaced = 0;  // strings with invalid UTF-8, written as U+FFFD
  std::string text = "{\"joints\": " + io::DumpJson(json(detections.joints), -1, &replaced) + ",\n\"frames\": [\n";
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    json views = json::array();
    for (size_t v = 0; v < frame.views.size(); ++v) {
      const Poses2D& view = frame.views[v];
      json poses = json::array();
      for (int p = 0; p < view.num_persons(); ++p) {
        const auto person = view.Person(p);
        json joints = json::array();
        for (int j = 0; j < num_joints; ++j) joints.push_back({person(0, j), person(1, j), person(2, j)});
        poses.push_back(std::move(joints));
      }
      views.push_back({{"camera", frame.cameras[v]}, {"poses", std::move(poses)}});
    }
    json frame_json = {{"id", frame.frame_id}, {"views", std::move(views)}};
    if (std::isfinite(frame.time_s)) frame_json["time"] = frame.time_s;
    text += io::DumpJson(frame_json, -1, &replaced);
    text += f + 1 < detections.frames.size() ? ",\n" : "\n";
  }
  text += "]}\n";
  io::WriteTextFile(path, io::NamedBy::kUser, text);
  return replaced;
}

}  // namespace rpt
