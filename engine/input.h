// SPDX-License-Identifier: MIT
// Opening an input: the one place where what the user named (a dataset, a labels file, a
// detections file, simulated detections) becomes frame sources (datasets/frame_source.h), each
// wrapped once: detections attached (engine/attached_detections.h) or simulated, then every
// frame validated (engine/checked_source.h). Every command and entry point opens its input here.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "datasets/calibration/calibration.h"
#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/input_warnings.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/simulate_detections.h"
#include "engine/detection_mapping.h"

namespace rpt::engine {

class AttachedDetections;

// What to read (the input options of every command that reads a dataset).
struct InputSpec {
  std::string dataset;              // dataset reader (engine/dataset_registry.h)
  std::string root;                 // its folder (or file)
  std::vector<std::string> params;  // key=value parameters of the reader (with `labels`: of the labels reader)
  std::string labels;               // generic labels file (JSON or HDF5 cache) instead of a dataset
  // A calibration file (any format datasets/calibration reads) instead of a dataset or labels: the
  // frames are those of the detections file (datasets/readers/detection_frames.h).
  std::string cameras;
  CalibrationReadOptions camera_read;  // how `cameras` is read (format, units, image size)
  double fps = 0;                   // with `cameras`: frame rate of the detection frames; 0 = times unknown
  std::string detections;           // detections file or folder (ReadDetectionsFile)
  DetectionMapping mapping;         // how its entries become frame ids, cameras and joints (--map-*, --coco-*, ...)
  bool simulate = false;            // simulated detections from the ground truth
  bool simulate_perfect = false;    // deprecated alias of detector = "perfect"
  std::string detector;             // simulated detector profile; empty = realistic
  uint64_t seed = 1;                // of the simulated detector
  // --seed (a thresholds file's "seed") was given: without --simulate it seeds nothing, an error
  // (detector-stats --compare, which simulates itself, clears it).
  bool seed_given = false;
  bool strict = false;              // unused input is an error (CheckStrict)
  // false: only the detections are wanted (rpt triangulate): readers go without their GT files
  // (DatasetRequest::ground_truth) and frames carry no persons.
  bool ground_truth = true;
};

// What a command needs of its input.
struct InputNeeds {
  bool detections = true;  // a sequence without any 2D detection is an InputError explaining the options
  // Messages name the Python module's arguments (detections_file=, simulate=True, detections=)
  // instead of the command line's flags.
  bool python_names = false;
};

// An opened input: one source per sequence. The run loop (engine/run.h) pulls them and calls
// Finished(i) when source i is exhausted; Warnings() is complete once every source is.
class Input {
 public:
  // `attached`: a detections file shared by the sequences; `per_sequence_files`: one per sequence
  // (VoxelPose caches). Both are kept for their unused-input counts.
  Input(std::vector<std::unique_ptr<FrameSource>> sources, InputWarnings opened, bool strict,
        std::shared_ptr<AttachedDetections> attached = nullptr,
        std::vector<std::shared_ptr<AttachedDetections>> per_sequence_files = {});
  ~Input();
  Input(Input&&) noexcept;
  Input& operator=(Input&&) noexcept;

  int size() const { return static_cast<int>(sources_.size()); }
  FrameSource& source(int i) { return *sources_[i]; }
  const SequenceHeader& header(int i) const { return headers_[i]; }
  // Source i is exhausted: its warnings are kept and the reader's memory freed.
  void Finished(int i);
  // The corrections and unused input reported so far: the files read up front, the finished
  // sources and, once every source has finished, the detection frames no sequence used.
  InputWarnings Warnings() const;
  // With --strict: throws InputError listing every unused-input warning reported so far.
  void CheckStrict() const;
  // The detections file or folder the frames' 2D poses come from (InputSpec::detections; empty for
  // a dataset's own, simulated or live detections): errors about a frame's detections name it.
  const std::string& detections_file() const { return detections_file_; }
  void set_detections_file(std::string path) { detections_file_ = std::move(path); }
  // Where the sequences' cameras come from (the --cameras file, the labels file or the dataset's
  // folder; empty for a generated scene or a live input): errors about the cameras name it.
  const std::string& cameras_origin() const { return cameras_origin_; }
  void set_cameras_origin(std::string path) { cameras_origin_ = std::move(path); }
  // Where the frames come from: the detections file with --cameras, else cameras_origin().
  const std::string& frames_origin() const { return frames_origin_.empty() ? cameras_origin_ : frames_origin_; }
  void set_frames_origin(std::string path) { frames_origin_ = std::move(path); }
  // Every sequence in memory (for the commands that need whole sequences: inspect, render,
  // report, detector-stats, convert); each frame validated once, like a run's.
  // With max_frames >= 0, an input of more frames (all sequences together) is refused before they
  // are read (InputError).
  std::vector<Sequence> Materialize(long max_frames = -1);

 private:
  std::vector<std::unique_ptr<FrameSource>> sources_;
  std::vector<SequenceHeader> headers_;
  std::vector<InputWarnings> finished_;
  std::vector<bool> done_;
  InputWarnings opened_;
  bool strict_ = false;
  std::shared_ptr<AttachedDetections> attached_;
  std::vector<std::shared_ptr<AttachedDetections>> per_sequence_files_;
  std::string detections_file_;
  std::string cameras_origin_;
  std::string frames_origin_;
};

// Opens the input `spec` names. Throws ConfigError for contradicting options and InputError for
// what cannot be read (naming the file and the place); with spec.strict, unused input found while
// opening throws too.
Input OpenInput(const InputSpec& spec, const InputNeeds& needs = {});

// Throws ConfigError on input options that contradict each other or name nothing known (what
// OpenInput checks before reading anything): a thresholds file checks its evaluations with it.
void CheckInputSpec(const InputSpec& spec);
// Of those checks, the dataset's: an unknown name, a --root the synthetic dataset does not read.
void CheckDatasetAndRoot(const InputSpec& spec);

// Opens and materialises (Input::Materialize, up to max_frames when >= 0), with --strict applied to the
// whole input. Running out of memory is an InputError naming the input.
std::vector<Sequence> LoadInput(const InputSpec& spec, const InputNeeds& needs, InputWarnings* warnings,
                                long max_frames = -1);

// The simulated detector of the input options: --detector PROFILE (--simulate-perfect: "perfect";
// neither: "realistic") with --seed (also what detector-stats --compare simulates with).
SimulationOptions SimulationOf(const InputSpec& spec);

// With `strict`, throws InputError listing every entry of `warnings` that reports unused input
// (InputWarningKind::kUnused), one "warning: <line>" per line; corrections within the tolerances
// are accepted.
void CheckStrict(bool strict, const InputWarnings& warnings);

// What the input options resolve to, for run.json (a default that changes later must not change
// what an old run folder says it ran on): the reader ("reader"), each of its parameters as given or
// by default ("param.<name>"), and with --simulate the detector profile and seed ("detector",
// "seed"); for --cameras FILE only the simulation, if any. Call after OpenInput checked the spec.
std::vector<std::pair<std::string, std::string>> ResolvedInputSettings(const InputSpec& spec);

// What is wrong with a calibration of fewer than 2 cameras, naming them, for an error that starts
// with the file or sequence: "1 camera (cam0): rpt triangulates ...".
std::string TooFewCamerasMessage(const std::vector<Camera>& cameras);

// The lines of `warnings` (InputWarning::Line()), e.g. for run.json.
std::vector<std::string> InputWarningLines(const InputWarnings& warnings);

}  // namespace rpt::engine
