// SPDX-License-Identifier: MIT
#include "cli/input_options.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <cmath>
#include <memory>
#include <string>

#include "cli/field_options.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::cli {

namespace {

// How the entries of --detections become frame ids, cameras and joints (engine/detection_mapping.h).
void AddDetectionMappingOptions(CLI::App* command, engine::DetectionMapping* mapping) {
  const std::string group = "Detection mapping (docs/own_data.md)";
  command
      ->add_option("--map-pattern", mapping->pattern,
                   "regular expression matching each file path of an OpenPose folder (relative to it), or each image "
                   "file_name of --coco-images; its groups feed --map-frame-id and --map-camera")
      ->group(group);
  command
      ->add_option("--map-frame-id", mapping->frame_id,
                   "frame id template: {N} group N, {N:W} zero-padded to W digits, {N:W+K} plus K (default {2:6})")
      ->group(group);
  command->add_option("--map-camera", mapping->camera, "camera name template (default {1}: the folder)")->group(group);
  command
      ->add_option("--openpose-joints", mapping->openpose_joints,
                   "joints read from an OpenPose folder: " + Join(engine::OpenPoseJointsNames(), "|") +
                       " (default auto: whole-body with face/hands, body-feet with BODY_25, else body)")
      ->check(CLI::IsMember(engine::OpenPoseJointsNames()))
      ->group(group);
  command
      ->add_option("--coco-images", mapping->coco_images,
                   "COCO annotation file whose \"images\" place the image ids of a COCO result list (by "
                   "\"frame_id\"/\"camera\" or by file_name, --map-*)")
      ->group(group);
  command
      ->add_option("--coco-image-ids", mapping->coco_image_ids,
                   "how a COCO result list's image ids become frames and cameras: images (the images of "
                   "--coco-images; default with it) or mvor (day*1e10 + cam*1e7 + frame; default without)")
      ->check(CLI::IsMember(engine::CocoImageIdsNames()))
      ->group(group);
  command
      ->add_option_function<double>(
          "--coco-min-score", [mapping](double score) { mapping->coco_min_score = score; },
          "COCO results with a lower person \"score\" are dropped (default: none)")
      ->check(CLI::NonNegativeNumber)
      ->group(group);
  command
      ->add_option("--coco-keypoints", mapping->coco_keypoints,
                   "the array of a COCO result holding the keypoints (default coco_keypoints when present, else "
                   "keypoints)")
      ->group(group);
  command
      ->add_option("--voxelpose-prefix", mapping->voxelpose_prefix,
                   "frame ids of a VoxelPose .pkl cache: <prefix>_<frame, 6 digits> (default: the sequence's name; "
                   "with --cameras the detections file's name)")
      ->group(group);
  command
      ->add_option("--rename-camera", mapping->rename_cameras,
                   "FROM=TO: camera FROM of the detections is camera TO of the calibration (repeatable; any format)")
      ->group(group);
}

void AddReaderOptions(CLI::App* command, engine::InputSpec* spec, const std::string& param_help) {
  command->add_option("--dataset", spec->dataset, "dataset reader (see `rpt datasets`)");
  command->add_option("--root", spec->root, "dataset folder in its original layout");
  command->add_option("--param", spec->params, param_help)->take_all();
}

void AddSourceOptions(CLI::App* command, engine::InputSpec* spec) {
  AddReaderOptions(command, spec,
                   "parameter key=value of the dataset reader, or with --labels of the labels file "
                   "(repeatable; see `rpt datasets`)");
  command->add_option("--labels", spec->labels, "generic labels file (skelda schema) instead of --dataset");
  command->add_option("--detections", spec->detections,
                      "2D detections: generic JSON, HDF5 cache, OpenPose folder, COCO result list or VoxelPose .pkl");
  AddDetectionMappingOptions(command, &spec->mapping);
}

void AddStrictOption(CLI::App* command, engine::InputSpec* spec) {
  command->add_flag("--strict", spec->strict,
                    "exit 2 when any input is not used (entries skipped, frames or files matching nothing); "
                    "corrections such as scores clamped to 1 are still accepted");
}

}  // namespace

void AddDatasetOptions(CLI::App* command, engine::InputSpec* spec) {
  AddReaderOptions(command, spec, "parameter key=value of the dataset reader (repeatable; see `rpt datasets`)");
}

void AddCamerasOptions(CLI::App* command, engine::InputSpec* spec) {
  command->add_option("--cameras", spec->cameras,
                      "calibration file instead of --dataset / --labels (our JSON, OpenCV yml/xml, EasyMocap "
                      "intri/extri, Pose2Sim/anipose toml, COLMAP, VoxelPose, Panoptic, 4D-Association; "
                      "docs/cameras.md): the frames are those of --detections");
  // How it is read: --cameras-format, --cameras-units, --cameras-image-width, --cameras-image-height
  // (the options of `rpt cameras show`), parsed once the command line is read.
  auto read = std::make_shared<FieldOptions<CalibrationReadOptions>>(command, "cameras-", "with --cameras, reading: ");
  command->parse_complete_callback([spec, read] { spec->camera_read = read->Parse(); });
  command->add_option("--fps", spec->fps, "with --cameras: frame rate of the detection frames (default: times unknown)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double rate = 0;
            try {
              rate = std::stod(text);
            } catch (const std::exception&) {
              return "expected a number of frames per second, got " + text;
            }
            return std::isfinite(rate) && rate > 0 ? "" : "expected a frame rate above 0 (frames per second), got " + text;
          },
          ""));
}

void AddDetectionInputOptions(CLI::App* command, engine::InputSpec* spec) {
  spec->ground_truth = false;
  AddSourceOptions(command, spec);
  AddCamerasOptions(command, spec);
  AddStrictOption(command, spec);
}

void AddInputOptions(CLI::App* command, engine::InputSpec* spec) {
  AddSourceOptions(command, spec);
  command->add_flag("--simulate", spec->simulate, "simulate 2D detections from the ground truth");
  command->add_option("--detector", spec->detector,
                      "with --simulate: detector profile " + Join(synthetic::DetectorProfileNames(), "|") +
                          " (default realistic; docs/detector_model.md)")
      ->check(CLI::IsMember(synthetic::DetectorProfileNames()));
  command->add_flag("--simulate-perfect", spec->simulate_perfect,
                    "deprecated: same as --detector perfect (exact projections, no noise)");
  command->add_option("--seed", spec->seed, "with --simulate: seed of the simulated detector")
      ->capture_default_str()
      ->each([spec](const std::string&) { spec->seed_given = true; });
  AddStrictOption(command, spec);
}

engine::Input OpenInputTimed(const engine::InputSpec& spec, double* seconds) {
  constexpr std::uintmax_t kAnnouncedBytes = 64u << 20;
  if (::isatty(STDERR_FILENO)) {
    for (const std::string& file : {spec.detections, spec.labels}) {
      std::error_code ec;
      if (file.empty() || !std::filesystem::is_regular_file(file, ec)) continue;
      const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
      if (ec || bytes < kAnnouncedBytes) continue;
      std::fprintf(stderr, "reading %s (%.0f MB) ...\n", PrintableText(file, LineBreaks::kEscape).c_str(),
                   static_cast<double>(bytes) / 1e6);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  engine::Input input = engine::OpenInput(spec);
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return input;
}

void PrintInputReadTime(double seconds) {
  if (seconds < 1.0) return;
  std::printf("  reading the input took %.2f s before the frames (not in the rate above)\n", seconds);
}

void PrintInputWarnings(const InputWarnings& warnings) {
  for (const InputWarning& w : warnings.items()) std::fprintf(stderr, "warning: %s\n", w.Line().c_str());
  std::fflush(stderr);
}

}  // namespace rpt::cli
