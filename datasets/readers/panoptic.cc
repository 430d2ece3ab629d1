// SPDX-License-Identifier: MIT
#include "datasets/readers/panoptic.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/calibration/row_major.h"
#include "datasets/camera_plausibility.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/io/number_text.h"

namespace rpt {
namespace {

constexpr int kJoints = 19;
constexpr int kRootJoint = 2;          // body_center
constexpr double kVisibleScore = 0.1;  // VoxelPose: a joint is visible when c > 0.1
constexpr double kHdFps = 29.97;
constexpr const char* kPoseFolder = "hdPose3d_stage1_coco19";
constexpr const char* kPosePrefix = "body3DScene_";

// Rows map Panoptic (x, y, z) to rpt (x, z, -y): a proper rotation (det +1).
Eigen::Matrix3d AxisPermutation() {
  Eigen::Matrix3d A;
  A << 1, 0, 0,  //
      0, 0, 1,   //
      0, -1, 0;
  return A;
}

std::string PanopticFrameId(const std::string& sequence, long frame) {
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06ld", frame);
  return "panoptic_" + sequence + "_" + digits;
}

}  // namespace

std::vector<Camera> ReadPanopticCameras(const std::filesystem::path& path, const std::string& selection,
                                        InputWarnings* warnings) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  const nlohmann::json& list = io::JsonAt(root, "/cameras", source);
  if (!list.is_array()) throw InputError(source + ": /cameras: expected an array of cameras");

  std::map<std::string, size_t> by_name;
  std::vector<std::string> hd_names;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string base = io::JsonPointerJoin("/cameras", i);
    const std::string name = io::JsonString(root, base + "/name", source);
    by_name.emplace(name, i);
    if (const nlohmann::json* type = io::JsonFind(root, base + "/type"); type && type->is_string() && *type == "hd") {
      hd_names.push_back(name);
    }
  }

  std::vector<std::string> names = selection == "hd" ? hd_names : SplitList(selection);
  // The studio has 31 HD cameras (00_00 to 00_30): "hd" takes the ones the file has, and fewer is said.
  constexpr size_t kStudioHdCameras = 31;
  if (selection == "hd" && hd_names.size() < kStudioHdCameras && warnings != nullptr) {
    warnings->AddMissing(source, "HD cameras of the studio's 31 missing from the file: cameras=hd uses the " +
                                     std::to_string(hd_names.size()) + " it has",
                         static_cast<long>(kStudioHdCameras - hd_names.size()));
  }
  if (selection.empty()) {
    if (list.empty()) throw InputError(source + ": /cameras: the list of cameras is empty");
    for (size_t i = 0; i < list.size(); ++i)
      names.push_back(io::JsonString(root, io::JsonPointerJoin("/cameras", i) + "/name", source));
  }
  if (names.empty()) {
    throw ConfigError(dataset_params::ParamKey("panoptic", "cameras") + ": no cameras selected by " + QuoteName(selection));
  }
  if (const std::string repeated = dataset_params::RepeatedNameProblem(names); !repeated.empty()) {
    throw ConfigError(dataset_params::ParamKey("panoptic", "cameras") + ": " + repeated);
  }
  std::vector<Camera> cameras;
  for (const std::string& name : names) {
    const auto it = by_name.find(name);
    if (it == by_name.end()) {
      std::string available;
      for (const std::string& hd : hd_names) available += (available.empty() ? "" : ", ") + hd;
      throw InputError(source + ": camera " + QuoteName(name) +
                       " not found; HD cameras: " + (available.empty() ? "(none)" : available) + " (plus " +
                       std::to_string(list.size() - hd_names.size()) + " VGA/Kinect cameras)");
    }
    const std::string base = io::JsonPointerJoin("/cameras", it->second);
    const std::vector<double> resolution = io::JsonNumbers(root, base + "/resolution", source, 2);
    for (const double side : resolution) {
      if (!(side >= 1 && side <= 1e6) || side != std::floor(side)) {  // checked before the cast to int
        throw InputError(source + ": " + base + "/resolution: expected integers in [1, 1000000]");
      }
    }
    const std::vector<double> dist = io::JsonNumbers(root, base + "/distCoef", source, 5);
    const std::vector<double> t = io::JsonMatrix(root, base + "/t", source, 3, 1);
    const Eigen::Matrix3d R =
        AcceptRotation(Matrix3FromRowMajor(io::JsonMatrix(root, base + "/R", source, 3, 3).data()), source,
                       source + ": " + base + "/R (camera " + QuoteName(name) + ")", warnings);
    Camera camera =
        ConvertPanopticCamera(name, static_cast<int>(resolution[0]), static_cast<int>(resolution[1]),
                              Matrix3FromRowMajor(io::JsonMatrix(root, base + "/K", source, 3, 3).data()),
                              {dist[0], dist[1], dist[2], dist[3], dist[4]}, R, Eigen::Vector3d(t[0], t[1], t[2]));
    if (const std::string error = camera.Validate(); !error.empty()) {
      throw InputError(source + ": " + base + ": " + error);  // error names the camera
    }
    CountImplausibleCamera(camera, source, warnings);
    cameras.push_back(std::move(camera));
  }
  return cameras;
}

namespace {

struct PoseFile {
  std::filesystem::path path;
  long frame = 0;
};

// body3DScene_<number>.json files sorted by name (= by number: they are zero padded), as
// VoxelPose's sorted(glob(...)). Other files are counted in `warnings` (unused input).
std::vector<PoseFile> ListPoseFiles(const std::filesystem::path& folder, InputWarnings* warnings) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) throw InputError(folder.string() + ": annotation folder not found");
  std::vector<PoseFile> files;
  long others = 0;
  std::string first_other;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::string prefix = kPosePrefix;
    PoseFile file;
    const bool matches = name.size() > prefix.size() + 5 && name.compare(0, prefix.size(), prefix) == 0 &&
                         name.compare(name.size() - 5, 5, ".json") == 0 &&
                         io::ParseInteger(name.substr(prefix.size(), name.size() - prefix.size() - 5), &file.frame);
    if (!matches) {
      if (others++ == 0 || name < first_other) first_other = name;
      continue;
    }
    file.path = entry.path();
    files.push_back(std::move(file));
  }
  warnings->AddUnused(
      folder.string(),
      "entries not named " + std::string(kPosePrefix) + "<number>.json ignored (e.g. " + QuoteName(first_other) + ")", others);
  std::sort(files.begin(), files.end(),
            [](const PoseFile& a, const PoseFile& b) { return a.path.filename() < b.path.filename(); });
  if (files.empty()) throw InputError(folder.string() + ": no " + std::string(kPosePrefix) + "*.json files");
  return files;
}

// The GT persons of one body3DScene file; bodies whose body centre is not visible are left out as
// VoxelPose does, counted under the sequence's folder in *warnings.
void ReadBodies(const std::filesystem::path& path, Poses3D* gt, InputWarnings* warnings) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  const nlohmann::json& bodies = io::JsonAt(root, "/bodies", source);
  if (!bodies.is_array()) throw InputError(source + ": /bodies: expected an array");
  gt->Clear(kJoints);
  for (size_t b = 0; b < bodies.size(); ++b) {
    const std::string base = io::JsonPointerJoin("/bodies", b);
    const std::vector<double> joints = io::JsonNumbers(root, base + "/joints19", source, 4 * kJoints);
    if (!std::all_of(joints.begin(), joints.end(), [](double v) { return std::isfinite(v); })) {
      throw InputError(source + ": " + base + "/joints19: contains NaN or infinity");
    }
    if (!(joints[4 * kRootJoint + 3] > kVisibleScore)) {  // root invisible: dropped as in VoxelPose
      warnings->AddMissing(path.parent_path().string(),
                           "bodies whose body_center has confidence <= 0.1 left out of the ground truth (VoxelPose's "
                           "rule; a person triangulated there counts as Invalid)",
                           1);
      continue;
    }
    const auto id = io::JsonIntIn(root, base + "/id", source, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    auto person = gt->AddPerson(static_cast<int>(id));
    for (int j = 0; j < kJoints; ++j) {
      const double c = joints[4 * j + 3];
      person.col(j) << PanopticPointToWorld(Eigen::Vector3d(joints[4 * j], joints[4 * j + 1], joints[4 * j + 2])),
          std::clamp(c, 0.0, 1.0);
    }
  }
}

// One sequence, one annotation file read per frame pulled: memory does not grow with the frames.
class PanopticSource final : public FrameSource {
 public:
  PanopticSource(const std::filesystem::path& root, const std::string& name, const PanopticParams& params)
      : name_(name), folder_(root / name), params_(params) {
    header_.name = "panoptic/" + name;
    if (params.cameras.empty()) throw ConfigError("panoptic: param cameras: no cameras selected");
    header_.cameras = ReadPanopticCameras(folder_ / ("calibration_" + name + ".json"), params.cameras, &warnings_);
    header_.gt_joints = PanopticJoints();
    header_.room.center_m = Eigen::Vector3d(0.0, -0.5, 0.8);
    header_.room.size_m = Eigen::Vector3d(8.0, 8.0, 2.0);
    header_.fps = kHdFps;
    files_ = ListPoseFiles(folder_ / kPoseFolder, &warnings_);
  }

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override {
    if (params_.skip_empty) return -1;  // known only once the files are read
    const long sampled = (static_cast<long>(files_.size()) + params_.every - 1) / params_.every;
    return params_.max_frames > 0 ? std::min<long>(sampled, params_.max_frames) : sampled;
  }
  bool Pull(SequenceFrame* frame) override {
    while (next_ < files_.size()) {
      if (params_.max_frames > 0 && delivered_ >= params_.max_frames) return false;
      const PoseFile& file = files_[next_];
      next_ += static_cast<size_t>(params_.every);
      frame->id = PanopticFrameId(name_, file.frame);
      frame->timestamp_s = static_cast<double>(file.frame) / kHdFps;
      frame->views.clear();
      frame->labels_2d.clear();
      ReadBodies(file.path, &frame->gt, &warnings_);
      if (params_.skip_empty && frame->gt.num_persons() == 0) continue;
      ++delivered_;
      return true;
    }
    return false;
  }
  const InputWarnings& warnings() const override { return warnings_; }

 private:
  std::string name_;
  std::filesystem::path folder_;
  PanopticParams params_;
  SequenceHeader header_;
  InputWarnings warnings_;
  std::vector<PoseFile> files_;
  size_t next_ = 0;
  long delivered_ = 0;
};

}  // namespace

const JointNames& PanopticJoints() {
  static const JointNames names = {"neck",        "nose",        "body_center", "shoulder_left", "elbow_left",
                                   "wrist_left",  "hip_left",    "knee_left",   "ankle_left",    "shoulder_right",
                                   "elbow_right", "wrist_right", "hip_right",   "knee_right",    "ankle_right",
                                   "eye_left",    "ear_left",    "eye_right",   "ear_right"};
  return names;
}

Eigen::Vector3d PanopticPointToWorld(const Eigen::Vector3d& point_cm) { return AxisPermutation() * point_cm / 100.0; }

Camera ConvertPanopticCamera(const std::string& name, int width, int height, const Eigen::Matrix3d& K,
                             const std::array<double, 5>& dist_coef, const Eigen::Matrix3d& R_panoptic,
                             const Eigen::Vector3d& t_cm) {
  // X_cam[cm] = R X_pan[cm] + t with X_pan = 100 A^T X_rpt[m]  =>  X_cam[m] = (R A^T) X_rpt + t / 100.
  Camera camera;
  camera.name = name;
  camera.width = width;
  camera.height = height;
  camera.K = K;
  camera.dist = dist_coef;
  const bool distorted = std::any_of(dist_coef.begin(), dist_coef.end(), [](double c) { return c != 0.0; });
  camera.model = distorted ? DistortionModel::kOpenCV : DistortionModel::kNone;
  camera.R = R_panoptic * AxisPermutation().transpose();
  camera.t = t_cm / 100.0;
  return camera;
}

std::string PanopticParams::Check() const {
  if (sequences.empty()) return dataset_params::ParamKey("panoptic", "sequences") + ": no sequences selected";
  const std::string repeated = dataset_params::RepeatedNameProblem(sequences);
  return repeated.empty() ? std::string() : dataset_params::ParamKey("panoptic", "sequences") + ": " + repeated;
}

DatasetInfo PanopticInfo() {
  DatasetInfo info;
  info.name = "panoptic";
  info.description = "CMU Panoptic Studio (panoptic-toolbox layout), HD cameras, coco19 3D ground truth";
  info.layout =
      "<root>/<seq>/calibration_<seq>.json\n"
      "<root>/<seq>/hdPose3d_stage1_coco19/body3DScene_%08d.json";
  info.params = DescribeDatasetParams<PanopticParams>();
  info.frame_id_prefix = "panoptic_";  // PanopticFrameId
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenPanoptic(const DatasetRequest& request) {
  if (!request.ground_truth) {
    throw ConfigError(
        "panoptic: the frames are the ground-truth files (hdPose3d_stage1_coco19/body3DScene_*.json) and "
        "the reader has no 2D detections of its own: it cannot run without its ground truth");
  }
  PanopticParams params = ParseDatasetParams<PanopticParams>("panoptic", request);
  std::error_code ec;
  if (!std::filesystem::is_directory(request.root, ec)) {
    throw InputError("panoptic: root " + QuoteName(request.root.string()) + " is not a directory");
  }
  // A sequence is a folder name: the slash shell completion adds is not part of it (it made the
  // calibration's path "<seq>/calibration_<seq>/.json"); one inside a name would name another folder.
  for (std::string& name : params.sequences) {
    while (name.size() > 1 && name.back() == '/') name.pop_back();
    if (name.find('/') != std::string::npos) {
      throw ConfigError(dataset_params::ParamKey("panoptic", "sequences") + ": " + QuoteName(name) +
                        " is not a folder name directly under the root");
    }
  }
  // All sequence folders are checked before any is read, so a typo fails fast.
  for (const std::string& name : params.sequences) {
    if (!std::filesystem::is_directory(request.root / name, ec)) {
      throw InputError("panoptic: sequence " + QuoteName(name) + " not found: " + (request.root / name).string() +
                       " is not a directory");
    }
  }
  std::vector<std::unique_ptr<FrameSource>> sources;
  for (const std::string& name : params.sequences) {
    sources.push_back(std::make_unique<PanopticSource>(request.root, name, params));
  }
  return sources;
}

}  // namespace rpt
