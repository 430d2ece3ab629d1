// SPDX-License-Identifier: MIT
#include "datasets/readers/egohumans.h"

#include <Eigen/Dense>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/npy.h"
#include "datasets/io/pickle.h"
#include "datasets/readers/colmap_text.h"
#include "datasets/readers/h36m_ego_common.h"
#include "core/printable_text.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using h36m_ego::PathName;

constexpr int kAriaImageSize = 1408;  // egohumans: any other COLMAP camera size is an exo camera
constexpr int kBodyJoints = 17;
constexpr int kWholeBodyJoints = 133;

struct EgoHumansOptions {
  fs::path root;
  std::vector<std::string> sequences;  // empty = all
  std::vector<std::string> cameras;    // empty = all exo cameras
  std::string anchor = "aria01";
  std::string gt = "poses3d";
  bool detections = false;
  int every = 1;
  int max_frames = 0;
  double fps = 20.0;
};

struct SequenceDir {
  fs::path path;
  std::string big;  // e.g. "01_tagging"
  std::string seq;  // e.g. "001_tagging"
};

EgoHumansOptions ParseEgoHumansOptions(const DatasetRequest& request) {
  const EgohumansParams params = ParseDatasetParams<EgohumansParams>("egohumans", request);
  EgoHumansOptions o;
  o.root = request.root;
  o.sequences = params.sequences;
  o.cameras = params.cameras;
  o.anchor = params.anchor;
  o.gt = std::string(EnumName(params.gt));
  o.detections = params.detections == EgohumansDetections::kCache;
  o.every = params.every;
  o.max_frames = params.max_frames;
  o.fps = params.fps;
  return o;
}

bool IsSequenceDir(const fs::path& p) { return fs::is_directory(p / "colmap" / "workplace"); }

std::vector<fs::path> SortedSubdirs(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory()) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The sequence directories under root: root itself, root/<seq>, or root/<big>/<seq>.
std::vector<SequenceDir> FindSequences(const EgoHumansOptions& options) {
  fs::path root = options.root.lexically_normal();
  if (root.filename().empty()) root = root.parent_path();
  if (!fs::is_directory(root)) throw InputError(PathName(options.root) + ": not a directory");
  std::vector<SequenceDir> all;
  if (IsSequenceDir(root)) {
    all.push_back({root, root.parent_path().filename().string(), root.filename().string()});
  } else {
    for (const fs::path& a : SortedSubdirs(root)) {
      if (IsSequenceDir(a)) {
        all.push_back({a, root.filename().string(), a.filename().string()});
        continue;
      }
      for (const fs::path& b : SortedSubdirs(a)) {
        if (IsSequenceDir(b)) all.push_back({b, a.filename().string(), b.filename().string()});
      }
    }
  }
  if (all.empty()) throw InputError(PathName(options.root) + ": no EgoHumans sequence found (expected <big_seq>/<seq>/colmap/workplace)");
  if (options.sequences.empty()) return all;
  std::vector<SequenceDir> out;
  for (const std::string& wanted : options.sequences) {
    bool found = false;
    for (const SequenceDir& s : all) {
      if (wanted == s.big + "/" + s.seq || wanted == s.seq || wanted == s.big) {
        out.push_back(s);
        found = true;
      }
    }
    if (!found) {
      std::string names;
      for (const SequenceDir& s : all) names += (names.empty() ? "" : ", ") + s.big + "/" + s.seq;
      throw InputError(PathName(options.root) + ": unknown sequence " + QuoteName(wanted) + " (found " + names + ")");
    }
  }
  return out;
}

// Time stamp from "camXX/00017.jpg" or "00017.npy" (the digits of the file stem); nullopt when the
// stem is not a non-negative integer.
std::optional<int> TimeStampOf(const std::string& file_name) {
  const std::string stem = fs::path(file_name).stem().string();
  int value = 0;
  if (!io::ParseInteger(stem, &value) || value < 0) return std::nullopt;  // time stamps count from 1
  return value;
}

Eigen::Matrix4d Matrix4(const io::PyView& view) {
  const auto values = h36m_ego::FiniteNumbers(view, 16);
  const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(values.data());
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) view.Fail("last row must be (0, 0, 0, 1)");
  return m;
}

// Camera pose from E = cam_from_aria as a 4x4 that may carry a scale s (colmap_from_aria is a
// similarity): x_cam = s (R X + t'). The pinhole/fisheye projection ignores the overall factor s,
// so R = A / s and t = b / s with s = cbrt(det A). R goes through AcceptRotation: counted under
// `source` (the files the pose comes from), errors name `where` (with the line).
void SetPose(const Eigen::Matrix4d& cam_from_aria, const std::string& source, const std::string& where,
             InputWarnings* warnings, Camera* camera) {
  const Eigen::Matrix3d A = cam_from_aria.topLeftCorner<3, 3>();
  const double det = A.determinant();
  if (!(det > 0) || !std::isfinite(det)) throw InputError(where + ": camera_from_anchor has a non-positive determinant");
  const double scale = std::cbrt(det);
  camera->R = AcceptRotation(A / scale, source, where + ": camera_from_anchor / scale", warnings);
  camera->t = cam_from_aria.topRightCorner<3, 1>() / scale;
}

// The exo cameras; rotation and quaternion corrections are counted in `warnings`.
std::vector<Camera> ReadExoCameras(const EgoHumansOptions& options, const SequenceDir& dir, int reference_time_stamp,
                                   InputWarnings* warnings) {
  const fs::path workplace = dir.path / "colmap" / "workplace";
  const fs::path cameras_path = workplace / "cameras.txt";
  const fs::path images_path = workplace / "images.txt";
  const std::vector<ColmapCamera> colmap_cameras = ReadColmapCamerasText(cameras_path);
  const std::vector<ColmapImage> images = ReadColmapImagesText(images_path, warnings);

  const fs::path transforms_path = workplace / "colmap_from_aria_transforms.pkl";
  const io::PyView transforms = io::ReadPickle(transforms_path);
  const Eigen::Matrix4d colmap_from_anchor = Matrix4(transforms.Key(options.anchor));

  // Exo name of each COLMAP camera: the folder of the first image using it (egohumans
  // get_colmap_camera_mapping; a later camera with the same name wins, as there).
  std::map<std::string, const ColmapCamera*> by_name;
  for (const ColmapCamera& c : colmap_cameras) {
    if (c.width == kAriaImageSize && c.height == kAriaImageSize) continue;
    const auto image = std::find_if(images.begin(), images.end(), [&](const ColmapImage& i) { return i.camera_id == c.camera_id; });
    if (image == images.end()) {
      throw InputError(PathName(cameras_path) + ":" + std::to_string(c.line) + ": exo camera " + std::to_string(c.camera_id) +
                       " has no image in " + PathName(images_path) + ", so it has no name");
    }
    const std::string name = image->name.substr(0, image->name.find('/'));
    by_name[name] = &c;
  }
  for (const std::string& wanted : options.cameras) {
    if (!by_name.count(wanted)) throw InputError(PathName(cameras_path) + ": unknown exo camera " + QuoteName(wanted));
  }

  std::vector<Camera> out;
  for (const auto& [name, colmap] : by_name) {
    if (!options.cameras.empty() && std::find(options.cameras.begin(), options.cameras.end(), name) == options.cameras.end()) {
      continue;
    }
    Camera camera = ColmapCameraToCamera(*colmap, PathName(cameras_path));
    camera.name = name;
    Eigen::Matrix4d cam_from_colmap = Eigen::Matrix4d::Identity();
    std::string where, pose_file;
    const fs::path manual = workplace / (name + ".npy");
    if (fs::is_regular_file(manual)) {
      // Manual calibration (egohumans CALIBRATION.MANUAL_EXO_CAMERAS): 4x4 colmap -> camera.
      cam_from_colmap = Matrix4(io::ReadNpy(manual));
      where = pose_file = PathName(manual);
    } else {
      const ColmapImage* best = nullptr;
      // In 64 bits: a distance of INT_MAX (GT time stamp 0, only cam01/2147483647.jpg; before the
      // negative ones were refused, cam01/-2147483648.jpg overflowed) used to leave `best` unset.
      long long best_distance = std::numeric_limits<long long>::max();
      for (const ColmapImage& image : images) {
        if (image.name.substr(0, image.name.find('/')) != name) continue;
        const auto stamp = TimeStampOf(image.name);
        if (!stamp) {
          throw InputError(PathName(images_path) + ":" + std::to_string(image.line) + ": image name " + QuoteName(image.name) +
                           " is not <camera>/<time stamp>.jpg");
        }
        const long long distance = std::llabs(static_cast<long long>(*stamp) - reference_time_stamp);
        if (distance < best_distance) best = &image, best_distance = distance;
      }
      cam_from_colmap.topLeftCorner<3, 3>() = ColmapQuaternionToRotation(best->qvec_wxyz);
      cam_from_colmap.topRightCorner<3, 1>() = best->tvec;
      pose_file = PathName(images_path);
      where = pose_file + ":" + std::to_string(best->line);
    }
    const std::string composed = " composed with " + PathName(transforms_path) + "[" + QuoteName(options.anchor) + "]";
    SetPose(cam_from_colmap * colmap_from_anchor, pose_file + composed, where + composed, warnings, &camera);
    h36m_ego::CheckCamera(camera, where);
    out.push_back(std::move(camera));
  }
  if (out.empty()) throw InputError(PathName(cameras_path) + ": no exo camera (all cameras are 1408x1408 Aria cameras)");
  return out;
}

// Time stamps of processed_data/<gt>/%05d.npy, sorted; other entries are counted in `warnings`
// (unused input).
std::vector<int> GtTimeStamps(const EgoHumansOptions& options, const SequenceDir& dir, InputWarnings* warnings) {
  const fs::path gt_dir = dir.path / "processed_data" / options.gt;
  if (!fs::is_directory(gt_dir)) throw InputError(PathName(gt_dir) + ": ground-truth directory not found");
  std::vector<int> out;
  long others = 0;
  std::string first_other;
  for (const auto& entry : fs::directory_iterator(gt_dir)) {
    const std::string name = entry.path().filename().string();
    const auto stamp = TimeStampOf(name);
    if (entry.is_regular_file() && entry.path().extension() == ".npy" && stamp) {
      out.push_back(*stamp);
    } else if (others++ == 0 || name < first_other) {
      first_other = name;
    }
  }
  warnings->AddUnused(PathName(gt_dir), "entries not named <time stamp>.npy ignored (e.g. " + QuoteName(first_other) + ")",
                      others);
  std::sort(out.begin(), out.end());
  if (out.empty()) throw InputError(PathName(gt_dir) + ": no %05d.npy files");
  return out;
}

std::vector<int> SelectedTimeStamps(const EgoHumansOptions& options, const SequenceDir& dir, InputWarnings* warnings) {
  const std::vector<int> all = GtTimeStamps(options, dir, warnings);
  std::vector<int> out;
  for (const std::size_t k : h36m_ego::SelectFrames(all.size(), options.every, options.max_frames)) out.push_back(all[k]);
  return out;
}

std::string EgoHumansFrameId(const SequenceDir& dir, int time_stamp) {
  return "egohumans_" + dir.big + "_" + dir.seq + "_" + h36m_ego::Padded(time_stamp, 5);
}

int TrackIdOf(const std::string& aria_name, int fallback) {
  std::size_t digits = aria_name.find_first_of("0123456789");
  if (digits == std::string::npos) return fallback;
  int value = 0;
  return io::ParseInteger(std::string_view(aria_name).substr(digits), &value) ? value : fallback;
}

Poses3D ReadGtFrame(const fs::path& path) {
  const io::PyView root = io::ReadNpy(path);
  if (!root.IsDict()) root.Fail("expected a dict aria name -> (17, 4) array");
  Poses3D gt;
  gt.Clear(kBodyJoints);
  int index = 0;
  for (const auto& [key, value] : root.Items()) {
    ++index;
    const std::string& name = key.AsStr();
    const auto shape = value.Shape();
    if (shape != std::vector<std::int64_t>{kBodyJoints, 4}) value.Fail("expected shape (17, 4) = COCO-17 x (x, y, z, valid)");
    const auto v = value.ToDoubles();
    Eigen::Matrix4Xd joints(4, kBodyJoints);
    int valid_joints = 0;
    for (int j = 0; j < kBodyJoints; ++j) {
      const double* p = &v[static_cast<std::size_t>(4 * j)];
      if (!std::isfinite(p[3])) value.Fail("joint " + std::to_string(j) + ": valid flag is NaN");
      const bool valid = p[3] > 0;
      if (valid && !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
        value.Fail("joint " + std::to_string(j) + ": NaN or infinite coordinate");
      }
      joints.col(j) = valid ? Eigen::Vector4d(p[0], p[1], p[2], 1.0) : Eigen::Vector4d::Zero();
      valid_joints += valid ? 1 : 0;
    }
    if (valid_joints == 0) continue;  // a wearer not triangulated in this frame
    gt.AddPerson(TrackIdOf(name, index)) = joints;
  }
  return gt;
}

// One view of the 2D cache: a list of dicts with 'keypoints' (133, 3) = x, y, confidence.
// Confidences in (1, 1.5] are clamped to 1 and counted under `cache_dir` (one warning line for the
// sequence's cache folder, not one per file).
Poses2D ReadCacheView(const fs::path& path, const std::string& cache_dir, InputWarnings* warnings) {
  if (!fs::is_regular_file(path)) throw InputError(PathName(path) + ": 2D pose cache file not found");
  const io::PyView root = io::ReadNpy(path);
  Poses2D view;
  view.Clear(kWholeBodyJoints);
  if (root.IsArray() && root.AsArray().Size() == 0) return view;  // np.save([]) of a frame without detections
  for (std::size_t i = 0; i < root.Size(); ++i) {
    const io::PyView entry = root.At(i);
    const io::PyView keypoints = entry.Key("keypoints");
    const auto shape = keypoints.Shape();
    if (shape != std::vector<std::int64_t>{kWholeBodyJoints, 3}) keypoints.Fail("expected shape (133, 3) = COCO-WholeBody x (x, y, score)");
    const auto v = keypoints.ToDoubles();
    auto person = view.AddPerson();
    for (int j = 0; j < kWholeBodyJoints; ++j) {
      const double* p = &v[static_cast<std::size_t>(3 * j)];
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
        keypoints.Fail("joint " + std::to_string(j) + ": NaN or infinite value");
      }
      // Checked before the comma initialiser: a throw inside one aborts Debug builds (Eigen asserts
      // that every coefficient was given).
      const double score =
          AcceptScore(p[2], cache_dir, warnings, [&] { return keypoints.Where() + ": joint " + std::to_string(j); });
      person.col(j) << p[0], p[1], score;
    }
  }
  return view;
}

fs::path CacheDir(const SequenceDir& dir) { return dir.path / "processed_data" / "poses2d"; }

fs::path CachePath(const SequenceDir& dir, const std::string& camera, int time_stamp) {
  return CacheDir(dir) / camera / "rgb" / (h36m_ego::Padded(time_stamp, 5) + ".npy");
}

}  // namespace

DatasetInfo EgohumansInfo() {
  DatasetInfo info;
  info.name = "egohumans";
  info.description = "EgoHumans exo (GoPro fisheye) cameras with triangulated COCO-17 GT of the Aria wearers";
  info.layout =
      "<root>/<big_seq>/<seq>/colmap/workplace/{cameras.txt,images.txt,colmap_from_aria_transforms.pkl[,camXX.npy]}\n"
      "<root>/<big_seq>/<seq>/processed_data/poses3d/%05d.npy (or refine_poses3d, fit_poses3d)\n"
      "<root>/<big_seq>/<seq>/processed_data/poses2d/<camXX>/rgb/%05d.npy (detections=cache)\n"
      "root may also be one <big_seq> or one <seq> directory";
  info.params = DescribeDatasetParams<EgohumansParams>();
  info.frame_id_prefix = "egohumans_";  // EgoHumansFrameId
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenEgohumans(const DatasetRequest& request) {
  if (!request.ground_truth) {
    throw ConfigError(
        "egohumans: the frames are the ground-truth time stamps (processed_data/<gt>/%05d.npy): the "
        "reader cannot run without its ground truth");
  }
  const EgoHumansOptions options = ParseEgoHumansOptions(request);
  std::vector<std::unique_ptr<FrameSource>> out;
  for (const SequenceDir& dir : FindSequences(options)) {
    InputWarnings warnings;
    const std::vector<int> stamps = SelectedTimeStamps(options, dir, &warnings);
    SequenceHeader header;
    header.name = "egohumans/" + dir.big + "/" + dir.seq;
    header.cameras = ReadExoCameras(options, dir, stamps.empty() ? 1 : stamps.front(), &warnings);
    header.gt_joints = CocoBodyJoints();
    header.fps = options.fps;
    if (options.detections) header.detection_joints = CocoWholeBodyJoints();
    // One ground-truth file (and one cache file per camera) read per frame pulled.
    auto convert = [dir, stamps, options, cameras = header.cameras](std::size_t i, SequenceFrame* frame,
                                                                    InputWarnings* frame_warnings) {
      const int stamp = stamps[i];
      frame->id = EgoHumansFrameId(dir, stamp);
      frame->timestamp_s = (stamp - 1) / options.fps;
      frame->gt = ReadGtFrame(dir.path / "processed_data" / options.gt / (h36m_ego::Padded(stamp, 5) + ".npy"));
      if (!options.detections) return;
      for (const Camera& camera : cameras) {
        frame->views.push_back(
            ReadCacheView(CachePath(dir, camera.name, stamp), PathName(CacheDir(dir)), frame_warnings));
      }
    };
    out.push_back(std::make_unique<IndexedFrameSource>(std::move(header), stamps.size(), std::move(convert),
                                                       std::move(warnings)));
  }
  return out;
}

}  // namespace rpt
