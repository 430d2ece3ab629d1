// SPDX-License-Identifier: MIT
#include "datasets/readers/shelf_4da.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/errors.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/openpose_body25.h"
#include "datasets/readers/openpose_paf_association.h"
#include "datasets/readers/shelf_campus.h"

namespace rpt {
namespace {

constexpr const char* kName = "shelf-4da";
constexpr const char* kFramePrefix = "shelf4da";
constexpr double kFps = 25.0;  // the Shelf reader's rate (not published for Shelf)
constexpr int kFileJoints = 15;  // SHELF15
constexpr int kHeadBottom = 12;
constexpr int kHeadTop = 13;
constexpr int kNose = 15;  // derived, after the file's joints

std::string What(const std::string& key) { return dataset_params::ParamKey(kName, key); }

std::string FrameId(size_t index) {
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
void ConvertGroundTruth(const std::vector<FourDaPerson>& persons, HeadNoseProxy nose_proxy, const std::string& source,
                        size_t frame, Poses3D* gt) {
  gt->Clear(static_cast<int>(Shelf4daJoints().size()));
  for (size_t p = 0; p < persons.size(); ++p) {
    const FourDaPerson& person = persons[p];
    if (person.identity < 0) {
      throw InputError(source + ":" + std::to_string(person.line) + ": frame " + std::to_string(frame) + ", person " +
                       std::to_string(p) + ": identity " + std::to_string(person.identity) +
                       " is negative (ground-truth identities are track ids >= 0)");
    }
    auto joints = gt->AddPerson(person.identity);
    joints.leftCols(kFileJoints) = person.joints;
    const Eigen::Vector3d bottom = person.joints.col(kHeadBottom).head<3>();
    const Eigen::Vector3d top = person.joints.col(kHeadTop).head<3>();
    const Eigen::Vector3d nose = nose_proxy == HeadNoseProxy::kTop      ? top
                                 : nose_proxy == HeadNoseProxy::kBottom ? bottom
                                                                    : Eigen::Vector3d(0.5 * (bottom + top));
    joints.col(kNose) << nose, std::min(person.joints(3, kHeadBottom), person.joints(3, kHeadTop));
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
void AssembleView(const PafCandidates& candidates, const PafAssociationOptions& options, const Camera& camera,
                  Poses2D* view) {
  const int num_joints = static_cast<int>(CocoBodyJoints().size());
  view->Clear(num_joints);
  const double sx = camera.width - 1.0;
  const double sy = camera.height - 1.0;
  for (const PafPerson& person : AssociatePafs(Body25PafSkeleton(), candidates, options)) {
    auto joints = view->AddPerson();
    bool any = false;
    for (int c = 0; c < num_joints; ++c) {
      const int b = CocoFromBody25()[static_cast<size_t>(c)];
      const int candidate = person[static_cast<size_t>(b)];
      if (candidate < 0) continue;
      const auto point = candidates.joints[static_cast<size_t>(b)].col(candidate);
      joints.col(c) << point(0) * sx, point(1) * sy, point(2);
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
  return info;
}

std::vector<Sequence> ReadShelf4da(const DatasetRequest& request) {
  const Shelf4daParams params = ParseDatasetParams<Shelf4daParams>(kName, request);
  PafAssociationOptions association;
  association.min_paf_score = params.min_paf_score;
  association.min_joints = params.min_joints;
  std::error_code ec;
  if (!std::filesystem::is_directory(request.root, ec)) {
    throw InputError(std::string(kName) + ": root '" + request.root.string() + "' is not a directory");
  }

  Sequence sequence;
  sequence.name = kName;
  sequence.cameras = ReadFourDaCalibration(request.root / "calibration.json", &sequence.warnings);
  sequence.gt_joints = Shelf4daJoints();
  sequence.room = ShelfRoom();
  sequence.fps = kFps;

  const std::filesystem::path gt_path = request.root / "gt.txt";
  const std::string gt_source = gt_path.string();
  const FourDaSkeletons gt = ReadFourDaSkeletons(gt_path);
  if (gt.num_joints != kFileJoints) {
    throw InputError(gt_source + ":1: header: " + std::to_string(gt.num_joints) + " joints, expected " +
                     std::to_string(kFileJoints) + " (SHELF15)");
  }
  const std::vector<size_t> frames = SelectFrames(params.frames, gt.frames.size(), gt_source);
  for (const size_t f : frames) {
    SequenceFrame& frame = sequence.frames.emplace_back();
    frame.id = FrameId(f);
    frame.timestamp_s = static_cast<double>(f) / kFps;
    ConvertGroundTruth(gt.frames[f], params.nose_proxy, gt_source, f, &frame.gt);
  }

  if (params.detections == Shelf4daDetections::kOpenPose) {
    sequence.detection_joints = CocoBodyJoints();
    for (SequenceFrame& frame : sequence.frames) frame.views.resize(sequence.cameras.size());
    for (size_t c = 0; c < sequence.cameras.size(); ++c) {
      const Camera& camera = sequence.cameras[c];
      const std::filesystem::path path = request.root / "detection" / (camera.name + ".txt");
      const FourDaDetections detections = ReadFourDaDetections(path, &sequence.warnings);
      if (detections.frames.size() != gt.frames.size()) {
        throw InputError(path.string() + ":1: header: " + std::to_string(detections.frames.size()) + " frames, " +
                         gt_source + " has " + std::to_string(gt.frames.size()));
      }
      for (size_t i = 0; i < frames.size(); ++i) {
        AssembleView(detections.frames[frames[i]], association, camera, &sequence.frames[i].views[c]);
      }
    }
  }
  ValidateSequence(sequence, request.root.string());
  std::vector<Sequence> out;
  out.push_back(std::move(sequence));
  return out;
}

}  // namespace rpt
