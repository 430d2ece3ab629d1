// SPDX-License-Identifier: MIT
#include "datasets/readers/shelf_campus.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/detections.h"
#include "datasets/io/mat.h"
#include "datasets/io/number_text.h"
#include "datasets/readers/voxelpose_calibration.h"
#include "datasets/readers/voxelpose_detections.h"

namespace rpt {
namespace {

constexpr int kFileJoints = 14;
constexpr int kHeadBottom = 12;
constexpr int kHeadTop = 13;

// What differs between the two datasets.
struct ShelfCampusSpec {
  std::string name;              // registry name and frame-id prefix
  std::string calibration_file;  // VoxelPose camera json in the root
  std::string detections_file;   // VoxelPose 2D cache in the root
  int width = 0;                 // image size, px
  int height = 0;
  std::string default_frames;    // of param frames
  Room room;
  std::string description;
};

const ShelfCampusSpec& ShelfSpec() {
  static const ShelfCampusSpec spec = [] {
    ShelfCampusSpec s;
    s.name = "shelf";
    s.calibration_file = "calibration_shelf.json";
    s.detections_file = "pred_shelf_maskrcnn_hrnet_coco.pkl";
    s.width = 1032;
    s.height = 776;
    s.default_frames = "300-600";
    s.room = ShelfRoom();
    s.description = "Shelf (TUM, Belagiannis et al. 2014): 5 cameras, up to 4 actors, VoxelPose calibration";
    return s;
  }();
  return spec;
}

const ShelfCampusSpec& CampusSpec() {
  static const ShelfCampusSpec spec = [] {
    ShelfCampusSpec s;
    s.name = "campus";
    s.calibration_file = "calibration_campus.json";
    s.detections_file = "pred_campus_maskrcnn_hrnet_coco.pkl";
    s.width = 360;
    s.height = 288;
    s.default_frames = "350-470,650-750";
    s.room.center_m = Eigen::Vector3d(3.0, 4.5, 1.0);
    s.room.size_m = Eigen::Vector3d(12.0, 12.0, 2.0);
    s.description = "Campus (CampusSeq1, Belagiannis et al. 2014): 3 cameras, 3 actors, VoxelPose calibration";
    return s;
  }();
  return spec;
}

ShelfCampusParams DefaultParams(const ShelfCampusSpec& spec) {
  ShelfCampusParams params;
  params.frames = spec.default_frames;
  return params;
}

DatasetInfo MakeInfo(const ShelfCampusSpec& spec) {
  DatasetInfo info;
  info.name = spec.name;
  info.description = spec.description;
  info.layout = "<root>/" + spec.calibration_file + "   VoxelPose cameras (R world->camera, T = centre in mm)\n" +
                "<root>/actorsGT.mat   ground truth (actor3D: actors x frames, 14x3 metres or empty)\n" + "<root>/" +
                spec.detections_file + "   VoxelPose 2D detections (only with detections=voxelpose)";
  info.params = DescribeDatasetParams(DefaultParams(spec));
  info.frame_id_prefix = spec.name + "_";  // ShelfCampusFrameId
  return info;
}

std::string ShelfCampusFrameId(const std::string& prefix, int frame) {
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06d", frame);
  return prefix + "_" + digits;
}

int ParseNonNegative(const std::string& text, const std::string& what) {
  int value = 0;
  if (!io::ParseInteger(text, &value) || value < 0) {
    throw ConfigError(what + ": " + QuoteName(text) + " is not a non-negative integer");
  }
  return value;
}

// actor3D: 1xP cell of Fx1 cells. Returns F, after checking that every actor has the same F.
size_t CountFrames(const io::MatValue& actor3d) {
  if (!actor3d.IsCell() || actor3d.IsEmpty()) {
    actor3d.Fail("expected a non-empty cell array of actors, got " + actor3d.Describe());
  }
  size_t frames = 0;
  for (size_t p = 0; p < actor3d.NumElements(); ++p) {
    const io::MatValue& actor = actor3d.Cell(p);
    if (!actor.IsCell()) actor.Fail("expected a cell array of frames, got " + actor.Describe());
    if (p == 0) frames = actor.NumElements();
    if (actor.NumElements() != frames) {
      actor.Fail("has " + std::to_string(actor.NumElements()) + " frames, actor 0 has " + std::to_string(frames));
    }
  }
  return frames;
}

std::vector<int> SelectActors(const std::string& text, size_t num_actors, const std::string& what,
                              const std::string& source) {
  std::vector<int> actors;
  if (text == "all") {
    for (size_t p = 0; p < num_actors; ++p) actors.push_back(static_cast<int>(p));
    return actors;
  }
  for (const std::string& item : SplitList(text)) {
    const int p = ParseNonNegative(item, what);
    if (static_cast<size_t>(p) >= num_actors) {
      throw InputError(source + ": actor " + item + " requested but actor3D has " + std::to_string(num_actors) +
                       " actors (0-" + std::to_string(num_actors - 1) + ")");
    }
    actors.push_back(p);
  }
  if (actors.empty()) throw ConfigError(what + ": no actors selected by " + QuoteName(text));
  std::sort(actors.begin(), actors.end());
  // An actor given twice is a mistake in the list (as a camera or sequence given twice is): refused.
  if (const auto twice = std::adjacent_find(actors.begin(), actors.end()); twice != actors.end()) {
    throw ConfigError(what + ": actor " + std::to_string(*twice) + " is listed twice");
  }
  return actors;
}

// The parsed actorsGT.mat and what to take from it.
struct ShelfCampusGroundTruth {
  io::MatFile mat;
  const io::MatValue* actor3d = nullptr;  // in `mat`
  std::vector<int> actors;
};

// Frame `f` of actorsGT.mat: the selected actors annotated there, plus the derived nose.
void ConvertGroundTruth(const ShelfCampusGroundTruth& truth, int f, HeadNoseProxy nose_proxy, Poses3D* gt) {
  gt->Clear(static_cast<int>(ShelfCampusJoints().size()));
  for (const int p : truth.actors) {
    const io::MatValue& pose = truth.actor3d->Cell(static_cast<size_t>(p)).Cell(static_cast<size_t>(f));
    if (pose.IsEmpty()) continue;  // actor not annotated in this frame
    const std::vector<double> rows = pose.RowMajor(kFileJoints, 3);
    if (!std::all_of(rows.begin(), rows.end(), [](double v) { return std::isfinite(v); })) {
      pose.Fail("contains NaN or infinity");
    }
    auto person = gt->AddPerson(p);
    for (int j = 0; j < kFileJoints; ++j) {
      person.col(j) << rows[3 * j], rows[3 * j + 1], rows[3 * j + 2], 1.0;
    }
    const Eigen::Vector3d bottom = person.col(kHeadBottom).head<3>();
    const Eigen::Vector3d top = person.col(kHeadTop).head<3>();
    const Eigen::Vector3d nose = nose_proxy == HeadNoseProxy::kTop      ? top
                                 : nose_proxy == HeadNoseProxy::kBottom ? bottom
                                                                        : Eigen::Vector3d(0.5 * (bottom + top));
    person.col(kFileJoints) << nose, 1.0;
  }
}

std::vector<std::unique_ptr<FrameSource>> OpenShelfCampus(const ShelfCampusSpec& spec, const DatasetRequest& request) {
  const ShelfCampusParams params = ParseDatasetParams(spec.name, request, DefaultParams(spec));
  const auto what = [&](const std::string& key) { return dataset_params::ParamKey(spec.name, key); };

  const std::vector<int> frames = ParseFrameRanges(params.frames, what("frames"));
  const HeadNoseProxy nose_proxy = params.nose_proxy;
  const double fps = params.fps;
  if (frames.front() < 0) {
    throw ConfigError(what("frames") + ": frame " + std::to_string(frames.front()) + " is negative");
  }
  const bool with_detections = params.detections == ShelfCampusDetections::kVoxelPose;
  if (!request.ground_truth && !with_detections) {
    throw ConfigError(spec.name +
                      ": without the ground truth (actorsGT.mat) the frames come from the detections: pass --param "
                      "detections=voxelpose");
  }

  std::error_code ec;
  if (!std::filesystem::is_directory(request.root, ec)) {
    throw InputError(spec.name + ": root " + QuoteName(request.root.string()) + " is not a directory");
  }

  SequenceHeader header;
  InputWarnings warnings;
  header.name = spec.name;
  header.cameras = ReadVoxelPoseCalibration(request.root / spec.calibration_file, spec.width, spec.height, &warnings);
  header.room = spec.room;
  header.fps = fps;

  std::shared_ptr<ShelfCampusGroundTruth> truth;
  if (request.ground_truth) {
    header.gt_joints = ShelfCampusJoints();
    const std::filesystem::path mat_path = request.root / "actorsGT.mat";
    truth = std::make_shared<ShelfCampusGroundTruth>();
    truth->mat = io::ReadMat(mat_path);
    truth->actor3d = &truth->mat.Get("actor3D");
    const size_t num_frames = CountFrames(*truth->actor3d);
    truth->actors = SelectActors(params.actors, truth->actor3d->NumElements(), what("actors"), mat_path.string());
    if (static_cast<size_t>(frames.back()) >= num_frames) {
      throw InputError(mat_path.string() + ": frame " + std::to_string(frames.back()) + " requested but actor3D has " +
                       std::to_string(num_frames) + " frames (0-" +
                       std::to_string(num_frames == 0 ? 0 : num_frames - 1) +
                       "); select frames with --param frames=...");
    }
  }

  std::shared_ptr<const VoxelPoseDetectionsFile> detections;
  if (with_detections) {
    const std::filesystem::path pkl = request.root / spec.detections_file;
    std::vector<std::string> camera_names;
    for (const Camera& camera : header.cameras) camera_names.push_back(camera.name);
    detections = std::make_shared<const VoxelPoseDetectionsFile>(pkl, camera_names);
    header.detection_joints = CocoBodyJoints();
    // The frames the cache has no key for are triangulated without detections (AttachDetections'
    // counts); a cache that has none of them is an error.
    AttachReport report;
    for (const int f : frames) {
      if (detections->HasFrame(f)) {
        ++report.frames_with_detections;
      } else if (report.frames_without++ == 0) {
        report.first_frame_without = ShelfCampusFrameId(spec.name, f);
      }
    }
    if (report.frames_with_detections == 0) {
      throw NoFrameMatchesError(pkl.string(), 0, "", spec.name, ShelfCampusFrameId(spec.name, frames.front()));
    }
    CountUnattachedFrames(report, pkl.string(), &warnings);
    warnings.Merge(detections->warnings());
    // mmpose's Shelf test subset: its actorsGT.mat holds Shelf frames 300-302 renumbered 0-2, its
    // cache the original frames 0-2, other instants: the detections attach, the numbers mean nothing.
    if (spec.name == "shelf" && truth && CountFrames(*truth->actor3d) == 3 &&
        detections->frames() == std::vector<long>{0, 1, 2}) {
      warnings.AddMissing(pkl.string(),
                          "frames of mmpose's 3-frame test subset: its ground truth is Shelf frames 300-302 "
                          "renumbered 0-2, its detections are frames 0-2, other instants, so the metrics compare "
                          "unrelated poses (use --simulate on this subset)",
                          report.frames_with_detections);
    }
  }

  auto convert = [name = spec.name, frames, fps, nose_proxy, truth, detections](size_t i, SequenceFrame* frame,
                                                                                InputWarnings* frame_warnings) {
    const int f = frames[i];
    frame->id = ShelfCampusFrameId(name, f);
    frame->timestamp_s = f / fps;
    if (truth) ConvertGroundTruth(*truth, f, nose_proxy, &frame->gt);
    if (detections) detections->ReadFrame(f, &frame->views, frame_warnings);
  };
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(
      std::make_unique<IndexedFrameSource>(std::move(header), frames.size(), std::move(convert), std::move(warnings)));
  return sources;
}

}  // namespace

const JointNames& ShelfCampusJoints() {
  static const JointNames names = {"ankle_right", "knee_right",  "hip_right",   "hip_left",       "knee_left",
                                   "ankle_left",  "wrist_right", "elbow_right", "shoulder_right", "shoulder_left",
                                   "elbow_left",  "wrist_left",  "head_bottom", "head_top",       "nose"};
  return names;
}

Room ShelfRoom() {
  Room room;
  room.center_m = Eigen::Vector3d(0.45, -0.32, 0.8);
  room.size_m = Eigen::Vector3d(8.0, 8.0, 2.0);
  return room;
}

DatasetInfo ShelfInfo() { return MakeInfo(ShelfSpec()); }
std::vector<std::unique_ptr<FrameSource>> OpenShelf(const DatasetRequest& request) {
  return OpenShelfCampus(ShelfSpec(), request);
}
DatasetInfo CampusInfo() { return MakeInfo(CampusSpec()); }
std::vector<std::unique_ptr<FrameSource>> OpenCampus(const DatasetRequest& request) {
  return OpenShelfCampus(CampusSpec(), request);
}

}  // namespace rpt
