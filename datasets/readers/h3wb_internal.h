// SPDX-License-Identifier: MIT
// Internal to the H3WB reader (datasets/readers/h3wb*.cc): its options and the clips both
// annotation formats are read into (h3wb.cc reads the npz, h3wb_json.cc the json files).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/input_warnings.h"

namespace rpt::h3wb {

namespace fs = std::filesystem;

inline constexpr int kJoints = 133;
inline constexpr double kFps = 50.0;
// Subjects tried when the json does not say which subject a frame belongs to.
inline const std::vector<std::string> kCandidateSubjects = {"S1", "S5", "S6", "S7", "S8", "S9", "S11"};

struct Options {
  fs::path root;
  fs::path file;
  bool npz = true;
  std::vector<std::string> subjects;
  std::vector<std::string> actions;
  std::string cameras_file;  // json only
  DistortionModel model = DistortionModel::kH36M;
  double global_to_m = 0.001;
  std::string global_units = "mm";
  int every = 1;
  int max_frames = 0;
  bool detections = false;  // attach the stored 2D as detections
};

// One sequence of the annotation file: its selected frames are converted one at a time from the
// parsed file (`convert` holds it).
struct Clip {
  std::string subject;
  std::string action;  // sanitised; "json" for id-grouped json frames
  bool sample_ids = false;  // frame numbers are sample ids (json without image paths)
  std::vector<Camera> cameras;
  std::vector<long long> numbers;  // per selected frame: its frame number (or first sample id), ascending
  std::string source;
  InputWarnings warnings;  // corrections of the cameras (carried by the subject's first clip)
  // Selected frame `i`: the GT pose in world metres (3 x 133) and, when 2D was asked for, per clip
  // camera the stored 2D pose (nullopt where the view has none). Throws InputError for
  // non-finite values and views that disagree.
  std::function<void(std::size_t i, Eigen::Matrix3Xd* world_m, std::vector<std::optional<Eigen::Matrix2Xd>>* pose_2d)>
      convert;
};

// `action` (sanitised) is selected by `filters` (empty = all): "Directions" selects "Directions-1".
bool ActionMatches(const std::string& action, const std::vector<std::string>& filters);

// The clips of a json annotation file (RGBto3D_train.json / 2Dto3D_train.json layouts).
std::vector<Clip> ReadJsonClips(const Options& options, bool want_2d);

}  // namespace rpt::h3wb
