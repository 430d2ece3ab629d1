// SPDX-License-Identifier: MIT
#include "engine/input.h"

#include <algorithm>
#include <filesystem>
#include <new>
#include <string_view>
#include <utility>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/calibration/calibration.h"
#include "datasets/readers/detection_frames.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/simulated_source.h"
#include "engine/attached_detections.h"
#include "engine/checked_source.h"
#include "engine/dataset_registry.h"

namespace rpt::engine {

void CheckInputSpec(const InputSpec& spec) {
  const int named = !spec.dataset.empty() + !spec.labels.empty() + !spec.cameras.empty();
  if (named != 1) {
    throw ConfigError(std::string("give one of --dataset NAME (with --root DIR), --labels FILE") +
                      (spec.ground_truth ? "" : " or --cameras FILE (with --detections)"));
  }
  CheckDatasetAndRoot(spec);
  if (!spec.cameras.empty()) {
    if (spec.detections.empty()) throw ConfigError("--cameras needs --detections FILE (the frames are its frames)");
    if (!spec.params.empty()) {
      throw ConfigError("--param " + spec.params.front() + ": parameters belong to --dataset or --labels, not --cameras");
    }
  }
  if (spec.fps != 0 && spec.cameras.empty()) {
    throw ConfigError("--fps applies to --cameras (datasets and labels give their own times; labels: --param fps=N)");
  }
  if (!(spec.fps >= 0)) throw ConfigError("--fps " + std::to_string(spec.fps) + ": expected a rate >= 0");
  CheckDetectionMapping(spec.mapping, spec.detections);
  if (!spec.ground_truth && spec.simulate) throw ConfigError("--simulate needs the ground truth (not with triangulate)");
  if (spec.simulate && !spec.detections.empty()) throw ConfigError("--simulate and --detections exclude each other");
  if (!spec.simulate && (!spec.detector.empty() || spec.simulate_perfect)) {
    throw ConfigError(std::string(spec.simulate_perfect ? "--simulate-perfect" : "--detector") +
                      " needs --simulate (the synthetic dataset takes --param noise=PROFILE)");
  }
  if (!spec.simulate && spec.seed_given) {
    throw ConfigError("--seed seeds the simulated detector: it needs --simulate (the synthetic dataset's own "
                      "detections take --param seed=N)");
  }
  if (spec.simulate_perfect && !spec.detector.empty() && spec.detector != "perfect") {
    throw ConfigError("--simulate-perfect (deprecated) contradicts --detector " + spec.detector);
  }
  // The synthetic dataset's own detector is replaced by --simulate's: without a --detector naming
  // it, the noise asked for would be ignored unseen.
  // With a --detector of another profile, the noise asked for would be ignored unseen as well.
  if (spec.simulate && !spec.simulate_perfect && spec.labels.empty() && spec.dataset == "synthetic") {
    constexpr std::string_view kNoise = "noise=";
    for (const std::string& assignment : spec.params) {
      if (!assignment.starts_with(kNoise)) continue;
      const std::string noise = assignment.substr(kNoise.size());
      if (noise == spec.detector) continue;
      throw ConfigError("--param " + assignment + " has no effect with --simulate, whose detector (--detector " +
                        (spec.detector.empty() ? std::string("realistic, the default") : spec.detector) +
                        ") replaces the dataset's: give --detector " + noise + " with --simulate, or --param " +
                        assignment + " without it");
    }
  }
  if (!spec.detector.empty()) {
    const std::vector<std::string>& profiles = synthetic::DetectorProfileNames();
    if (std::find(profiles.begin(), profiles.end(), spec.detector) == profiles.end())
      throw ConfigError("--detector " + QuoteName(spec.detector) + ": unknown profile" +
                        DidYouMean(spec.detector, profiles) + "; known: " + Join(profiles));
  }
}

void CheckDatasetAndRoot(const InputSpec& spec) {
  if (spec.dataset.empty() || !spec.labels.empty()) return;
  CheckDatasetName(spec.dataset);
  // The synthetic dataset is generated: a folder given to it would be ignored unseen (a typo in a
  // thresholds file's root would turn its evaluation into a skipped one elsewhere).
  if (spec.dataset == "synthetic" && !spec.root.empty())
    throw ConfigError("--root " + PrintableText(spec.root) + ": the synthetic dataset is generated and reads no folder");
}

namespace {

// The reader request: --labels FILE is the generic labels reader with the file as its root, so
// --param reaches it like any reader's.
DatasetRequest RequestOf(const InputSpec& spec) {
  DatasetRequest request;
  request.dataset = spec.labels.empty() ? spec.dataset : "generic";
  request.root = spec.labels.empty() ? spec.root : spec.labels;
  request.ground_truth = spec.ground_truth;
  for (const std::string& assignment : spec.params) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw ConfigError("--param " + assignment + ": expected key=value");
    request.params[assignment.substr(0, eq)] = assignment.substr(eq + 1);
  }
  return request;
}

bool IsVoxelPoseCache(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  return extension == ".pkl" || extension == ".pickle";
}

// The reader's own sources of 2D detections: its "detections" parameter's values other than none
// ("openpose" for mvor, "voxelpose" for shelf); empty when it has none.
std::vector<std::string> OwnDetectionValues(const std::string& dataset) {
  std::vector<std::string> values;
  if (const DatasetInfo* info = FindDatasetInfo(dataset)) {
    for (const DatasetParam& param : info->params) {
      if (param.name != "detections") continue;
      std::string rest = param.type;  // "none | voxelpose"
      while (!rest.empty()) {
        const size_t bar = rest.find('|');
        std::string value = rest.substr(0, bar);
        value.erase(0, value.find_first_not_of(' '));
        value.erase(value.find_last_not_of(' ') + 1);
        if (!value.empty() && value != "none") values.push_back(value);
        rest = bar == std::string::npos ? "" : rest.substr(bar + 1);
      }
    }
  }
  return values;
}

std::string NoDetectionsMessage(const std::string& sequence, const std::string& dataset, bool python_names) {
  std::string message = "sequence " + QuoteName(sequence) + " has no 2D detections: pass " +
                        (python_names ? "detections_file=FILE or simulate=True" : "--detections FILE or --simulate");
  const std::vector<std::string> own = OwnDetectionValues(dataset);
  if (own.empty()) return message;
  message += ", or the dataset's own (";
  for (size_t i = 0; i < own.size(); ++i) {
    message += (i ? " or " : "") + (python_names ? "detections='" + own[i] + "'" : "--param detections=" + own[i]);
  }
  return message + ")";
}

}  // namespace

Input::Input(std::vector<std::unique_ptr<FrameSource>> sources, InputWarnings opened, bool strict,
             std::shared_ptr<AttachedDetections> attached,
             std::vector<std::shared_ptr<AttachedDetections>> per_sequence_files)
    : sources_(std::move(sources)),
      finished_(sources_.size()),
      done_(sources_.size(), false),
      opened_(std::move(opened)),
      strict_(strict),
      attached_(std::move(attached)),
      per_sequence_files_(std::move(per_sequence_files)) {
  headers_.reserve(sources_.size());
  for (const auto& source : sources_) headers_.push_back(source->header());
}

Input::~Input() = default;
Input::Input(Input&&) noexcept = default;
Input& Input::operator=(Input&&) noexcept = default;

void Input::Finished(int i) {
  if (done_[i]) return;
  finished_[i] = sources_[i]->warnings();
  done_[i] = true;
  sources_[i].reset();  // whatever the reader still holds
}

InputWarnings Input::Warnings() const {
  // The readers' first (sequence order), then the detections file's, then what the file and the
  // sequences did not use of each other.
  InputWarnings all;
  bool every_done = true;
  for (size_t i = 0; i < sources_.size(); ++i) {
    all.Merge(done_[i] ? finished_[i] : sources_[i]->warnings());
    every_done = every_done && done_[i];
  }
  all.Merge(opened_);
  if (every_done) {
    if (attached_) all.Merge(attached_->Unused());
    for (const auto& file : per_sequence_files_) all.Merge(file->Unused());
  }
  return all;
}

void Input::CheckStrict() const { engine::CheckStrict(strict_, Warnings()); }

std::vector<Sequence> Input::Materialize(long max_frames) {
  std::vector<Sequence> sequences;
  sequences.reserve(sources_.size());
  long frames = 0;
  for (int i = 0; i < size(); ++i) {
    sequences.push_back(rpt::Materialize(*sources_[i], max_frames < 0 ? -1 : max_frames - frames));
    frames += static_cast<long>(sequences.back().frames.size());
    sequences.back().warnings = {};  // in Warnings(): not twice
    Finished(i);
  }
  CheckStrict();
  return sequences;
}

namespace {

// --cameras FILE --detections FILE: one sequence of the detection frames, named after the
// detections file (a VoxelPose cache's frame ids "<name>_<frame>" unless --voxelpose-prefix).
std::vector<std::unique_ptr<FrameSource>> OpenDetectionsOnCameras(const InputSpec& spec, InputWarnings* opened) {
  Calibration calibration = ReadCalibration(spec.cameras, spec.camera_read, opened);
  std::filesystem::path path(spec.detections);
  DetectionFramesOptions options;
  options.name = (path.has_filename() ? path : path.parent_path()).stem().string();
  options.fps = spec.fps;
  VoxelPoseDetectionsOptions voxelpose;
  voxelpose.frame_id_prefix = options.name;
  for (const Camera& camera : calibration.cameras) voxelpose.cameras.push_back(camera.name);
  CheckRenameTargets(spec.mapping, voxelpose.cameras, spec.cameras);
  Detections detections = ReadMappedDetections(spec.detections, spec.mapping, voxelpose);
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(
      OpenDetectionFrames(std::move(calibration.cameras), std::move(detections), options, spec.cameras, path));
  return sources;
}

}  // namespace

Input OpenInput(const InputSpec& spec, const InputNeeds& needs) {
  CheckInputSpec(spec);
  InputWarnings opened;
  if (!spec.cameras.empty()) {
    std::vector<std::unique_ptr<FrameSource>> sources = OpenDetectionsOnCameras(spec, &opened);
    for (auto& source : sources) source = std::make_unique<CheckedSource>(std::move(source));
    Input input(std::move(sources), std::move(opened), spec.strict);
    input.set_detections_file(spec.detections);
    input.set_cameras_origin(spec.cameras);
    input.set_frames_origin(spec.detections);
    input.CheckStrict();
    return input;
  }
  std::vector<std::unique_ptr<FrameSource>> sources = OpenDataset(RequestOf(spec));
  std::shared_ptr<AttachedDetections> attached;
  std::vector<std::shared_ptr<AttachedDetections>> per_sequence_files;
  if (spec.simulate) {
    for (auto& source : sources) {
      source = std::make_unique<SimulatedDetectionsSource>(std::move(source), SimulationOf(spec));
    }
  } else if (IsVoxelPoseCache(spec.detections)) {
    // A VoxelPose cache is keyed "<camera>_<frame>": read per sequence, with its cameras and its
    // name as the frame-id prefix ("shelf" -> "shelf_000300"); it covers every image, so frames no
    // sequence uses are not reported.
    for (auto& source : sources) {
      VoxelPoseDetectionsOptions voxelpose;
      voxelpose.frame_id_prefix = source->header().name;
      for (const Camera& camera : source->header().cameras) voxelpose.cameras.push_back(camera.name);
      auto file = std::make_shared<AttachedDetections>(ReadMappedDetections(spec.detections, spec.mapping, voxelpose),
                                                       spec.detections, /*report_unused_frames=*/false);
      opened.Merge(file->file_warnings());
      source = file->Wrap(std::move(source));
      per_sequence_files.push_back(std::move(file));
    }
  } else if (!spec.detections.empty()) {
    // One file for all sequences: each frame goes to the sequence that holds its id.
    attached =
        std::make_shared<AttachedDetections>(ReadMappedDetections(spec.detections, spec.mapping), spec.detections);
    if (const DatasetInfo* info = FindDatasetInfo(spec.dataset); spec.labels.empty() && info != nullptr) {
      attached->SetDatasetFrameIdPrefix(info->frame_id_prefix);
    }
    opened.Merge(attached->file_warnings());  // once, however many sequences use it
    for (auto& source : sources) source = attached->Wrap(std::move(source));
  }
  for (auto& source : sources) {
    if (needs.detections && source->header().detection_joints.empty()) {
      throw InputError(NoDetectionsMessage(source->header().name, spec.dataset, needs.python_names));
    }
    source = std::make_unique<CheckedSource>(std::move(source));
  }
  Input input(std::move(sources), std::move(opened), spec.strict, std::move(attached), std::move(per_sequence_files));
  if (!spec.simulate) input.set_detections_file(spec.detections);
  input.set_cameras_origin(spec.labels.empty() ? spec.root : spec.labels);
  // What the readers found unusable while opening (e.g. files not matching the reader's pattern);
  // the rest is known once the sources are exhausted (the run loop checks again then).
  input.CheckStrict();
  return input;
}

std::vector<Sequence> LoadInput(const InputSpec& spec, const InputNeeds& needs, InputWarnings* warnings,
                                long max_frames) {
  try {
    Input input = OpenInput(spec, needs);
    std::vector<Sequence> sequences = input.Materialize(max_frames);
    warnings->Merge(input.Warnings());
    return sequences;
  } catch (const std::bad_alloc&) {
    std::string paths;
    for (const std::string& path : {spec.root, spec.labels, spec.detections}) {
      if (!path.empty()) paths += (paths.empty() ? "" : ", ") + path;
    }
    throw InputError((paths.empty() ? "dataset " + spec.dataset : paths) +
                     ": out of memory reading the input whole (it is too large for this machine's memory)");
  }
}

std::vector<std::pair<std::string, std::string>> ResolvedInputSettings(const InputSpec& spec) {
  std::vector<std::pair<std::string, std::string>> settings;
  if (spec.cameras.empty()) {
    const DatasetRequest request = RequestOf(spec);
    settings.emplace_back("reader", request.dataset);
    if (const DatasetInfo* info = FindDatasetInfo(request.dataset)) {
      for (const DatasetParam& param : info->params) {
        const auto given = request.params.find(param.name);
        settings.emplace_back("param." + param.name, given != request.params.end() ? given->second : param.default_value);
      }
    }
  }
  if (spec.simulate) {
    settings.emplace_back("detector", SimulationOf(spec).detector);
    settings.emplace_back("seed", std::to_string(spec.seed));
  }
  return settings;
}

std::string TooFewCamerasMessage(const std::vector<Camera>& cameras) {
  std::string names;
  for (const Camera& camera : cameras) names += (names.empty() ? "" : ", ") + QuoteName(camera.name);
  return std::to_string(cameras.size()) + (cameras.size() == 1 ? " camera" : " cameras") +
         (names.empty() ? "" : " (" + names + ")") +
         ": rpt triangulates from 2 or more calibrated cameras that see the same persons; give the "
         "calibration of every camera of the recording";
}

SimulationOptions SimulationOf(const InputSpec& spec) {
  SimulationOptions simulation;
  simulation.seed = spec.seed;
  simulation.detector = spec.simulate_perfect ? "perfect" : spec.detector.empty() ? "realistic" : spec.detector;
  return simulation;
}

void CheckStrict(bool strict, const InputWarnings& warnings) {
  const std::vector<InputWarning> unused = warnings.Unused();
  if (!strict || unused.empty()) return;
  std::string message = "--strict: part of the input is not used (" + std::to_string(unused.size()) + " warning(s)):";
  for (const InputWarning& w : unused) message += "\n  warning: " + w.Line();
  throw InputError(message);
}

std::vector<std::string> InputWarningLines(const InputWarnings& warnings) {
  std::vector<std::string> lines;
  for (const InputWarning& w : warnings.items()) lines.push_back(w.Line());
  return lines;
}

}  // namespace rpt::engine
