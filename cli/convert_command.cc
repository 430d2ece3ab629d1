// SPDX-License-Identifier: MIT
// `rpt convert`: any readable input (dataset or labels, with detections) into one HDF5 cache
// that loads much faster than JSON; `--labels-out` / `--detections-out` also write the generic
// JSON interchange files. Every command that takes --labels / --detections accepts the cache.
// Every output is written beside its file, and all are renamed over their files once all are complete
// (io::StagedFile).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "cli/commands.h"
#include "cli/input_options.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/staged_output.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "engine/input.h"

namespace rpt::cli {
namespace {

struct ConvertArgs {
  engine::InputSpec input;
  std::string out;             // HDF5 cache
  std::string labels_out;      // generic labels JSON
  std::string detections_out;  // generic detections JSON
  bool float64 = false;
};

Detections CollectDetections(const std::vector<Sequence>& sequences) {
  Detections detections;
  detections.unlisted_cameras_unavailable = true;  // a view without data this frame is left out
  for (const Sequence& s : sequences) {
    if (detections.joints.empty()) detections.joints = s.detection_joints;
    if (!s.detection_joints.empty() && s.detection_joints != detections.joints) {
      throw InputError("sequence " + QuoteName(s.name) + " has other detection joints than the first sequence");
    }
    for (const SequenceFrame& f : s.frames) {
      if (f.views.empty()) continue;
      FrameDetections frame;
      frame.frame_id = f.id;
      frame.time_s = f.timestamp_s;  // for a run with --cameras instead of the labels
      for (size_t v = 0; v < f.views.size(); ++v) {
        if (f.views[v].unavailable) continue;
        frame.cameras.push_back(s.cameras[v].name);
        frame.views.push_back(f.views[v]);
      }
      detections.frames.push_back(std::move(frame));
    }
  }
  return detections;
}

void RunConvert(const ConvertArgs& args) {
  if (args.out.empty() && args.labels_out.empty() && args.detections_out.empty()) {
    throw ConfigError("nothing to write: give --out CACHE.h5, --labels-out FILE.json or --detections-out FILE.json");
  }
  if (!args.labels_out.empty() && args.input.dataset.empty() && args.input.labels.empty()) {
    throw ConfigError("--labels-out needs labels: give --dataset NAME --root DIR or --labels FILE");
  }
  // Detections alone (no --dataset / --labels): convert the file as it is.
  const bool detections_only = args.input.dataset.empty() && args.input.labels.empty() && !args.input.detections.empty();
  // Corrected values (scores clamped to 1, rotations re-orthonormalised) are what gets written.
  InputWarnings warnings;
  std::vector<Sequence> sequences =
      detections_only ? std::vector<Sequence>{} : engine::LoadInput(args.input, {.detections = false}, &warnings);
  // GT ids that number the persons of a frame (MVOR's person_id) are written as no id (-1): the
  // files written have no such flag, and their ids would be read as identities across frames
  // (eval counted 668 identity switches over 688 matches on converted MVOR).
  for (Sequence& sequence : sequences) {
    if (sequence.gt_ids_across_frames) continue;
    for (SequenceFrame& frame : sequence.frames) std::fill(frame.gt.track_ids.begin(), frame.gt.track_ids.end(), -1);
  }
  const Detections detections = detections_only
                                    ? engine::ReadMappedDetections(args.input.detections, args.input.mapping)
                                    : CollectDetections(sequences);
  warnings.Merge(detections.warnings);  // empty unless read directly above
  engine::CheckStrict(args.input.strict, warnings);  // engine::LoadInput checked its own; this covers the direct read
  PrintInputWarnings(warnings);
  std::vector<std::unique_ptr<io::ParentFolders>> folders;  // removed again, while empty, on failure
  for (const std::string& file : {args.out, args.labels_out, args.detections_out}) {
    if (!file.empty()) folders.push_back(std::make_unique<io::ParentFolders>(file));
  }
  // Every output is written beside its file first and all are renamed over their files at the end,
  // one after the other: an interrupted or failed conversion leaves every old output as it was (the
  // cache used to be renamed into place before the JSON files were written: an interrupt then left
  // a new cache beside old JSON files, and said "finished outputs unchanged").
  std::vector<std::unique_ptr<io::StagedFile>> staged;
  // Runs `write` on the temporary of `file`; its errors name the file, not the temporary.
  const auto stage = [&staged](const std::string& file, const std::function<void(const std::filesystem::path&)>& write) {
    staged.push_back(std::make_unique<io::StagedFile>(file, io::NamedBy::kUser));
    const std::string temporary = staged.back()->path().string();
    try {
      write(staged.back()->path());
    } catch (const InputError& e) {
      std::string message = e.what();
      for (size_t at; (at = message.find(temporary)) != std::string::npos;) message.replace(at, temporary.size(), file);
      throw InputError(message);
    }
  };
  if (!args.out.empty() && (!sequences.empty() || !detections.frames.empty())) {
    std::error_code ec;
    const auto status = std::filesystem::status(args.out, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
      throw InputError(args.out + ": not a regular file (an HDF5 cache cannot be written to a device or pipe)");
    }
    stage(args.out, [&](const std::filesystem::path& path) {
      Hdf5WriteOptions options;
      options.float64 = args.float64;
      if (!sequences.empty()) {
        WriteSequencesHdf5(path, sequences, options);
        options.add_to_existing = true;
      }
      if (!detections.frames.empty()) WriteDetectionsHdf5(path, detections, options);
    });
  }
  std::vector<std::pair<std::string, int>> replaced;  // per JSON output: strings not valid UTF-8
  if (!args.labels_out.empty()) {
    stage(args.labels_out, [&](const std::filesystem::path& path) {
      replaced.emplace_back(args.labels_out, WriteLabels(path, sequences));
    });
  }
  if (!args.detections_out.empty()) {
    if (detections.frames.empty()) throw InputError("the input has no detections to write to " + args.detections_out);
    stage(args.detections_out, [&](const std::filesystem::path& path) {
      replaced.emplace_back(args.detections_out, WriteGenericDetections(path, detections));
    });
  }
  for (const auto& file : staged) file->Commit();
  for (const auto& [file, count] : replaced) {
    if (count > 0) {
      std::fprintf(stderr, "warning: %s: %d string(s) not valid UTF-8 (frame ids, names); invalid bytes written as U+FFFD\n",
                   file.c_str(), count);
    }
  }
  for (const auto& created : folders) created->Keep();
  long frames = 0;
  for (const Sequence& s : sequences) frames += static_cast<long>(s.frames.size());
  long frames_with_detections = 0;  // at least one person in some view (frames listed empty do not count)
  for (const FrameDetections& frame : detections.frames) {
    frames_with_detections +=
        std::any_of(frame.views.begin(), frame.views.end(), [](const Poses2D& view) { return view.num_persons() > 0; });
  }
  if (sequences.empty()) {  // --detections alone: no labels, the detection frames are the input
    std::printf("converted %zu detection frames (%ld with detections; no labels)\n", detections.frames.size(),
                frames_with_detections);
  } else {
    std::printf("converted %zu sequence(s), %ld frames, %ld frames with detections\n", sequences.size(), frames,
                frames_with_detections);
  }
}

}  // namespace

void RegisterConvertCommand(CLI::App& app) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* command = app.add_subcommand("convert", "Write an input's labels and detections to an HDF5 cache or JSON");
  AddInputOptions(command, &args->input);
  command->add_option("--out", args->out, "HDF5 cache with cameras, ground truth and detections");
  command->add_option("--labels-out", args->labels_out, "generic labels JSON (skelda schema)");
  command->add_option("--detections-out", args->detections_out, "generic detections JSON");
  command->add_flag("--float64", args->float64, "store coordinates as float64 (default float32)");
  command->callback([args] { RunConvert(*args); });
}

}  // namespace rpt::cli
