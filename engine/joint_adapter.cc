// SPDX-License-Identifier: MIT
#include "engine/joint_adapter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/body_frame.h"
#include "core/closest_name.h"
#include "core/option_codec.h"
#include "core/errors.h"
#include "core/text.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/text_file.h"
#include "core/printable_text.h"

namespace rpt::engine {
namespace {

using Json = nlohmann::json;

constexpr const char* kAdapterFormat = "rpt joint adapter";
constexpr int kAdapterVersion = 1;
constexpr const char* kBodyFrameText =
    "origin mid-hip; x toward the person's right (hips + shoulders), z up the spine (orthogonal to x), "
    "y = z cross x, forward; metres";
const std::vector<std::string> kAdapterKeys = {"format", "version", "kind", "body_frame", "statistic", "joints", "fit"};
const std::vector<std::string> kAdapterJointKeys = {"name", "offset_m", "samples", "spread_m"};
const std::vector<std::string> kAdapterFitKeys = {"dataset", "root",  "params", "sequences", "frames",
                                                  "matched_persons", "persons_without_body_frame", "min_samples",
                                                  "frame_ids", "first_frame", "last_frame", "command",
                                                  "git_revision"};

// Checks one adapter file; every error names the file and the JSON path.
class AdapterValidator {
 public:
  explicit AdapterValidator(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void Fail(const std::string& where, const std::string& what) const {
    throw InputError(path_ + ": " + (where.empty() ? "/" : where) + ": " + what);
  }
  static std::string Describe(const Json& value) { return std::string(value.type_name()) + " " + io::JsonExcerpt(value); }

  void Keys(const Json& object, const std::string& where, const std::vector<std::string>& known) const {
    if (!object.is_object()) Fail(where, "expected an object, got " + Describe(object));
    for (const auto& [key, value] : object.items()) {
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        Fail(io::JsonPointerJoin(where, key), "unknown key " + QuoteName(key) + DidYouMean(key, known));
      }
    }
  }
  const Json& Required(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.contains(key)) Fail(where, "missing \"" + key + "\"");
    return object[key];
  }
  std::string String(const Json& value, const std::string& where) const {
    if (!value.is_string()) Fail(where, "expected a string, got " + Describe(value));
    return value.get<std::string>();
  }
  long Count(const Json& value, const std::string& where) const {
    const std::optional<std::int64_t> n = io::JsonToInt64(value);
    if (!value.is_number() || !n || *n < 0 || *n > std::numeric_limits<long>::max()) {
      Fail(where, "expected a non-negative integer, got " + Describe(value));
    }
    return static_cast<long>(*n);
  }
  std::vector<std::string> Strings(const Json& value, const std::string& where) const {
    if (!value.is_array()) Fail(where, "expected a list of strings, got " + Describe(value));
    std::vector<std::string> out;
    for (size_t i = 0; i < value.size(); ++i) out.push_back(String(value[i], io::JsonPointerJoin(where, i)));
    return out;
  }

 private:
  std::string path_;
};

Json OffsetJson(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

}  // namespace

const char* OffsetStatisticName(OffsetStatistic statistic) {
  return statistic == OffsetStatistic::kMean ? "mean" : "median";
}

std::string JointAdapter::Name() const { return path.empty() ? "the adapter" : "the adapter " + QuoteName(path); }

JointAdapter ReadJointAdapter(const std::filesystem::path& path) {
  const std::string source = path.string();
  const Json root = io::LoadJsonFile(path);
  const AdapterValidator v(source);
  v.Keys(root, "", kAdapterKeys);
  JointAdapter adapter;
  adapter.path = source;
  if (v.String(v.Required(root, "format", ""), "/format") != kAdapterFormat) {
    v.Fail("/format", std::string("expected \"") + kAdapterFormat + "\" (a file written by `rpt fit-adapter`)");
  }
  if (v.Count(v.Required(root, "version", ""), "/version") != kAdapterVersion) {
    v.Fail("/version", "this rpt reads version " + std::to_string(kAdapterVersion));
  }
  if (root.contains("kind") && v.String(root["kind"], "/kind") != "body_frame_offsets") {
    v.Fail("/kind", "expected \"body_frame_offsets\" (the only kind of adapter)");
  }
  if (root.contains("body_frame")) v.String(root["body_frame"], "/body_frame");
  if (root.contains("statistic")) {
    const std::string statistic = v.String(root["statistic"], "/statistic");
    if (statistic != "mean" && statistic != "median") v.Fail("/statistic", "expected \"mean\" or \"median\"");
    adapter.statistic = statistic == "mean" ? OffsetStatistic::kMean : OffsetStatistic::kMedian;
  }

  const Json& joints = v.Required(root, "joints", "");
  if (!joints.is_array() || joints.empty()) v.Fail("/joints", "expected a non-empty list of joints");
  for (size_t i = 0; i < joints.size(); ++i) {
    const std::string where = io::JsonPointerJoin("/joints", i);
    const Json& joint = joints[i];
    v.Keys(joint, where, kAdapterJointKeys);
    const std::string name = v.String(v.Required(joint, "name", where), where + "/name");
    if (name.empty()) v.Fail(where + "/name", "empty joint name");
    if (FindJoint(adapter.joints, name) >= 0) v.Fail(where + "/name", "joint " + QuoteName(name) + " appears twice");
    const Json& offset = v.Required(joint, "offset_m", where);
    if (!offset.is_array() || offset.size() != 3) {
      v.Fail(where + "/offset_m", "expected 3 numbers (x right, y forward, z up; metres), got " +
                                      AdapterValidator::Describe(offset));
    }
    Eigen::Vector3d value;
    for (int k = 0; k < 3; ++k) {
      const std::string at = io::JsonPointerJoin(where + "/offset_m", static_cast<size_t>(k));
      if (!offset[k].is_number()) v.Fail(at, "expected a number, got " + AdapterValidator::Describe(offset[k]));
      value(k) = offset[k].get<double>();
      if (!std::isfinite(value(k)) || std::abs(value(k)) > kMaxJointOffsetM) {
        v.Fail(at, "an offset of at most " + FormatNumber(kMaxJointOffsetM) + " m per axis, got " +
                       AdapterValidator::Describe(offset[k]));
      }
    }
    adapter.joints.push_back(name);
    adapter.offset_m.push_back(value);
    adapter.samples.push_back(joint.contains("samples") ? v.Count(joint["samples"], where + "/samples") : 0);
    double spread = std::numeric_limits<double>::quiet_NaN();
    if (joint.contains("spread_m") && !joint["spread_m"].is_null()) {
      if (!joint["spread_m"].is_number()) {
        v.Fail(where + "/spread_m", "expected a number, got " + AdapterValidator::Describe(joint["spread_m"]));
      }
      spread = joint["spread_m"].get<double>();
    }
    adapter.spread_m.push_back(spread);
  }

  const Json& fit = v.Required(root, "fit", "");
  v.Keys(fit, "/fit", kAdapterFitKeys);
  JointAdapterFitInfo& info = adapter.fit;
  const auto text = [&](const char* key) { return fit.contains(key) ? v.String(fit[key], "/fit/" + std::string(key)) : ""; };
  const auto count = [&](const char* key) { return fit.contains(key) ? v.Count(fit[key], "/fit/" + std::string(key)) : 0L; };
  info.dataset = text("dataset");
  info.root = text("root");
  info.command = text("command");
  info.git_revision = text("git_revision");
  if (fit.contains("params")) info.params = v.Strings(fit["params"], "/fit/params");
  if (fit.contains("sequences")) info.sequences = v.Strings(fit["sequences"], "/fit/sequences");
  info.frames = count("frames");
  info.matched_persons = count("matched_persons");
  info.persons_without_body_frame = count("persons_without_body_frame");
  info.min_samples = count("min_samples");
  // The frames it was fitted on are what keeps it off them: required.
  info.frame_ids = v.Strings(v.Required(fit, "frame_ids", "/fit"), "/fit/frame_ids");
  if (static_cast<long>(info.frame_ids.size()) != info.frames) {
    v.Fail("/fit/frame_ids", std::to_string(info.frame_ids.size()) + " frame ids, but \"frames\" says " +
                                 std::to_string(info.frames));
  }
  adapter.Index();
  return adapter;
}

nlohmann::ordered_json JointAdapterJson(const JointAdapter& adapter, bool with_frame_ids) {
  using Ordered = nlohmann::ordered_json;
  Ordered out;
  out["format"] = kAdapterFormat;
  out["version"] = kAdapterVersion;
  if (!adapter.path.empty() && !with_frame_ids) out["file"] = adapter.path;
  out["kind"] = "body_frame_offsets";
  out["body_frame"] = kBodyFrameText;
  out["statistic"] = OffsetStatisticName(adapter.statistic);
  Ordered joints = Ordered::array();
  for (size_t j = 0; j < adapter.joints.size(); ++j) {
    Ordered joint;
    joint["name"] = adapter.joints[j];
    joint["offset_m"] = OffsetJson(adapter.offset_m[j]);
    joint["samples"] = j < adapter.samples.size() ? adapter.samples[j] : 0;
    const double spread = j < adapter.spread_m.size() ? adapter.spread_m[j] : std::nan("");
    joint["spread_m"] = std::isfinite(spread) ? Ordered(spread) : Ordered(nullptr);
    joints.push_back(joint);
  }
  out["joints"] = joints;
  const JointAdapterFitInfo& fit = adapter.fit;
  Ordered f;
  f["dataset"] = fit.dataset;
  f["root"] = fit.root;
  f["params"] = fit.params;
  f["sequences"] = fit.sequences;
  f["frames"] = fit.frames;
  f["matched_persons"] = fit.matched_persons;
  f["persons_without_body_frame"] = fit.persons_without_body_frame;
  f["min_samples"] = fit.min_samples;
  if (with_frame_ids) {
    f["frame_ids"] = fit.frame_ids;
  } else if (!fit.frame_ids.empty()) {
    f["first_frame"] = fit.frame_ids.front();
    f["last_frame"] = fit.frame_ids.back();
  }
  f["command"] = fit.command;
  f["git_revision"] = fit.git_revision;
  out["fit"] = f;
  return out;
}

void WriteJointAdapter(const std::filesystem::path& path, const JointAdapter& adapter) {
  io::WriteTextFile(path, io::NamedBy::kUser, io::DumpJson(JointAdapterJson(adapter, true), 2) + "\n");
}

std::string FitDescription(const JointAdapterFitInfo& fit) {
  std::string text = fit.dataset.empty() ? "input" : fit.dataset;
  for (const std::string& param : fit.params) text += " " + param;
  text += ": " + std::to_string(fit.frames) + " frames";
  if (!fit.frame_ids.empty()) text += " (" + QuoteName(fit.frame_ids.front()) + " to " + QuoteName(fit.frame_ids.back()) + ")";
  text += ", " + std::to_string(fit.matched_persons) + " matched persons";
  return text;
}

void CheckAdapterJoints(const JointAdapter& adapter, const JointNames& joints) {
  const std::string where = adapter.path.empty() ? "joint adapter" : adapter.path;
  if (adapter.joints != joints) {
    std::string difference;
    const size_t n = std::min(adapter.joints.size(), joints.size());
    for (size_t j = 0; j < n && difference.empty(); ++j) {
      if (adapter.joints[j] != joints[j]) {
        difference = "joint " + std::to_string(j) + " (/joints/" + std::to_string(j) + "/name) is '" +
                     adapter.joints[j] + "', the predictions' is " + QuoteName(joints[j]);
      }
    }
    if (difference.empty()) {
      difference = "the first " + std::to_string(n) + " joints agree";
    }
    throw ConfigError(where + ": fitted for other joints than the predictions': " + difference + " (" +
                      std::to_string(adapter.joints.size()) + " joints in the adapter, " + std::to_string(joints.size()) +
                      " in the predictions); fit it again with the options of this run");
  }
  if (!BodyFrameJoints::Find(joints).complete()) {
    throw ConfigError(where + ": the predictions lack the hips and shoulders a body frame is built from "
                      "(hip_left, hip_right, shoulder_left, shoulder_right)");
  }
}

}  // namespace rpt::engine
