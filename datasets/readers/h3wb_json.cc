// SPDX-License-Identifier: MIT
// H3WB json annotations (streamed with a SAX parser) -> clips (datasets/readers/h3wb_internal.h).
#include "datasets/readers/h3wb_internal.h"

#include <Eigen/Core>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/io/npy.h"
#include "datasets/readers/h36m_ego_common.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/human36m_internal.h"
#include "core/printable_text.h"

namespace rpt::h3wb {
namespace {

using h36m_ego::PathName;

// Camera-frame metres -> world metres.
Eigen::Vector3d ToWorld(const Camera& camera, const Eigen::Vector3d& x_cam_m) { return camera.R.transpose() * (x_cam_m - camera.t); }

// ---------------------------------------------------------------------------------------
// json

struct ImagePathInfo {
  std::string subject;
  std::string action;
  int camera = -1;
  long long frame = 0;
};

// "<...>/S8/Images/Directions 1.54138969/frame_0012.jpg" -> S8, Directions-1, camera 0, 12.
std::optional<ImagePathInfo> ParseImagePath(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : path) {
    if (c == '/' || c == '\\') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  if (!part.empty()) parts.push_back(part);
  if (parts.size() < 3) return std::nullopt;
  ImagePathInfo info;
  // Frame: trailing digits of the file stem.
  const std::string stem = fs::path(parts.back()).stem().string();
  std::size_t digits = stem.size();
  while (digits > 0 && stem[digits - 1] >= '0' && stem[digits - 1] <= '9') --digits;
  if (digits == stem.size() || stem.size() - digits > 12) return std::nullopt;
  info.frame = std::stoll(stem.substr(digits));
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string& p = parts[i];
    if (p.size() >= 2 && p[0] == 'S' && std::all_of(p.begin() + 1, p.end(), [](char c) { return c >= '0' && c <= '9'; })) info.subject = p;
    const std::size_t dot = p.rfind('.');
    if (dot != std::string::npos && dot > 0) {
      const int camera = h36m_ego::H36mCameraIndex(std::string_view(p).substr(dot + 1));
      if (camera >= 0) {
        info.camera = camera;
        info.action = h36m_ego::SanitizeName(p.substr(0, dot));
      }
    }
  }
  if (info.subject.empty() || info.camera < 0) return std::nullopt;
  return info;
}

struct JsonSample {
  long long id = 0;
  std::string key;
  Eigen::Matrix3Xd camera_mm;  // 3 x 133, camera coordinates
  std::optional<Eigen::Matrix2Xd> pose_2d;
  std::optional<ImagePathInfo> path;
};

// Streams the json (files reach ~1 GB; a DOM would need several times that) and keeps per sample
// only keypoints_3d, keypoints_2d (when wanted) and image_path. Errors name the JSON pointer.
class SampleSax final : public nlohmann::json_sax<nlohmann::json> {
 public:
  SampleSax(fs::path file, bool want_2d, std::vector<JsonSample>* out)
      : file_(std::move(file)), source_(PathName(file_)), want_2d_(want_2d), out_(out) {}

  bool null() override { return Value(false, 0); }
  bool boolean(bool) override { return Value(false, 0); }
  bool number_integer(number_integer_t v) override { return Value(true, static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return Value(true, static_cast<double>(v)); }
  bool number_float(number_float_t v, const string_t&) override { return Value(true, v); }
  bool binary(binary_t&) override { return Value(false, 0); }
  bool string(string_t& text) override {
    if (depth_ == 2 && field_ == "image_path") image_path_ = text;
    return Value(false, 0);
  }

  bool start_object(std::size_t) override {
    if (depth_ == 1) {
      StartSample();
    } else if (depth_ == 2 && KeypointsField() > 0) {
      kp_ = KeypointsField();
      (kp_ == 3 ? has_3d_ : has_2d_) = true;
    } else if (depth_ == 3 && kp_ > 0) {
      joint_ = JointIndex(joint_key_);
      if (joint_ >= 0) (kp_ == 3 ? joint_seen_3d_ : joint_seen_2d_)[static_cast<std::size_t>(joint_)] = 1;
    }
    ++depth_;
    return true;
  }
  bool start_array(std::size_t) override {
    NotAnObject();
    ++depth_;
    return true;
  }
  bool key(string_t& k) override {
    if (depth_ == 1) sample_key_ = k;
    if (depth_ == 2) field_ = k;
    if (depth_ == 3) joint_key_ = k;
    if (depth_ == 4) axis_ = k;
    return true;
  }
  bool end_object() override { return End(); }
  bool end_array() override { return End(); }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    // Line and column of the byte offset, for the message.
    std::ifstream in(file_, std::ios::binary);
    std::size_t line = 1, column = 1, offset = 0;
    char c;
    while (offset + 1 < position && in.get(c)) {
      ++offset;
      if (c == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string msg = e.what();
    if (const auto p = msg.find(": "); p != std::string::npos && msg.rfind("[json.exception", 0) == 0) msg = msg.substr(p + 2);
    throw InputError(source_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": JSON parse error: " + msg);
  }

 private:
  // 3 = keypoints_3d, 2 = keypoints_2d (when wanted), 0 = another field.
  int KeypointsField() const { return field_ == "keypoints_3d" ? 3 : (want_2d_ && field_ == "keypoints_2d") ? 2 : 0; }

  static int JointIndex(const std::string& text) {
    int value = -1;
    return io::ParseInteger(text, &value) && value >= 0 && value < kJoints ? value : -1;
  }

  std::string Pointer(int levels) const {
    std::string p;
    if (levels >= 1) p = io::JsonPointerJoin(p, sample_key_);
    if (levels >= 2) p = io::JsonPointerJoin(p, field_);
    if (levels >= 3) p = io::JsonPointerJoin(p, joint_key_);
    if (levels >= 4) p = io::JsonPointerJoin(p, axis_);
    return p;
  }
  [[noreturn]] void Fail(const std::string& pointer, const std::string& what) const {
    throw InputError(source_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  // A scalar or array where an object is required.
  void NotAnObject() const {
    if (depth_ == 0) Fail("", "expected an object keyed by sample id");
    if (depth_ == 1) Fail(Pointer(1), "expected an object");
    if (depth_ == 2 && KeypointsField() > 0) Fail(Pointer(2), "missing or not an object");
    if (depth_ == 3 && kp_ > 0) Fail(Pointer(3), "expected an object {x, y" + std::string(kp_ == 3 ? ", z}" : "}"));
  }

  bool Value(bool is_number, double value) {
    if (depth_ != 4) {
      NotAnObject();
      return true;
    }
    if (kp_ == 0 || joint_ < 0) return true;
    const int axis = axis_ == "x" ? 0 : axis_ == "y" ? 1 : axis_ == "z" ? 2 : -1;
    if (axis < 0 || axis >= kp_) return true;
    if (!is_number) Fail(Pointer(4), "expected a number");
    if (!std::isfinite(value)) Fail(Pointer(4), "NaN or infinite");
    if (kp_ == 3) {
      sample_.camera_mm(axis, joint_) = value;
      set_3d_[static_cast<std::size_t>(3 * joint_ + axis)] = 1;
    } else {
      pose_2d_(axis, joint_) = value;
      set_2d_[static_cast<std::size_t>(2 * joint_ + axis)] = 1;
    }
    return true;
  }

  void StartSample() {
    sample_ = JsonSample();
    sample_.key = sample_key_;
    if (!io::ParseInteger(sample_key_, &sample_.id) || sample_.id < 0) {
      Fail(Pointer(1), "sample id is not a non-negative integer");
    }
    sample_.camera_mm.setZero(3, kJoints);
    pose_2d_.setZero(2, kJoints);
    has_3d_ = has_2d_ = false;
    joint_seen_3d_.assign(kJoints, 0);
    joint_seen_2d_.assign(kJoints, 0);
    set_3d_.assign(3 * kJoints, 0);
    set_2d_.assign(2 * kJoints, 0);
    image_path_.clear();
    field_.clear();
  }

  // Checks that every joint of a keypoints field was given; `dims` = 3 or 2.
  void CheckComplete(const std::string& field, int dims, const std::vector<std::uint8_t>& seen, const std::vector<std::uint8_t>& set) const {
    static const char* kAxes[] = {"x", "y", "z"};
    const std::string base = io::JsonPointerJoin(io::JsonPointerJoin("", sample_key_), field);
    for (int j = 0; j < kJoints; ++j) {
      const std::string joint = io::JsonPointerJoin(base, std::to_string(j));
      if (!seen[static_cast<std::size_t>(j)]) Fail(joint, "missing joint");
      for (int d = 0; d < dims; ++d) {
        if (!set[static_cast<std::size_t>(dims * j + d)]) Fail(io::JsonPointerJoin(joint, kAxes[d]), "expected a number");
      }
    }
  }

  bool End() {
    --depth_;
    if (depth_ == 3) joint_ = -1;
    if (depth_ == 2) kp_ = 0;
    if (depth_ == 1) {  // end of a sample
      if (!has_3d_) Fail(io::JsonPointerJoin(Pointer(1), "keypoints_3d"), "missing or not an object");
      CheckComplete("keypoints_3d", 3, joint_seen_3d_, set_3d_);
      if (has_2d_) {
        CheckComplete("keypoints_2d", 2, joint_seen_2d_, set_2d_);
        sample_.pose_2d = pose_2d_;
      }
      if (!image_path_.empty()) sample_.path = ParseImagePath(image_path_);
      out_->push_back(std::move(sample_));
    }
    return true;
  }

  fs::path file_;
  std::string source_;
  bool want_2d_;
  std::vector<JsonSample>* out_;
  int depth_ = 0;
  std::string sample_key_, field_, joint_key_, axis_, image_path_;
  int kp_ = 0;
  int joint_ = -1;
  JsonSample sample_;
  Eigen::Matrix2Xd pose_2d_;
  bool has_3d_ = false, has_2d_ = false;
  std::vector<std::uint8_t> joint_seen_3d_, joint_seen_2d_, set_3d_, set_2d_;
};

std::vector<JsonSample> ReadJsonSamples(const fs::path& file, bool want_2d) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(PathName(file) + ": file not found or unreadable");
  std::vector<JsonSample> out;
  SampleSax sax(file, want_2d, &out);
  nlohmann::json::sax_parse(in, &sax);
  std::sort(out.begin(), out.end(), [](const JsonSample& a, const JsonSample& b) { return a.id < b.id; });
  return out;
}

struct JsonGroup {
  std::string subject;  // empty until known
  std::string action;
  long long number = 0;
  std::vector<std::pair<int, const JsonSample*>> views;  // (camera index, sample)
};

std::string GroupName(const JsonGroup& g) {
  std::string ids;
  for (const auto& [c, s] : g.views) ids += (ids.empty() ? "" : ", ") + s->key;
  return "samples " + ids;
}

// Largest distance between the views' world poses; world pose of the first view in *world_m.
double ViewDisagreement(const JsonGroup& group, const std::vector<Camera>& cameras, Eigen::Matrix3Xd* world_m) {
  double worst = 0;
  Eigen::Matrix3Xd first(3, kJoints);
  for (std::size_t v = 0; v < group.views.size(); ++v) {
    const Camera& camera = cameras[static_cast<std::size_t>(group.views[v].first)];
    for (int j = 0; j < kJoints; ++j) {
      const Eigen::Vector3d x = ToWorld(camera, group.views[v].second->camera_mm.col(j) / 1000.0);
      if (v == 0) {
        first.col(j) = x;
      } else {
        worst = std::max(worst, (x - first.col(j)).norm());
      }
    }
  }
  if (world_m) *world_m = first;
  return worst;
}

}  // namespace

std::vector<Clip> ReadJsonClips(const Options& options, bool want_2d) {
  const std::string source = PathName(options.file);
  // The parsed samples stay for the clips' frames, converted when they are pulled.
  const auto samples_ptr = std::make_shared<const std::vector<JsonSample>>(ReadJsonSamples(options.file, want_2d));
  const std::vector<JsonSample>& samples = *samples_ptr;
  if (samples.empty()) throw InputError(source + ": no samples");
  const bool by_path = std::all_of(samples.begin(), samples.end(), [](const JsonSample& s) { return s.path.has_value(); });
  if (!by_path && !options.actions.empty()) {
    throw ConfigError("h3wb: actions: this json has no parseable image_path, so its frames carry no action");
  }

  // Cameras per subject, loaded on demand from the cameras file.
  fs::path cameras_file;
  if (options.cameras_file == "auto") {
    const fs::path dir = fs::is_regular_file(options.root) ? options.root.parent_path() : options.root;
    for (const fs::path& p : {dir / "metadata.xml", dir / "cameras.pkl", options.file.parent_path() / "metadata.xml",
                              options.file.parent_path() / "cameras.pkl"}) {
      if (fs::is_regular_file(p)) {
        cameras_file = p;
        break;
      }
    }
    if (cameras_file.empty()) {
      throw InputError(PathName(dir) + ": the json format needs Human3.6M cameras: no metadata.xml or cameras.pkl found (pass --param cameras_file=PATH)");
    }
  } else {
    cameras_file = h36m_ego::ResolveUnder(options.root, options.cameras_file);
  }
  std::map<std::string, std::optional<std::vector<Camera>>> camera_cache;
  // Corrections of each subject's cameras, taken over by the subject's first clip (cameras tried
  // only to identify a subject are not counted).
  std::map<std::string, InputWarnings> camera_warnings;
  auto cameras_of = [&](const std::string& subject, bool required) -> const std::vector<Camera>* {
    auto it = camera_cache.find(subject);
    if (it == camera_cache.end()) {
      std::optional<std::vector<Camera>> cams;
      try {
        cams = ReadHuman36mCameras(cameras_file, subject, options.model, &camera_warnings[subject]);
      } catch (const InputError&) {
        if (required) throw;
      }
      it = camera_cache.emplace(subject, std::move(cams)).first;
    }
    if (!it->second && required) it->second = ReadHuman36mCameras(cameras_file, subject, options.model);  // throws the reason
    return it->second ? &*it->second : nullptr;
  };

  // Group the views into frames.
  std::map<std::tuple<std::string, std::string, long long>, JsonGroup> groups;
  for (const JsonSample& s : samples) {
    JsonGroup key_group;
    int camera = 0;
    std::tuple<std::string, std::string, long long> key;
    if (by_path) {
      if (std::find(options.subjects.begin(), options.subjects.end(), s.path->subject) == options.subjects.end()) continue;
      if (!ActionMatches(s.path->action, options.actions)) continue;
      key = {s.path->subject, s.path->action, s.path->frame};
      camera = s.path->camera;
    } else {
      key = {"", "json", (s.id / 4) * 4};
      camera = static_cast<int>(s.id % 4);
    }
    JsonGroup& group = groups[key];
    group.subject = std::get<0>(key);
    group.action = std::get<1>(key);
    group.number = std::get<2>(key);
    for (const auto& [c, other] : group.views) {
      if (c == camera) {
        throw InputError(source + ": samples " + other->key + " and " + s.key + " are both camera " +
                         Human36mCameraIds()[static_cast<std::size_t>(c)] + " of the same frame");
      }
    }
    group.views.emplace_back(camera, &s);
  }

  // Per clip, its frames (groups) in frame-number order (the groups' map order).
  std::map<std::pair<std::string, std::string>, Clip> clips;
  std::map<std::pair<std::string, std::string>, std::vector<const JsonGroup*>> clip_groups;
  std::set<std::string> seen_subjects;
  if (by_path) {
    for (const JsonSample& s : samples) seen_subjects.insert(s.path->subject);
  }
  for (auto& [key, group] : groups) {
    std::sort(group.views.begin(), group.views.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (!group.subject.empty()) {
      cameras_of(group.subject, true);  // the views must agree: checked when the frame is converted
    } else if (group.views.size() == 1) {
      if (options.subjects.size() != 1) {
        throw InputError(source + ": " + GroupName(group) + ": a single view cannot tell its subject; select exactly one subject");
      }
      group.subject = options.subjects.front();
      cameras_of(group.subject, true);
    } else {
      // Subject = the one whose cameras make the views agree.
      double best = std::numeric_limits<double>::infinity();
      std::string best_subject;
      for (const std::string& subject : kCandidateSubjects) {
        const std::vector<Camera>* cameras = cameras_of(subject, false);
        if (!cameras) continue;
        const double d = ViewDisagreement(group, *cameras, nullptr);
        if (d < best) best = d, best_subject = subject;
      }
      if (!(best <= h36m_ego::kViewAgreementToleranceM)) {
        std::ostringstream msg;
        msg << source << ": " << GroupName(group) << ": the views do not agree in world coordinates for any subject's cameras";
        if (!best_subject.empty()) msg << " (best " << best_subject << ": " << best * 1000.0 << " mm)";
        msg << "; are ids 4k..4k+3 the four views of one frame?";
        throw InputError(msg.str());
      }
      group.subject = best_subject;
    }
    seen_subjects.insert(group.subject);
    if (std::find(options.subjects.begin(), options.subjects.end(), group.subject) == options.subjects.end()) continue;
    Clip& clip = clips[{group.subject, group.action}];
    if (clip.subject.empty()) {
      clip.subject = group.subject;
      clip.action = group.action;
      clip.sample_ids = !by_path;
      clip.cameras = *cameras_of(group.subject, true);
      clip.source = source;
      clip.warnings = std::exchange(camera_warnings[group.subject], InputWarnings{});
    }
    clip_groups[{group.subject, group.action}].push_back(&group);
  }

  auto shared_groups =
      std::make_shared<const decltype(groups)>(std::move(groups));  // the JsonGroups stay where they are
  std::vector<Clip> out;
  for (const std::string& subject : options.subjects) {
    bool any = false;
    for (auto& [key, clip] : clips) {
      if (key.first != subject) continue;
      any = true;
      std::vector<const JsonGroup*>& frames = clip_groups[key];
      std::stable_sort(frames.begin(), frames.end(),
                       [](const JsonGroup* a, const JsonGroup* b) { return a->number < b->number; });
      std::vector<const JsonGroup*> kept;
      for (const std::size_t k : h36m_ego::SelectFrames(frames.size(), options.every, options.max_frames)) {
        kept.push_back(frames[k]);
        clip.numbers.push_back(frames[k]->number);
      }
      clip.convert = [samples_ptr, shared_groups, kept, cameras = clip.cameras, source,
                      cameras_file = cameras_file.string()](std::size_t i, Eigen::Matrix3Xd* world_m,
                                                            std::vector<std::optional<Eigen::Matrix2Xd>>* pose_2d) {
        const JsonGroup& group = *kept[i];
        const double disagreement = ViewDisagreement(group, cameras, world_m);
        if (!(disagreement <= h36m_ego::kViewAgreementToleranceM)) {
          std::ostringstream msg;
          msg << source << ": " << GroupName(group) << " (" << group.subject << " " << group.action << " frame "
              << group.number << "): the views disagree by " << disagreement * 1000.0
              << " mm in world coordinates (cameras from " << cameras_file << ")";
          throw InputError(msg.str());
        }
        pose_2d->assign(cameras.size(), std::nullopt);
        for (const auto& [c, s] : group.views) (*pose_2d)[static_cast<std::size_t>(c)] = s->pose_2d;
      };
      out.push_back(std::move(clip));
    }
    if (!any && seen_subjects.count(subject)) throw InputError(source + ": no frames of subject " + subject + " with the selected actions");
    if (!any) {
      std::string known;
      for (const std::string& s : seen_subjects) known += (known.empty() ? "" : ", ") + s;
      throw InputError(source + ": unknown subject " + QuoteName(subject) + " (file has " + (known.empty() ? "none" : known) + ")");
    }
  }
  return out;
}

}  // namespace rpt::h3wb
