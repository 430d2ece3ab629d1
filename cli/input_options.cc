// SPDX-License-Identifier: MIT
#include "cli/input_options.h"

#include <cstdio>

#include "core/text.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::cli {

namespace {

void AddSourceOptions(CLI::App* command, engine::InputSpec* spec) {
  command->add_option("--dataset", spec->dataset, "dataset reader (see `rpt datasets`)");
  command->add_option("--root", spec->root, "dataset folder in its original layout");
  command->add_option("--param", spec->params,
                      "parameter key=value of the dataset reader, or with --labels of the labels file "
                      "(repeatable; see `rpt datasets`)")
      ->take_all();
  command->add_option("--labels", spec->labels, "generic labels file (skelda schema) instead of --dataset");
  command->add_option("--detections", spec->detections,
                      "2D detections: generic JSON, HDF5 cache, OpenPose folder, COCO result list or VoxelPose .pkl");
}

void AddStrictOption(CLI::App* command, engine::InputSpec* spec) {
  command->add_flag("--strict", spec->strict,
                    "exit 2 when any input is not used (entries skipped, frames or files matching nothing); "
                    "corrections such as scores clamped to 1 are still accepted");
}

void AddCamerasOptions(CLI::App* command, engine::InputSpec* spec) {
  command->add_option("--cameras", spec->cameras,
                      "calibration file instead of --dataset / --labels (our JSON, OpenCV yml/xml, EasyMocap "
                      "intri/extri, Pose2Sim/anipose toml, COLMAP, VoxelPose, Panoptic, 4D-Association; "
                      "docs/cameras.md): the frames are those of --detections");
  command->add_option("--fps", spec->fps, "with --cameras: frame rate of the detection frames (default: times unknown)")
      ->check(CLI::PositiveNumber);
}

}  // namespace

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
  command->add_option("--seed", spec->seed, "seed of the simulated detector")->capture_default_str();
  AddStrictOption(command, spec);
}

void PrintInputWarnings(const InputWarnings& warnings) {
  for (const InputWarning& w : warnings.items()) std::fprintf(stderr, "warning: %s\n", w.Line().c_str());
  std::fflush(stderr);
}

}  // namespace rpt::cli
