// SPDX-License-Identifier: MIT
// Human3.6M reader: h36m-fetch annot.h5 (HDF5, camera-frame mm per camera) or the
// learnable-triangulation multi-view labels npy (world mm), with cameras from metadata.xml,
// mmpose cameras.pkl or the labels npy.
#include "datasets/readers/human36m.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/hdf5_file.h"
#include "datasets/io/npy.h"
#include "datasets/readers/h36m_ego_common.h"
#include "datasets/readers/human36m_internal.h"

namespace rpt {
namespace {

using h36m_ego::PathName;

constexpr double kHuman36mFps = 50.0;
constexpr int kNumJoints = 18;  // 17 H36M joints + nose
constexpr int kNoseIndex = 17;
constexpr int kNeckNoseIndex = 9;
constexpr int kHeadIndex = 10;
// Raw 32-joint indices of the first 17 GT joints (Human36mJoints() order).
constexpr std::array<int, 17> kRawIndices = {0, 1, 2, 3, 6, 7, 8, 12, 13, 14, 15, 17, 18, 19, 25, 26, 27};
// learnable-triangulation joint i -> Human36mJoints() index. Their order (raw
// 3,2,1,6,7,8,0,12,13,15,27,26,25,17,18,19,14): RAnkle RKnee RHip LHip LKnee LAnkle Pelvis Spine
// Thorax Head RWrist RElbow RShoulder LShoulder LElbow LWrist Neck/Nose.
constexpr std::array<int, 17> kLearnableTriToJoint = {3, 2, 1, 4, 5, 6, 0, 7, 8, 10, 16, 15, 14, 11, 12, 13, 9};

constexpr const char* kLabelsFileName = "human36m-multiview-labels-GTbboxes.npy";

struct Human36mOptions {
  std::filesystem::path root;
  std::vector<std::string> subjects;
  std::vector<std::string> actions;  // empty = all
  std::vector<std::string> exclude;  // "S9/Greeting-2"
  bool use_npy = false;
  std::filesystem::path labels_file;
  std::filesystem::path cameras_file;  // empty = cameras from the labels npy
  DistortionModel model = DistortionModel::kH36M;
  bool nose_from_head = true;
  int every = 1;
  int max_frames = 0;
};

// "Directions" matches "Directions-1" and "Directions-2"; "Directions-1" only itself.
bool Human36mActionMatches(const std::string& action, const std::string& filter) {
  if (action == filter) return true;
  if (action.size() <= filter.size() + 1 || action.compare(0, filter.size(), filter) != 0 || action[filter.size()] != '-') {
    return false;
  }
  return std::all_of(action.begin() + static_cast<std::ptrdiff_t>(filter.size()) + 1, action.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

bool ActionSelected(const Human36mOptions& options, const std::string& subject, const std::string& action) {
  if (!options.actions.empty() &&
      std::none_of(options.actions.begin(), options.actions.end(),
                   [&](const std::string& f) { return Human36mActionMatches(action, f); })) {
    return false;
  }
  for (const std::string& item : options.exclude) {
    const std::size_t slash = item.find('/');
    const std::string subject_filter = slash == std::string::npos ? "" : item.substr(0, slash);
    const std::string action_filter = slash == std::string::npos ? item : item.substr(slash + 1);
    if ((subject_filter.empty() || subject_filter == subject) && Human36mActionMatches(action, action_filter))
      return false;
  }
  return true;
}

// Every `exclude` entry must name something: an entry for one of the selected subjects (or for
// every subject, without "S9/") that matches none of its actions, or whose subject differs from a
// selected one in case only, is a ConfigError (a typo would exclude nothing, silently). Entries
// for subjects not selected are part of a list for all subjects (learnable-triangulation's).
// `actions`: each selected subject's actions in the data, whatever `actions=` selects.
void CheckExcludes(const Human36mOptions& options, const std::map<std::string, std::vector<std::string>>& actions) {
  const auto lower = [](std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  for (const std::string& item : options.exclude) {
    const std::size_t slash = item.find('/');
    const std::string subject_filter = slash == std::string::npos ? "" : item.substr(0, slash);
    const std::string action_filter = slash == std::string::npos ? item : item.substr(slash + 1);
    bool applies = false, matches = false;
    std::string known;
    for (const auto& [subject, names] : actions) {
      if (!subject_filter.empty() && subject_filter != subject) {
        if (lower(subject_filter) == lower(subject)) {
          throw ConfigError("human36m.exclude: " + QuoteName(item) + ": no subject " + QuoteName(subject_filter) +
                            " (did you mean " + QuoteName(subject) + "?)");
        }
        continue;
      }
      applies = true;
      for (const std::string& action : names) {
        matches = matches || Human36mActionMatches(action, action_filter);
        if (known.size() < 400) known += (known.empty() ? "" : ", ") + action;
      }
    }
    if (applies && !matches) {
      throw ConfigError("human36m.exclude: " + QuoteName(item) + " matches no action of " +
                        (subject_filter.empty() ? std::string("the selected subjects") : subject_filter) +
                        " (actions: " + known + ")");
    }
  }
}

std::optional<std::filesystem::path> FirstExisting(const std::vector<std::filesystem::path>& candidates) {
  for (const auto& p : candidates) {
    if (std::filesystem::is_regular_file(p)) return p;
  }
  return std::nullopt;
}

std::string ListPaths(const std::vector<std::filesystem::path>& paths) {
  std::string out;
  for (const auto& p : paths) out += (out.empty() ? "" : ", ") + p.string();
  return out;
}

Human36mOptions ParseHuman36mOptions(const DatasetRequest& request) {
  const Human36mParams params = ParseDatasetParams<Human36mParams>("human36m", request);
  Human36mOptions o;
  o.root = request.root;
  o.subjects = params.subjects;
  o.actions = params.actions;
  o.exclude = params.exclude;
  o.model = ToDistortionModel(params.distortion);
  o.nose_from_head = params.nose_proxy == H36mNoseProxy::kHead;
  o.every = params.every;
  o.max_frames = params.max_frames;

  const std::string& labels_file = params.labels_file;
  const std::vector<std::filesystem::path> label_candidates =
      labels_file == "auto" ? std::vector<std::filesystem::path>{o.root / "extra" / kLabelsFileName, o.root / kLabelsFileName}
                            : std::vector<std::filesystem::path>{h36m_ego::ResolveUnder(o.root, labels_file)};
  const std::optional<std::filesystem::path> found_labels = FirstExisting(label_candidates);

  if (params.labels == H36mLabels::kAnnot) {
    o.use_npy = false;
  } else if (params.labels == H36mLabels::kNpy) {
    o.use_npy = true;
  } else {
    // annot.h5 files of a requested subject win; otherwise the labels npy (its image folders may
    // also live under processed/); otherwise processed/ alone still means annot.h5 (errors name it).
    bool has_annot = false;
    for (const std::string& subject : o.subjects) {
      const std::filesystem::path dir = o.root / "processed" / subject;
      if (!std::filesystem::is_directory(dir)) continue;
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        has_annot = has_annot || std::filesystem::is_regular_file(entry.path() / "annot.h5");
      }
    }
    if (has_annot) {
      o.use_npy = false;
    } else if (found_labels) {
      o.use_npy = true;
    } else if (std::filesystem::is_directory(o.root / "processed")) {
      o.use_npy = false;
    } else {
      throw InputError(PathName(o.root) + ": no Human3.6M labels found (looked for the directory " +
                       (o.root / "processed").string() + " and " + ListPaths(label_candidates) + ")");
    }
  }
  if (o.use_npy) {
    if (!found_labels) throw InputError(ListPaths(label_candidates) + ": labels file not found");
    o.labels_file = *found_labels;
  }

  const std::string& cameras_file = params.cameras_file;
  if (cameras_file == "labels") {
    if (!o.use_npy) throw ConfigError("human36m: cameras_file=labels needs labels=npy");
  } else if (cameras_file == "auto") {
    const std::vector<std::filesystem::path> candidates = {o.root / "metadata.xml", o.root / "cameras.pkl",
                                                           o.root / "annotation_body3d" / "cameras.pkl"};
    if (const auto found = FirstExisting(candidates)) {
      o.cameras_file = *found;
    } else if (!o.use_npy) {
      throw InputError(ListPaths(candidates) + ": no camera file found (or pass --param cameras_file=PATH)");
    }
  } else {
    o.cameras_file = h36m_ego::ResolveUnder(o.root, cameras_file);
  }
  return o;
}

SequenceHeader NewHeader(const std::string& subject, const std::string& action, std::vector<Camera> cameras) {
  SequenceHeader header;
  header.name = "human36m/" + subject + "/" + action;
  header.cameras = std::move(cameras);
  header.gt_joints = Human36mJoints();
  header.fps = kHuman36mFps;
  return header;
}

// The frame with one person whose first 17 joints are `joints_m` (metres, world).
void FillFrame(bool nose_from_head, const std::string& subject, const std::string& action, long long frame_idx,
               const Eigen::Matrix<double, 3, 17>& joints_m, SequenceFrame* frame) {
  frame->id = "human36m_" + subject + "_" + action + "_" + h36m_ego::Padded(frame_idx, 6);
  frame->timestamp_s = static_cast<double>(frame_idx) / kHuman36mFps;
  frame->gt.Clear(kNumJoints);
  auto person = frame->gt.AddPerson(0);
  for (int j = 0; j < 17; ++j) person.col(j) << joints_m.col(j), 1.0;
  person.col(kNoseIndex) = person.col(nose_from_head ? kHeadIndex : kNeckNoseIndex);
}

// The cameras of `subject`; their corrections go to `warnings`, which the subject's first sequence
// takes over (the cameras are shared by all its sequences: counted once).
std::vector<Camera> SubjectCameras(const Human36mOptions& options, const io::PyView* labels, const std::string& subject,
                                   InputWarnings* warnings) {
  if (options.cameras_file.empty()) return h36m_ego::LearnableTriCameras(*labels, subject, options.model, warnings);
  return ReadHuman36mCameras(options.cameras_file, subject, options.model, warnings);
}

// ---------------------------------------------------------------------------------------
// HDF5 (h36m-fetch annot.h5)

struct AnnotRows {
  std::map<long long, std::vector<std::pair<int, std::size_t>>> by_frame;  // frame -> (camera index, row)
  std::vector<double> pose;  // rows x 32 x 3, camera-frame mm
};

AnnotRows ReadAnnot(const std::filesystem::path& path) {
  const std::string source = PathName(path);
  const io::Hdf5Quiet quiet;
  const io::Hdf5Reader file(path);
  AnnotRows rows;
  rows.pose = file.Numbers<double>("pose/3d", H5T_NATIVE_DOUBLE, {-1, 32, 3}, "rows x 32 raw joints x 3");
  const std::vector<double> camera = file.Numbers<double>("camera", H5T_NATIVE_DOUBLE, {-1}, "camera id per row");
  const std::vector<double> frame = file.Numbers<double>("frame", H5T_NATIVE_DOUBLE, {-1}, "frame number per row");
  const std::size_t n = rows.pose.size() / (32 * 3);
  if (camera.size() != n || frame.size() != n) {
    throw InputError(source + ": camera (" + std::to_string(camera.size()) + " rows) and frame (" +
                     std::to_string(frame.size()) + " rows) must have one entry per row of pose/3d (" +
                     std::to_string(n) + " rows)");
  }
  for (std::size_t r = 0; r < n; ++r) {
    const double cam = camera[r];
    const std::string cam_text = std::isfinite(cam) ? std::to_string(static_cast<long long>(cam)) : "nan";
    const int index = cam == std::floor(cam) ? h36m_ego::H36mCameraIndex(cam_text) : -1;
    if (index < 0) throw InputError(source + ": camera: row " + std::to_string(r) + ": unknown camera id " + cam_text);
    const double f = frame[r];
    if (!std::isfinite(f) || f < 1 || f != std::floor(f)) {
      throw InputError(source + ": frame: row " + std::to_string(r) + ": expected a 1-based frame number");
    }
    rows.by_frame[static_cast<long long>(f)].emplace_back(index, r);
  }
  for (auto& [f, entries] : rows.by_frame) {
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 1; i < entries.size(); ++i) {
      if (entries[i].first == entries[i - 1].first) {
        throw InputError(source + ": frame " + std::to_string(f) + " appears twice for camera " +
                         Human36mCameraIds()[static_cast<std::size_t>(entries[i].first)]);
      }
    }
  }
  return rows;
}

// World-frame joints (metres) of row `row` of pose/3d (camera-frame mm of camera `camera`).
Eigen::Matrix<double, 3, 17> AnnotRowToWorld(const AnnotRows& rows, std::size_t row, const Camera& camera,
                                             const std::string& source) {
  Eigen::Matrix<double, 3, 17> out;
  for (int j = 0; j < 17; ++j) {
    const double* p = &rows.pose[(row * 32 + static_cast<std::size_t>(kRawIndices[static_cast<std::size_t>(j)])) * 3];
    const Eigen::Vector3d x_cam_m(p[0] / 1000.0, p[1] / 1000.0, p[2] / 1000.0);
    if (!x_cam_m.allFinite()) {
      throw InputError(source + ": pose/3d: row " + std::to_string(row) + " joint " +
                       std::to_string(kRawIndices[static_cast<std::size_t>(j)]) + ": NaN or infinite coordinate");
    }
    out.col(j) = camera.R.transpose() * (x_cam_m - camera.t);
  }
  return out;
}

std::vector<std::string> SortedActionDirs(const std::filesystem::path& subject_dir) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(subject_dir)) {
    if (entry.is_directory() && std::filesystem::is_regular_file(entry.path() / "annot.h5")) {
      out.push_back(entry.path().filename().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The world pose of one annot.h5 frame: from the first camera (id order); every other camera must
// agree with it.
Eigen::Matrix<double, 3, 17> AnnotFrameToWorld(const AnnotRows& rows, long long frame,
                                               const std::vector<Camera>& cameras, const std::string& source) {
  const auto& entries = rows.by_frame.at(frame);
  const int ref_camera = entries.front().first;
  const auto world =
      AnnotRowToWorld(rows, entries.front().second, cameras[static_cast<std::size_t>(ref_camera)], source);
  for (std::size_t e = 1; e < entries.size(); ++e) {
    const auto other =
        AnnotRowToWorld(rows, entries[e].second, cameras[static_cast<std::size_t>(entries[e].first)], source);
    const double deviation = (other - world).colwise().norm().maxCoeff();
    if (!(deviation <= h36m_ego::kViewAgreementToleranceM)) {
      std::ostringstream msg;
      msg << source << ": frame " << frame << ": camera "
          << Human36mCameraIds()[static_cast<std::size_t>(entries[e].first)] << " puts the pose " << deviation * 1000.0
          << " mm away from camera " << Human36mCameraIds()[static_cast<std::size_t>(ref_camera)]
          << " after conversion to world coordinates (wrong cameras file or subject?)";
      throw InputError(msg.str());
    }
  }
  return world;
}

// One source per selected action directory; its annot.h5 is read when the source is opened and
// converted one frame per Next.
std::vector<std::unique_ptr<FrameSource>> OpenFromAnnot(const Human36mOptions& options) {
  std::vector<std::unique_ptr<FrameSource>> out;
  std::map<std::string, std::vector<std::string>> actions;
  for (const std::string& subject : options.subjects) {
    const std::filesystem::path subject_dir = options.root / "processed" / subject;
    if (!std::filesystem::is_directory(subject_dir)) throw InputError(PathName(subject_dir) + ": unknown subject (no such directory)");
    actions[subject] = SortedActionDirs(subject_dir);
  }
  CheckExcludes(options, actions);
  for (const std::string& subject : options.subjects) {
    const std::filesystem::path subject_dir = options.root / "processed" / subject;
    InputWarnings camera_warnings;
    const std::vector<Camera> cameras = SubjectCameras(options, nullptr, subject, &camera_warnings);
    bool any = false;
    for (const std::string& action : SortedActionDirs(subject_dir)) {
      if (!ActionSelected(options, subject, action)) continue;
      any = true;
      const std::filesystem::path path = subject_dir / action / "annot.h5";
      auto rows = std::make_shared<const AnnotRows>(ReadAnnot(path));
      std::vector<long long> frames;
      for (const auto& [f, entries] : rows->by_frame) frames.push_back(f);
      std::vector<long long> selected;
      for (const std::size_t k : h36m_ego::SelectFrames(frames.size(), options.every, options.max_frames)) {
        selected.push_back(frames[k]);
      }
      auto convert = [rows, selected, cameras, source = PathName(path), nose_from_head = options.nose_from_head,
                      subject, action](std::size_t i, SequenceFrame* frame, InputWarnings*) {
        FillFrame(nose_from_head, subject, action, selected[i] - 1,
                  AnnotFrameToWorld(*rows, selected[i], cameras, source), frame);
      };
      const std::size_t count = selected.size();
      out.push_back(std::make_unique<IndexedFrameSource>(NewHeader(subject, action, cameras), count, std::move(convert),
                                                         std::exchange(camera_warnings, InputWarnings{})));
    }
    if (!any) throw InputError(PathName(subject_dir) + ": no selected action directory with an annot.h5");
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// learnable-triangulation labels npy

// The labels npy is read once for every sequence; each source converts its rows one frame per Next.
std::vector<std::unique_ptr<FrameSource>> OpenFromLabels(const Human36mOptions& options) {
  const std::string source = PathName(options.labels_file);
  const io::PyView labels = io::ReadNpy(options.labels_file);
  if (!labels.IsDict()) labels.Fail("expected the dict written by generate-labels-npy-multiview.py");
  const io::PyView subject_names = labels.Key("subject_names");
  const io::PyView action_names = labels.Key("action_names");
  const io::PyView table = labels.Key("table");
  const auto table_shape = table.Shape();
  if (table_shape.size() != 1) table.Fail("expected a 1-D structured array, got " + std::to_string(table_shape.size()) + " dimensions");
  const std::int64_t n = table_shape[0];
  const auto subject_idx = table.Field("subject_idx").ToDoubles({n});
  const auto action_idx = table.Field("action_idx").ToDoubles({n});
  const auto frame_idx = table.Field("frame_idx").ToDoubles({n});
  const io::PyView keypoints_view = table.Field("keypoints");
  const auto keypoints_shape = keypoints_view.Shape();
  if (keypoints_shape != std::vector<std::int64_t>{n, 17, 3}) keypoints_view.Fail("expected 17 x 3 keypoints per row");
  keypoints_view.AsArray();  // an ndarray (else InputError), read per frame below

  // (subject index, action index) -> (frame index, table row)
  std::map<std::pair<int, int>, std::vector<std::pair<long long, std::size_t>>> groups;
  for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) {
    const double s = subject_idx[r], a = action_idx[r], f = frame_idx[r];
    if (!(s >= 0 && s < static_cast<double>(subject_names.Size()) && s == std::floor(s))) {
      table.Fail("row " + std::to_string(r) + ": subject_idx out of range");
    }
    if (!(a >= 0 && a < static_cast<double>(action_names.Size()) && a == std::floor(a))) {
      table.Fail("row " + std::to_string(r) + ": action_idx out of range");
    }
    if (!(f >= 0 && f == std::floor(f))) table.Fail("row " + std::to_string(r) + ": frame_idx must be a non-negative integer");
    groups[{static_cast<int>(s), static_cast<int>(a)}].emplace_back(static_cast<long long>(f), r);
  }

  std::map<std::string, std::vector<std::string>> actions;  // of the selected subjects, for CheckExcludes
  for (const auto& [key, rows] : groups) {
    const std::string subject = subject_names.At(static_cast<std::size_t>(key.first)).AsStr();
    if (std::find(options.subjects.begin(), options.subjects.end(), subject) == options.subjects.end()) continue;
    actions[subject].push_back(h36m_ego::SanitizeName(action_names.At(static_cast<std::size_t>(key.second)).AsStr()));
  }
  CheckExcludes(options, actions);

  std::vector<std::unique_ptr<FrameSource>> out;
  for (const std::string& subject : options.subjects) {
    std::size_t s = subject_names.Size();
    std::string known;
    for (std::size_t i = 0; i < subject_names.Size(); ++i) {
      known += (i ? ", " : "") + subject_names.At(i).AsStr();
      if (subject_names.At(i).AsStr() == subject) s = i;
    }
    if (s == subject_names.Size()) subject_names.Fail("unknown subject " + QuoteName(subject) + " (file has " + known + ")");
    InputWarnings camera_warnings;
    const std::vector<Camera> cameras = SubjectCameras(options, &labels, subject, &camera_warnings);
    bool any = false;
    for (std::size_t a = 0; a < action_names.Size(); ++a) {
      const std::string action = h36m_ego::SanitizeName(action_names.At(a).AsStr());
      if (!ActionSelected(options, subject, action)) continue;
      auto it = groups.find({static_cast<int>(s), static_cast<int>(a)});
      if (it == groups.end()) continue;
      any = true;
      auto& rows = it->second;
      std::stable_sort(rows.begin(), rows.end());
      std::vector<std::pair<long long, std::size_t>> selected;  // (frame index, table row)
      for (const std::size_t k : h36m_ego::SelectFrames(rows.size(), options.every, options.max_frames)) {
        selected.push_back(rows[k]);
      }
      auto convert = [keypoints_view, selected, nose_from_head = options.nose_from_head, subject, action](
                         std::size_t i, SequenceFrame* frame, InputWarnings*) {
        const io::NdArray& keypoints = keypoints_view.AsArray();
        const std::size_t row = selected[i].second;
        Eigen::Matrix<double, 3, 17> joints_m;
        for (std::size_t j = 0; j < 17; ++j) {
          for (std::size_t d = 0; d < 3; ++d) {
            const double v = keypoints.ElementAsDouble(keypoints.StorageIndex((row * 17 + j) * 3 + d)) / 1000.0;
            if (!std::isfinite(v)) {
              keypoints_view.Fail("row " + std::to_string(row) + " joint " + std::to_string(j) +
                                  ": NaN or infinite coordinate");
            }
            joints_m(static_cast<Eigen::Index>(d), kLearnableTriToJoint[j]) = v;
          }
        }
        FillFrame(nose_from_head, subject, action, selected[i].first, joints_m, frame);
      };
      const std::size_t count = selected.size();
      out.push_back(std::make_unique<IndexedFrameSource>(NewHeader(subject, action, cameras), count, std::move(convert),
                                                         std::exchange(camera_warnings, InputWarnings{})));
    }
    if (!any) throw InputError(source + ": no labels for subject " + subject + " with the selected actions");
  }
  return out;
}

}  // namespace

const JointNames& Human36mJoints() {
  static const JointNames names = {"pelvis",       "hip_right",      "knee_right",  "ankle_right",    "hip_left",
                                   "knee_left",    "ankle_left",     "spine",       "thorax",         "neck_nose",
                                   "head",         "shoulder_left",  "elbow_left",  "wrist_left",     "shoulder_right",
                                   "elbow_right",  "wrist_right",    "nose"};
  return names;
}

DistortionModel ToDistortionModel(H36mLens lens) {
  switch (lens) {
    case H36mLens::kOpenCV:
      return DistortionModel::kOpenCV;
    case H36mLens::kNone:
      return DistortionModel::kNone;
    case H36mLens::kH36m:
      break;
  }
  return DistortionModel::kH36M;
}

std::string Human36mParams::Check() const {
  return subjects.empty() ? dataset_params::ParamKey("human36m", "subjects") + ": no subject given" : std::string();
}

DatasetInfo Human36mInfo() {
  DatasetInfo info;
  info.name = "human36m";
  info.description = "Human3.6M (4 cameras, 1 person): h36m-fetch annot.h5 or learnable-triangulation labels";
  info.layout =
      "<root>/metadata.xml or <root>/cameras.pkl (mmpose)   cameras (or param cameras_file)\n"
      "<root>/processed/<S>/<Action>-<sub>/annot.h5           h36m-fetch labels (labels=annot)\n"
      "<root>/extra/human36m-multiview-labels-GTbboxes.npy    learnable-triangulation labels (labels=npy)";
  info.params = DescribeDatasetParams<Human36mParams>();
  info.frame_id_prefix = "human36m_";  // FillFrame
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenHuman36m(const DatasetRequest& request) {
  if (!request.ground_truth) {
    throw ConfigError(
        "human36m: the frames are the ground-truth labels (annot.h5 or the labels npy) and the reader "
        "has no 2D detections of its own: it cannot run without its ground truth");
  }
  const Human36mOptions options = ParseHuman36mOptions(request);
  return options.use_npy ? OpenFromLabels(options) : OpenFromAnnot(options);
}

}  // namespace rpt
