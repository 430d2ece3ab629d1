// SPDX-License-Identifier: MIT
#include "cli/load_input.h"

#include <cstdio>
#include <filesystem>
#include <unordered_set>

#include "core/errors.h"
#include "core/text.h"
#include "datasets/detections.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/registry.h"
#include "datasets/simulated_source.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::cli {

void AddInputOptions(CLI::App* command, InputArgs* args) {
  command->add_option("--dataset", args->dataset, "dataset reader (see `rpt datasets`)");
  command->add_option("--root", args->root, "dataset folder in its original layout");
  command->add_option("--param", args->params, "dataset parameter key=value (repeatable; see `rpt datasets`)")
      ->take_all();
  command->add_option("--labels", args->labels, "generic labels file (skelda schema) instead of --dataset");
  command->add_option("--detections", args->detections,
                      "2D detections: generic JSON, HDF5 cache, OpenPose folder or COCO result list");
  command->add_flag("--simulate", args->simulate, "simulate 2D detections from the ground truth");
  command->add_option("--detector", args->detector,
                      "with --simulate: detector profile " + Join(synthetic::DetectorProfileNames(), "|") +
                          " (default realistic; docs/detector_model.md)")
      ->check(CLI::IsMember(synthetic::DetectorProfileNames()));
  command->add_flag("--simulate-perfect", args->simulate_perfect,
                    "deprecated: same as --detector perfect (exact projections, no noise)");
  command->add_option("--seed", args->seed, "seed of the simulated detector")->capture_default_str();
  command->add_flag("--strict", args->strict,
                    "exit 2 when any input is not used (entries skipped, frames or files matching nothing); "
                    "corrections such as scores clamped to 1 are still accepted");
}

namespace {

// Throws ConfigError on contradicting input options.
void CheckInputArgs(const InputArgs& args) {
  if (args.dataset.empty() == args.labels.empty()) {
    throw ConfigError("give either --dataset NAME (with --root DIR) or --labels FILE");
  }
  if (args.simulate && !args.detections.empty()) throw ConfigError("--simulate and --detections exclude each other");
  if (!args.simulate && (!args.detector.empty() || args.simulate_perfect)) {
    throw ConfigError(std::string(args.simulate_perfect ? "--simulate-perfect" : "--detector") +
                      " needs --simulate (the synthetic dataset takes --param noise=PROFILE)");
  }
  if (args.simulate_perfect && !args.detector.empty() && args.detector != "perfect") {
    throw ConfigError("--simulate-perfect (deprecated) contradicts --detector " + args.detector);
  }
}

DatasetRequest RequestOf(const InputArgs& args) {
  DatasetRequest request;
  request.dataset = args.dataset;
  request.root = args.root;
  for (const std::string& assignment : args.params) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw ConfigError("--param " + assignment + ": expected key=value");
    request.params[assignment.substr(0, eq)] = assignment.substr(eq + 1);
  }
  return request;
}

std::string NoDetectionsMessage(const std::string& sequence) {
  return "sequence '" + sequence +
         "' has no 2D detections: pass --detections FILE, --simulate, or the dataset's own cache "
         "(e.g. --param detections=voxelpose)";
}

}  // namespace

SimulationOptions SimulationOf(const InputArgs& args) {
  SimulationOptions simulation;
  simulation.seed = args.seed;
  simulation.detector = args.simulate_perfect ? "perfect" : args.detector.empty() ? "realistic" : args.detector;
  return simulation;
}

std::vector<Sequence> LoadInput(const InputArgs& args, bool require_detections, InputWarnings* warnings) {
  CheckInputArgs(args);
  std::vector<Sequence> sequences;
  InputWarnings detection_warnings;  // of a detections file read once for all sequences
  if (!args.labels.empty()) {
    sequences = MaterializeAll(OpenLabelsFile(args.labels, LabelsOptions{}));
  } else {
    sequences = ReadDataset(RequestOf(args));
  }
  if (args.simulate) {
    for (Sequence& s : sequences) SimulateDetections(SimulationOf(args), &s);
  } else if (!args.detections.empty() && std::filesystem::path(args.detections).extension() == ".pkl") {
    // VoxelPose caches are keyed "<camera>_<frame>": they need the sequence's cameras and frame-id
    // prefix to map keys to ids; they cover every image, so frames not in the sequence are left out.
    for (Sequence& s : sequences) {
      DetectionsFileOptions options;
      options.voxelpose.frame_id_prefix =
          s.frames.empty() ? s.name : s.frames.front().id.substr(0, s.frames.front().id.rfind('_'));
      for (const Camera& camera : s.cameras) options.voxelpose.cameras.push_back(camera.name);
      Detections detections = ReadDetectionsFile(args.detections, options);
      std::unordered_set<std::string> ids;
      for (const SequenceFrame& frame : s.frames) ids.insert(frame.id);
      std::erase_if(detections.frames, [&](const FrameDetections& frame) { return !ids.count(frame.frame_id); });
      AttachDetections(detections, args.detections, std::span<Sequence>(&s, 1), &s.warnings);
      s.warnings.Merge(detections.warnings);  // read per sequence: its own frames' corrections
    }
  } else if (!args.detections.empty()) {
    // One file for all sequences (the scenes of a labels file): each frame goes to its sequence,
    // with the same errors and counted warnings as for a single sequence.
    const Detections detections = ReadDetectionsFile(args.detections, DetectionsFileOptions{});
    detection_warnings = detections.warnings;  // once, however many sequences it is attached to
    AttachDetections(detections, args.detections, sequences, &detection_warnings);
  }
  InputWarnings loaded;
  for (const Sequence& s : sequences) loaded.Merge(s.warnings);
  loaded.Merge(detection_warnings);
  CheckStrict(args.strict, loaded);
  warnings->Merge(loaded);
  for (const Sequence& s : sequences) {
    ValidateSequence(s, s.name);
    if (!require_detections) continue;
    bool any = false;
    for (const SequenceFrame& f : s.frames) any |= !f.views.empty();
    if (!any) {
      throw InputError(NoDetectionsMessage(s.name));
    }
  }
  return sequences;
}

std::vector<std::unique_ptr<FrameSource>> OpenInput(const InputArgs& args, bool require_detections,
                                                    InputWarnings* warnings) {
  CheckInputArgs(args);
  if (args.dataset.empty() || !args.detections.empty()) {
    std::vector<Sequence> sequences = LoadInput(args, require_detections, warnings);
    for (Sequence& s : sequences) s.warnings = {};  // in `warnings` already: not twice
    return SourcesOf(std::move(sequences));
  }
  // Every reader streams; with its own or simulated detections nothing is loaded whole. Streamed
  // frames are validated as they come (cli/run_sequence.h).
  std::vector<std::unique_ptr<FrameSource>> sources = OpenDataset(RequestOf(args));
  if (args.simulate) {
    for (auto& source : sources) {
      source = std::make_unique<SimulatedDetectionsSource>(std::move(source), SimulationOf(args));
    }
  }
  for (const auto& source : sources) {
    if (require_detections && source->header().detection_joints.empty()) {  // a reader without its own
      throw InputError(NoDetectionsMessage(source->header().name));
    }
  }
  // What the sources found unusable so far (e.g. files not matching the reader's pattern); the
  // rest is known once they are exhausted: the consumer checks their warnings again then.
  for (const auto& source : sources) CheckStrict(args.strict, source->warnings());
  return sources;
}

void CheckStrict(bool strict, const InputWarnings& warnings) {
  const std::vector<InputWarning> unused = warnings.Unused();
  if (!strict || unused.empty()) return;
  std::string message = "--strict: part of the input is not used (" + std::to_string(unused.size()) + " warning(s)):";
  for (const InputWarning& w : unused) message += "\n  warning: " + w.Line();
  throw InputError(message);
}

void PrintInputWarnings(const InputWarnings& warnings) {
  for (const InputWarning& w : warnings.items()) std::fprintf(stderr, "warning: %s\n", w.Line().c_str());
  std::fflush(stderr);
}

std::vector<std::string> InputWarningLines(const InputWarnings& warnings) {
  std::vector<std::string> lines;
  for (const InputWarning& w : warnings.items()) lines.push_back(w.Line());
  return lines;
}

}  // namespace rpt::cli
