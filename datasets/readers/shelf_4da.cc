// SPDX-License-Identifier: MIT
#include "datasets/readers/shelf_4da.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/openpose_body25.h"
#include "datasets/readers/openpose_paf_association.h"
#include "datasets/readers/shelf_campus.h"

namespace rpt {
namespace {

constexpr const char* kName = "shelf-4da";
constexpr const char* kFramePrefix = "shelf4da";
constexpr double kShelfFps = 25.0;  // the Shelf reader's rate (not published for Shelf)
constexpr int kShelf15Joints = 15;  // SHELF15
constexpr int kShelf15HeadBottom = 12;
constexpr int kShelf15HeadTop = 13;
constexpr int kNose = 15;  // derived, after the file's joints

std::string What(const std::string& key) { return dataset_params::ParamKey(kName, key); }

std::string ShelfFourDaFrameId(size_t index) {
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06zu", index);
  return std::string(kFramePrefix) + "_" + digits;
}

// The frame indices to read, checked against the files' frame count.
std::vector<size_t> SelectFrames(const std::string& text, size_t num_frames, const std::string& source) {
  std::vector<size_t> out;
  if (text == "all") {
    for (size_t f = 0; f < num_frames; ++f) out.push_back(f);
    return out;
  }
  const std::vector<int> frames = ParseFrameRanges(text, What("frames"));
  if (frames.front() < 0) throw ConfigError(What("frames") + ": frame " + std::to_string(frames.front()) + " is negative");
  if (static_cast<size_t>(frames.back()) >= num_frames) {
    throw InputError(source + ": frame " + std::to_string(frames.back()) + " requested but the file has " +
                     std::to_string(num_frames) + " frames (0-" + std::to_string(num_frames == 0 ? 0 : num_frames - 1) +
                     ")");
  }
  for (int f : frames) out.push_back(static_cast<size_t>(f));
  return out;
}

// gt.txt persons -> Poses3D with the derived nose.
void ConvertShelf15GroundTruth(const std::vector<FourDaPerson>& persons, HeadNoseProxy nose_proxy,
                               const std::string& source, size_t frame, Poses3D* gt) {
  gt->Clear(static_cast<int>(Shelf4daJoints().size()));
  for (size_t p = 0; p < persons.size(); ++p) {
    const FourDaPerson& person = persons[p];
    if (person.identity < 0) {
      throw InputError(source + ":" + std::to_string(person.line) + ": frame " + std::to_string(frame) + ", person " +
                       std::to_string(p) + ": identity " + std::to_string(person.identity) +
                       " is negative (ground-truth identities are track ids >= 0)");
    }
    auto joints = gt->AddPerson(person.identity);
    joints.leftCols(kShelf15Joints) = person.joints;
    const Eigen::Vector3d bottom = person.joints.col(kShelf15HeadBottom).head<3>();
    const Eigen::Vector3d top = person.joints.col(kShelf15HeadTop).head<3>();
    const Eigen::Vector3d nose = nose_proxy == HeadNoseProxy::kTop      ? top
                                 : nose_proxy == HeadNoseProxy::kBottom ? bottom
                                                                    : Eigen::Vector3d(0.5 * (bottom + top));
    joints.col(kNose) << nose, std::min(person.joints(3, kShelf15HeadBottom), person.joints(3, kShelf15HeadTop));
  }
}

// For each COCO-17 joint its BODY_25 index.
const std::array<int, 17>& CocoFromBody25() {
  static const std::array<int, 17> map = [] {
    std::array<int, 17> m{};
    for (size_t c = 0; c < m.size(); ++c) m[c] = FindJoint(Body25Joints(), CocoBodyJoints()[c]);
    return m;
  }();
  return map;
}

// Assembled BODY_25 persons of one view -> COCO-17 poses in pixels.
void AssembleView(const PackedPafCandidates& candidates, const PafAssociationOptions& options, const Camera& camera,
                  Poses2D* view) {
  const int num_joints = static_cast<int>(CocoBodyJoints().size());
  view->Clear(num_joints);
  const double sx = camera.width - 1.0;
  const double sy = camera.height - 1.0;
  // Per thread, so frames may be converted in parallel; allocation-free once warm.
  thread_local PafAssociator associator;
  thread_local PafPersons persons;
  associator.Run(Body25PafSkeleton(), candidates, options, &persons);
  for (int p = 0; p < persons.size(); ++p) {
    const int* person = persons.Person(p);
    auto joints = view->AddPerson();
    bool any = false;
    for (int c = 0; c < num_joints; ++c) {
      const int b = CocoFromBody25()[static_cast<size_t>(c)];
      const int candidate = person[b];
      if (candidate < 0) continue;
      joints.col(c) << candidates.x(b, candidate) * sx, candidates.y(b, candidate) * sy, candidates.score(b, candidate);
      any = true;
    }
    if (!any) view->data.resize(view->data.size() - 3 * static_cast<size_t>(num_joints));
  }
}

}  // namespace

const JointNames& Shelf4daJoints() {
  static const JointNames names = [] {
    JointNames n(ShelfCampusJoints().begin(), ShelfCampusJoints().begin() + 14);
    n.push_back("hip_middle");
    n.push_back("nose");
    return n;
  }();
  return names;
}

DatasetInfo Shelf4daInfo() {
  DatasetInfo info;
  info.name = kName;
  info.description =
      "Shelf as bundled by 4D-Association: 5 cameras, 301 frames, real OpenPose BODY_25 detections aligned with its 3D GT";
  info.layout =
      "<root>/calibration.json   cameras (K, RT world->camera in metres, imgSize)\n"
      "<root>/gt.txt   ground truth (SHELF15 joints in metres, identity per person)\n"
      "<root>/detection/<camera>.txt   OpenPose BODY_25 candidates and PAF scores (only with detections=openpose)";
  info.params = DescribeDatasetParams<Shelf4daParams>();
  info.frame_id_prefix = std::string(kFramePrefix) + "_";  // ShelfFourDaFrameId
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenShelf4da(const DatasetRequest& request) {
  const Shelf4daParams params = ParseDatasetParams<Shelf4daParams>(kName, request);
  PafAssociationOptions association;
  association.min_paf_score = params.min_paf_score;
  association.min_joints = params.min_joints;
  const bool with_detections = params.detections == Shelf4daDetections::kOpenPose;
  if (!request.ground_truth && !with_detections) {
    throw ConfigError(std::string(kName) +
                      ": without the ground truth (gt.txt) the frames come from the detections: pass --param "
                      "detections=openpose");
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(request.root, ec)) {
    throw InputError(std::string(kName) + ": root " + QuoteName(request.root.string()) + " is not a directory");
  }

  SequenceHeader header;
  InputWarnings warnings;
  header.name = kName;
  header.cameras = ReadFourDaCalibration(request.root / "calibration.json", &warnings);
  header.room = ShelfRoom();
  header.fps = kShelfFps;

  // The parsed files: gt.txt and one detection file per camera, converted one frame per Next.
  struct Files {
    std::optional<FourDaSkeletons> gt;
    std::string gt_source;
    // The selected frames' candidates, packed in the order they are grouped: image i * cameras + c
    // is camera c of the i-th selected frame (PafCandidateStore: one buffer, not ~50 blocks per view).
    PafCandidateStore candidates;
    std::vector<size_t> frames;  // the selected frame indices
  };
  auto files = std::make_shared<Files>();
  std::string count_source;  // the file the frame count comes from
  size_t num_frames = 0;
  if (request.ground_truth) {
    header.gt_joints = Shelf4daJoints();
    const std::filesystem::path gt_path = request.root / "gt.txt";
    files->gt_source = gt_path.string();
    files->gt = ReadFourDaSkeletons(gt_path);
    if (files->gt->num_joints != kShelf15Joints) {
      throw InputError(files->gt_source + ":1: header: " + std::to_string(files->gt->num_joints) +
                       " joints, expected " + std::to_string(kShelf15Joints) + " (SHELF15)");
    }
    count_source = files->gt_source;
    num_frames = files->gt->frames.size();
    files->frames = SelectFrames(params.frames, num_frames, count_source);
  }
  if (with_detections) {
    header.detection_joints = CocoBodyJoints();
    std::vector<FourDaDetections> parsed;  // per camera, packed below
    for (const Camera& camera : header.cameras) {
      const std::filesystem::path path = request.root / "detection" / (camera.name + ".txt");
      FourDaDetections& detections = parsed.emplace_back(ReadFourDaDetections(path, &warnings));
      if (count_source.empty()) {  // without gt.txt: the first detection file counts the frames
        count_source = path.string();
        num_frames = detections.frames.size();
      }
      if (detections.frames.size() != num_frames) {
        throw InputError(path.string() + ":1: header: " + std::to_string(detections.frames.size()) + " frames, " +
                         count_source + " has " + std::to_string(num_frames));
      }
    }
    // A detection file of a camera calibration.json does not have is not read: said, not silent.
    std::set<std::string> unread;
    for (const auto& entry : std::filesystem::directory_iterator(request.root / "detection", ec)) {
      const std::filesystem::path& file = entry.path();
      if (file.extension() != ".txt") continue;
      const std::string camera = file.stem().string();
      if (std::none_of(header.cameras.begin(), header.cameras.end(), [&](const Camera& c) { return c.name == camera; })) {
        unread.insert(camera);
      }
    }
    if (!unread.empty()) {
      std::string names;
      for (const std::string& camera : unread) names += (names.empty() ? "" : ", ") + QuoteName(camera);
      warnings.AddUnused((request.root / "detection").string(),
                         "detection files of cameras calibration.json does not have, not read (cameras " + names + ")",
                         static_cast<long>(unread.size()));
    }
    if (!request.ground_truth) files->frames = SelectFrames(params.frames, num_frames, count_source);
    for (const size_t f : files->frames) {
      for (const FourDaDetections& camera : parsed) files->candidates.Append(Body25PafSkeleton(), camera.frames[f]);
    }
  }

  auto convert = [files, nose_proxy = params.nose_proxy](size_t i, SequenceFrame* frame, InputWarnings*) {
    const size_t f = files->frames[i];
    frame->id = ShelfFourDaFrameId(f);
    frame->timestamp_s = static_cast<double>(f) / kShelfFps;
    if (files->gt) ConvertShelf15GroundTruth(files->gt->frames[f], nose_proxy, files->gt_source, f, &frame->gt);
  };
  // The grouping reads only the parsed candidates (AssembleView's scratch is per thread), so it
  // completes frames in parallel (datasets/frame_source.h).
  auto complete = [files, association, cameras = header.cameras](size_t i, SequenceFrame* frame) {
    if (files->candidates.size() == 0) return;
    // Timed: the grouping is per-frame work before the pipeline (the step table's row
    // "paf_grouping (reader)").
    const auto start = std::chrono::steady_clock::now();
    frame->views.resize(cameras.size());
    for (size_t c = 0; c < cameras.size(); ++c) {
      AssembleView(files->candidates[i * cameras.size() + c], association, cameras[c], &frame->views[c]);
    }
    frame->paf_grouping_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  };
  const size_t count = files->frames.size();
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(std::make_unique<IndexedFrameSource>(std::move(header), count, std::move(convert),
                                                         std::move(warnings), std::move(complete)));
  return sources;
}

}  // namespace rpt
