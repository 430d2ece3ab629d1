// SPDX-License-Identifier: MIT
#include "datasets/readers/mvor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/detections.h"
#include "datasets/io/json_file.h"
#include "datasets/io/number_text.h"
#include "datasets/readers/coco_detections.h"
#include "core/text.h"

namespace rpt {
namespace {

constexpr int kNumCameras = 3;
constexpr std::int64_t kMinInt = std::numeric_limits<int>::min(), kMaxInt = std::numeric_limits<int>::max();
constexpr int kFilePoints = 12;
constexpr double kFloorShiftM = 1.0;  // the room frame's origin is about 1 m above the floor
constexpr const char* kAnnotationFile = "camma_mvor_2018.json";
constexpr const char* kDetectionsFile = "openpose_kps.json";

// The first of `candidates` (relative to root) that exists, else the first one (for the error).
std::filesystem::path FindFile(const std::filesystem::path& root, std::initializer_list<std::filesystem::path> candidates) {
  for (const std::filesystem::path& relative : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(root / relative, ec)) return root / relative;
  }
  return root / *candidates.begin();
}

std::vector<int> ParseDays(const std::string& text, const std::string& what) {
  std::vector<int> days;
  for (const std::string& item : SplitList(text)) {
    if (item.size() != 1 || item[0] < '1' || item[0] > '4') throw ConfigError(what + ": " + QuoteName(item) + " is not a day 1-4");
    days.push_back(item[0] - '0');
  }
  if (days.empty()) throw ConfigError(what + ": no day selected by " + QuoteName(text));
  // A day given twice is a mistake in the list (as a camera or sequence given twice is): refused.
  if (const std::string repeated = dataset_params::RepeatedNameProblem(SplitList(text)); !repeated.empty()) {
    throw ConfigError(what + ": " + repeated);
  }
  std::sort(days.begin(), days.end());
  return days;
}

Eigen::Matrix4d Rigid(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const std::vector<double> v = io::JsonNumbers(root, pointer, source, 16);
  Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(v.data());
  if (!m.allFinite() || (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) {
    throw InputError(source + ": " + pointer + ": expected a 4x4 rigid transform with last row 0 0 0 1");
  }
  return m;
}

// World (room frame in metres, floor shift) -> camera i, following the conventions in mvor.h.
std::vector<Camera> ReadCameras(const nlohmann::json& root, const std::string& source, bool distortion,
                                InputWarnings* warnings, Eigen::Matrix4d* cam1_to_world) {
  const std::string base = "/cameras_info/camParams";
  Eigen::Matrix4d room = Rigid(root, base + "/firstCamToRoomRef", source);
  room.topLeftCorner<3, 3>() = AcceptRotation(room.topLeftCorner<3, 3>(), source, source + ": " + base + "/firstCamToRoomRef", warnings);
  Eigen::Matrix4d to_world = Eigen::Matrix4d::Identity();  // room mm -> world m
  to_world.topLeftCorner<3, 3>() /= 1000.0;
  to_world(2, 3) = kFloorShiftM;
  *cam1_to_world = to_world * room;  // camera-1 mm -> world m (not rigid: includes the mm -> m scale)

  std::vector<Camera> cameras;
  for (int i = 0; i < kNumCameras; ++i) {
    const std::string extrinsics = io::JsonPointerJoin(base + "/extrinsics", i);
    const std::string intrinsics = io::JsonPointerJoin(base + "/intrinsics", i);
    Eigen::Matrix4d cam_to_cam1 = Rigid(root, extrinsics, source);
    cam_to_cam1.topLeftCorner<3, 3>() =
        AcceptRotation(cam_to_cam1.topLeftCorner<3, 3>(), source, source + ": " + extrinsics, warnings);
    // world -> camera i (mm): inv(E_i) * inv(room) * inv(to_world), then mm -> m.
    const Eigen::Matrix4d cam_to_world_mm = room * cam_to_cam1;  // camera i (mm) -> room (mm)
    const Eigen::Matrix3d R_cw = cam_to_world_mm.topLeftCorner<3, 3>();
    const Eigen::Vector3d center_m = cam_to_world_mm.topRightCorner<3, 1>() / 1000.0 + Eigen::Vector3d(0, 0, kFloorShiftM);

    Camera camera;
    camera.name = "cam" + std::to_string(i + 1);
    const std::vector<double> size = io::JsonNumbers(root, intrinsics + "/imagesize", source, 2);
    const std::vector<double> focal = io::JsonNumbers(root, intrinsics + "/focallength", source, 2);
    const std::vector<double> principal = io::JsonNumbers(root, intrinsics + "/principalpoint", source, 2);
    const double skew = io::JsonFind(root, intrinsics + "/skew_value") ? io::JsonNumber(root, intrinsics + "/skew_value", source) : 0.0;
    for (const double side : size) {
      if (!(side >= 1 && side <= 1e6) || side != std::floor(side)) {  // checked before the cast to int
        throw InputError(source + ": " + intrinsics + "/imagesize: expected integers in [1, 1000000]");
      }
    }
    camera.width = static_cast<int>(size[0]);
    camera.height = static_cast<int>(size[1]);
    camera.K << focal[0], skew, principal[0], 0, focal[1], principal[1], 0, 0, 1;
    camera.R = AcceptRotation(R_cw.transpose(), source, source + ": " + extrinsics, nullptr);
    camera.t = -camera.R * center_m;
    if (distortion) {
      const std::vector<double> d = io::JsonNumbers(root, intrinsics + "/distortion", source, 5);
      camera.model = DistortionModel::kOpenCV;
      camera.dist = {d[0], d[1], d[3], d[4], d[2]};  // file k1 k2 k3 p1 p2 -> OpenCV k1 k2 p1 p2 k3
    }
    if (const std::string error = camera.Validate(); !error.empty()) throw InputError(source + ": " + intrinsics + ": " + error);
    cameras.push_back(std::move(camera));
  }
  return cameras;
}

// "2015-04-01 06:47:08.947101" -> seconds since midnight.
double SecondsOfDay(const std::string& text, const std::string& where) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, seconds_at = 0;
  double second = -1;  // read without the C library, whose strtod would take LC_NUMERIC's decimal comma
  if (std::sscanf(text.c_str(), "%d-%d-%d %d:%d:%n", &year, &month, &day, &hour, &minute, &seconds_at) != 5 ||
      seconds_at == 0 || !ParseNumber(TrimBlanks(std::string_view(text).substr(static_cast<size_t>(seconds_at))), &second) ||
      hour < 0 || hour > 23 || minute < 0 || minute > 59 || !(second >= 0 && second < 61)) {
    throw InputError(where + ": " + QuoteName(text) + " is not a time 'YYYY-MM-DD hh:mm:ss.ffffff'");
  }
  return hour * 3600.0 + minute * 60.0 + second;
}

// Frame number from "day1/cam2/color/000017.png".
int FrameNumber(const std::string& file_name, const std::string& where) {
  const size_t slash = file_name.rfind('/');
  const size_t dot = file_name.rfind('.');
  const std::string digits = file_name.substr(slash == std::string::npos ? 0 : slash + 1,
                                              dot == std::string::npos ? std::string::npos : dot - slash - 1);
  if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) {
    throw InputError(where + ": file name " + QuoteName(file_name) + " does not end in a frame number");
  }
  int frame = 0;
  if (!io::ParseInteger(digits, &frame)) throw InputError(where + ": file name " + QuoteName(file_name) + ": bad frame number");
  return frame;
}

std::string MvorFrameId(int day, int frame) {
  char text[48];
  std::snprintf(text, sizeof(text), "mvor_day%d_%06d", day, frame);
  return text;
}

}  // namespace

const JointNames& MvorJoints() {
  static const JointNames names = {"head",       "shoulder_middle", "shoulder_left", "shoulder_right", "hip_left",
                                   "hip_right",  "elbow_left",      "elbow_right",   "wrist_left",     "wrist_right",
                                   "hand_left",  "hand_right",      "nose"};
  return names;
}

DatasetInfo MvorInfo() {
  DatasetInfo info;
  info.name = "mvor";
  info.description = "MVOR operating room (3 RGB-D cameras, 732 frames, 4 days), with its OpenPose detections";
  info.layout = std::string("<root>/annotations/") + kAnnotationFile + "        (or <root>/" + kAnnotationFile +
                ")\n<root>/detections_results/" + kDetectionsFile + "  (or <root>/" + kDetectionsFile +
                "; with detections=openpose)";
  info.params = DescribeDatasetParams<MvorParams>();
  info.frame_id_prefix = "mvor_day";  // MvorFrameId
  return info;
}

namespace {

// One multi-view frame of the annotation file, indexed when the file is opened and converted when
// it is pulled.
struct MvorFrame {
  std::string id;
  double timestamp_s = 0;
  std::vector<size_t> persons;                          // indices into /annotations3D
  std::array<std::vector<size_t>, kNumCameras> labels;  // per camera, indices into /annotations
  std::vector<size_t> detections;                       // indices into MvorFiles::detections.frames
};

// The parsed files every day's source converts its frames from.
struct MvorFiles {
  nlohmann::json root;
  std::string source;
  Eigen::Matrix4d cam1_to_world = Eigen::Matrix4d::Identity();
  bool ground_truth = true;
  Detections detections;  // the selected days' OpenPose detections (empty without)
  std::map<std::string, int> camera_index;
};

void ConvertFrame(const MvorFiles& files, const MvorFrame& in, SequenceFrame* frame, InputWarnings* warnings) {
  const nlohmann::json& root = files.root;
  const std::string& source = files.source;
  const int num_joints = static_cast<int>(MvorJoints().size());
  const int nose = num_joints - 1;
  frame->id = in.id;
  frame->timestamp_s = in.timestamp_s;
  if (files.ground_truth) {
    frame->gt.Clear(num_joints);
    for (const size_t i : in.persons) {
      const std::string person = io::JsonPointerJoin("/annotations3D", i);
      const std::vector<double> values = io::JsonNumbers(root, person + "/keypoints3D", source, 4 * kFilePoints);
      auto out =
          frame->gt.AddPerson(static_cast<int>(io::JsonIntIn(root, person + "/person_id", source, kMinInt, kMaxInt)));
      for (int j = 0; j < kFilePoints; ++j) {
        const Eigen::Vector4d cam1(values[4 * j], values[4 * j + 1], values[4 * j + 2], 1.0);
        const double flag = values[4 * j + 3];
        if (!cam1.allFinite() || !std::isfinite(flag)) {
          throw InputError(source + ": " + person + "/keypoints3D: point " + std::to_string(j) + " is not finite");
        }
        out.col(j) << (files.cam1_to_world * cam1).head<3>(), flag > 0 ? 1.0 : 0.0;
      }
      out.col(nose) = out.col(0);
    }
    frame->labels_2d.resize(kNumCameras);
    for (int c = 0; c < kNumCameras; ++c) {
      for (const size_t i : in.labels[static_cast<size_t>(c)]) {
        const std::string label = io::JsonPointerJoin("/annotations", i);
        PersonLabel2D out;
        const int person_id = static_cast<int>(io::JsonIntIn(root, label + "/person_id", source, kMinInt, kMaxInt));
        for (int p = 0; p < frame->gt.num_persons() && person_id >= 0; ++p) {
          if (frame->gt.track_ids[p] == person_id) out.gt_person = p;
        }
        const std::vector<double> box = io::JsonNumbers(root, label + "/bbox", source, 4);
        out.box_px << box[0], box[1], box[0] + box[2], box[1] + box[3];
        const std::vector<double> points = io::JsonNumbers(root, label + "/keypoints", source, 30);
        out.visibility.assign(num_joints, kLabelAbsent);
        for (int j = 0; j < 10; ++j) {
          const double v = points[3 * j + 2];
          out.visibility[j] = v == 2 ? kLabelVisible : v == 1 ? kLabelOccluded : kLabelAbsent;
        }
        out.visibility[nose] = out.visibility[0];
        frame->labels_2d[c].push_back(std::move(out));
      }
    }
    // Four frames give two 3D persons the same person_id: the later one is not tracked (-1), as
    // ids name one person each (the generic labels refuse a repeat; the 2D labels above keep the
    // match they had, to the last).
    long repeated = 0;
    for (int p = 1; p < frame->gt.num_persons(); ++p) {
      for (int q = 0; q < p; ++q) {
        if (frame->gt.track_ids[p] >= 0 && frame->gt.track_ids[q] == frame->gt.track_ids[p]) {
          frame->gt.track_ids[p] = -1;
          ++repeated;
          break;
        }
      }
    }
    warnings->Add(source, "3D persons whose person_id repeats another's in their frame, not tracked (id -1)", "", 0,
                  repeated);
  }
  if (files.detections.joints.empty()) return;
  const int detection_joints = static_cast<int>(files.detections.joints.size());
  frame->views.assign(kNumCameras, Poses2D{});
  for (Poses2D& view : frame->views) view.Clear(detection_joints);
  for (const size_t d : in.detections) {
    const FrameDetections& found = files.detections.frames[d];
    for (size_t v = 0; v < found.views.size(); ++v)
      frame->views[files.camera_index.at(found.cameras[v])] = found.views[v];
  }
}

}  // namespace

std::vector<std::unique_ptr<FrameSource>> OpenMvor(const DatasetRequest& request) {
  const MvorParams params = ParseDatasetParams<MvorParams>("mvor", request);
  const std::vector<int> days = ParseDays(params.days, dataset_params::ParamKey("mvor", "days"));
  const bool with_detections = params.detections == MvorDetections::kOpenPose;
  const bool distortion = params.distortion == MvorDistortion::kFile;
  const bool paper_joints = params.evaluated == MvorEvaluated::kPaper;
  if (!request.ground_truth && !with_detections) {
    throw ConfigError(
        "mvor: without the ground truth the detections are all there is to read: pass --param "
        "detections=openpose");
  }

  std::error_code ec;
  if (!std::filesystem::is_directory(request.root, ec)) {
    throw InputError("mvor: root " + QuoteName(request.root.string()) + " is not a directory");
  }
  const std::filesystem::path path = FindFile(request.root, {std::filesystem::path("annotations") / kAnnotationFile, kAnnotationFile});
  auto files = std::make_shared<MvorFiles>();
  files->root = io::LoadJsonFile(path);
  files->source = path.string();
  files->ground_truth = request.ground_truth;
  const nlohmann::json& root = files->root;
  const std::string& source = files->source;

  InputWarnings warnings;
  const std::vector<Camera> cameras = ReadCameras(root, source, distortion, &warnings, &files->cam1_to_world);
  for (int c = 0; c < kNumCameras; ++c) files->camera_index[cameras[static_cast<size_t>(c)].name] = c;

  // 3D persons by their "<id1>_<id2>_<id3>" key.
  std::map<std::string, std::vector<size_t>> persons_of;
  // 2D labels by image id: `annotations`, 10 points x [x, y, v] in the order of MvorJoints()
  // (v: 0 not labelled, 1 occluded, 2 visible), person_id -1 for persons labelled by a box only.
  std::map<std::int64_t, std::vector<size_t>> labels_of;
  if (request.ground_truth) {
    const nlohmann::json& persons = io::JsonAt(root, "/annotations3D", source);
    if (!persons.is_array()) throw InputError(source + ": /annotations3D: expected an array");
    for (size_t i = 0; i < persons.size(); ++i) {
      persons_of[io::JsonString(root, io::JsonPointerJoin("/annotations3D", i) + "/image_ids", source)].push_back(i);
    }
    if (const nlohmann::json* labels = io::JsonFind(root, "/annotations"); labels != nullptr && labels->is_array()) {
      for (size_t i = 0; i < labels->size(); ++i) {
        labels_of[io::JsonInt(root, io::JsonPointerJoin("/annotations", i) + "/image_id", source)].push_back(i);
      }
    }
  }

  std::map<int, std::vector<MvorFrame>> frames_of_day;
  for (int day : days) frames_of_day[day];
  const nlohmann::json& frames = io::JsonAt(root, "/multiview_images", source);
  if (!frames.is_array()) throw InputError(source + ": /multiview_images: expected an array");
  std::map<int, double> day_start;
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::string base = io::JsonPointerJoin("/multiview_images", f);
    const nlohmann::json& images = io::JsonAt(root, base + "/images", source);
    if (!images.is_array() || images.size() != kNumCameras) {
      throw InputError(source + ": " + base + "/images: expected " + std::to_string(kNumCameras) + " images");
    }
    std::string key;
    std::vector<std::int64_t> image_ids;
    int day = 0, frame_number = -1;
    double time_s = 0;
    for (int c = 0; c < kNumCameras; ++c) {
      const std::string image = io::JsonPointerJoin(base + "/images", c);
      const int cam = static_cast<int>(io::JsonIntIn(root, image + "/cam_id", source, 1, kNumCameras));
      const int image_day = static_cast<int>(io::JsonIntIn(root, image + "/day_id", source, 0, kMaxInt));
      const int number = FrameNumber(io::JsonString(root, image + "/file_name", source), source + ": " + image);
      if (cam != c + 1) throw InputError(source + ": " + image + "/cam_id: expected " + std::to_string(c + 1));
      if (c > 0 && (image_day != day || number != frame_number)) {
        throw InputError(source + ": " + image + ": day or frame number differs from the frame's first image");
      }
      day = image_day;
      frame_number = number;
      if (c == 0) time_s = SecondsOfDay(io::JsonString(root, image + "/date_captured", source), source + ": " + image);
      image_ids.push_back(io::JsonInt(root, image + "/id", source));
      key += (c == 0 ? "" : "_") + std::to_string(image_ids.back());
    }
    const auto day_frames = frames_of_day.find(day);
    if (day_frames == frames_of_day.end()) continue;
    const auto start = day_start.try_emplace(day, time_s).first;

    MvorFrame& frame = day_frames->second.emplace_back();
    frame.id = MvorFrameId(day, frame_number);
    frame.timestamp_s = time_s - start->second;
    if (const auto persons = persons_of.find(key); persons != persons_of.end()) {
      frame.persons = std::move(persons->second);
      persons_of.erase(persons);
    }
    for (int c = 0; c < kNumCameras && request.ground_truth; ++c) {
      if (const auto labels = labels_of.find(image_ids[c]); labels != labels_of.end()) {
        frame.labels[static_cast<size_t>(c)] = labels->second;
      }
    }
  }

  // 3D persons left over belong to days not selected, or to no multi-view frame at all: those of
  // a selected day (the day of the key's first image id) are unused input.
  long unmatched_persons = 0;
  for (const auto& [key, indices] : persons_of) {
    std::int64_t first_image = 0;
    const bool parsed = io::ParseInteger(std::string_view(key).substr(0, key.find('_')), &first_image);
    const std::int64_t day = first_image / 10'000'000'000LL;
    if (!parsed || std::find(days.begin(), days.end(), day) != days.end()) {
      unmatched_persons += static_cast<long>(indices.size());
    }
  }
  warnings.AddUnused(source, "annotations3D entries whose image_ids are no multi-view frame ignored",
                     unmatched_persons);

  // The days with frames, in order.
  std::vector<std::pair<int, std::vector<MvorFrame>*>> out;
  const bool days_given = request.params.count("days") > 0;  // an explicit day must have frames
  for (auto& [day, day_frames] : frames_of_day) {
    if (day_frames.empty() && !days_given) continue;  // the default asks for all days there are
    if (day_frames.empty()) throw InputError(source + ": no frames of day " + std::to_string(day));
    out.emplace_back(day, &day_frames);
  }
  if (out.empty()) throw InputError(source + ": no multi-view frames");

  if (with_detections) {
    const std::filesystem::path detections_path =
        FindFile(request.root, {std::filesystem::path("detections_results") / kDetectionsFile, kDetectionsFile});
    if (!std::filesystem::is_regular_file(detections_path, ec)) {
      throw InputError("mvor: " + detections_path.string() +
                       " not found (the OpenPose detections shipped with MVOR); use --param detections=none with "
                       "--detections FILE or --simulate");
    }
    Detections& detections = files->detections;
    detections = ReadCocoDetections(detections_path);
    const std::string detections_source = detections_path.string();
    // The file covers every day: frames of days not selected are left out on purpose (not unused
    // input). A COCO result list has no entry for an image without detections: the loaded frames
    // it lacks get empty views.
    std::unordered_map<std::string, std::vector<std::pair<int, MvorFrame*>>> places;  // frame id -> (day, frame)
    std::unordered_set<std::string> loaded;
    for (const auto& [day, day_frames] : out) {
      for (MvorFrame& frame : *day_frames) {
        places[frame.id].emplace_back(day, &frame);
        loaded.insert(frame.id);
      }
    }
    std::erase_if(detections.frames, [&](const FrameDetections& frame) {
      const bool selected_day = std::any_of(days.begin(), days.end(), [&](int day) {
        return frame.frame_id.rfind("mvor_day" + std::to_string(day) + "_", 0) == 0;
      });
      return !selected_day;
    });
    for (const FrameDetections& frame : detections.frames) loaded.erase(frame.frame_id);
    for (const std::string& id : loaded) detections.frames.push_back(FrameDetections{id, {}, {}});
    // AttachDetections, with the frames' views filled when they are pulled.
    const int num_joints = static_cast<int>(detections.joints.size());
    AttachReport report;
    std::unordered_set<const MvorFrame*> attached;
    for (size_t d = 0; d < detections.frames.size(); ++d) {
      const FrameDetections& found = detections.frames[d];
      const auto it = places.find(found.frame_id);
      if (it == places.end()) {
        if (report.unused_frames++ == 0) report.first_unused_frame = found.frame_id;
        continue;
      }
      for (const auto& [day, frame] : it->second) {
        attached.insert(frame);
        for (size_t v = 0; v < found.views.size(); ++v) {
          if (!files->camera_index.count(found.cameras[v])) {
            throw InputError(detections_source + ": frame " + QuoteName(found.frame_id) + ": camera " + QuoteName(found.cameras[v]) +
                             " is not a camera of sequence 'mvor/day" + std::to_string(day) + "'");
          }
          if (found.views[v].num_persons() > 0 && found.views[v].num_joints != num_joints) {
            throw InputError(detections_source + ": frame " + QuoteName(found.frame_id) + ", camera " + QuoteName(found.cameras[v]) +
                             ": " + std::to_string(found.views[v].num_joints) + " joints, expected " +
                             std::to_string(num_joints));
          }
        }
        frame->detections.push_back(d);
      }
    }
    for (const auto& [day, day_frames] : out) {
      int with = 0;
      for (const MvorFrame& frame : *day_frames) {
        if (attached.count(&frame)) {
          ++with;
        } else if (report.frames_without++ == 0) {
          report.first_frame_without = frame.id;
        }
      }
      if (with == 0) {
        throw NoFrameMatchesError(detections_source, detections.frames.size(),
                                  detections.frames.empty() ? "" : detections.frames.front().frame_id,
                                  "mvor/day" + std::to_string(day), day_frames->front().id);
      }
      report.frames_with_detections += with;
    }
    CountUnattachedFrames(report, detections_source, &warnings);
    warnings.Merge(detections.warnings);
  }

  std::vector<std::unique_ptr<FrameSource>> sources;
  for (const auto& [day, day_frames] : out) {
    SequenceHeader header;
    header.name = "mvor/day" + std::to_string(day);
    header.cameras = cameras;
    if (request.ground_truth) header.gt_joints = MvorJoints();
    header.detection_joints = files->detections.joints;
    header.gt_ids_across_frames = false;  // person_id numbers the persons of a frame (0 = the first)
    // Encloses every annotated person's centre with room to spare (x -2.0..2.6, y -0.4..3.1 m).
    header.room.center_m = Eigen::Vector3d(0.3, 1.3, 1.0);
    header.room.size_m = Eigen::Vector3d(6.0, 5.0, 2.0);
    header.evaluated_joints = {"shoulder_left", "shoulder_right", "elbow_left", "elbow_right",
                               "wrist_left",    "wrist_right",    "hip_left",   "hip_right"};
    if (paper_joints) header.evaluated_joints.insert(header.evaluated_joints.begin(), "nose");
    auto frames_of = std::make_shared<const std::vector<MvorFrame>>(std::move(*day_frames));
    auto convert = [files, frames_of](size_t i, SequenceFrame* frame, InputWarnings* warnings) {
      ConvertFrame(*files, (*frames_of)[i], frame, warnings);
    };
    const size_t count = frames_of->size();
    // Corrections are counted once per file: the first day's source carries them.
    sources.push_back(std::make_unique<IndexedFrameSource>(std::move(header), count, std::move(convert),
                                                           sources.empty() ? std::move(warnings) : InputWarnings{}));
  }
  return sources;
}

}  // namespace rpt
