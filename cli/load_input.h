// SPDX-License-Identifier: MIT
// The input options shared by eval, inspect and convert: which dataset (or generic labels), where
// its 2D detections come from, and loading all of it into validated Sequences.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt::cli {

struct InputArgs {
  std::string dataset;
  std::string root;
  std::vector<std::string> params;  // key=value
  std::string labels;               // generic labels file (instead of --dataset)
  std::string detections;           // detections file or folder
  bool simulate = false;            // simulated detections from the GT
  bool simulate_perfect = false;    // deprecated alias of detector = "perfect"
  std::string detector;             // simulated detector profile (synthetic::DetectorProfileNames()); empty = realistic
  uint64_t seed = 1;
  bool strict = false;  // --strict: unused input is an error (CheckStrict)
};

void AddInputOptions(CLI::App* command, InputArgs* args);

// Reads the sequences and attaches detections. With `require_detections`, a sequence without
// any detection is an InputError explaining the options. Throws InputError / ConfigError.
// The corrections the readers applied (rotations re-orthonormalised, scores clamped) and the
// input they could not use (skipped entries, unmatched frames, ...; one entry per file and kind)
// are added to `warnings`: the sequences' own and the detection file's. With args.strict, unused
// input throws (CheckStrict).
std::vector<Sequence> LoadInput(const InputArgs& args, bool require_detections, InputWarnings* warnings);

// The input as frame sources (datasets/frame_source.h), for consumers that stream (rpt eval):
// a dataset with its own or simulated detections is pulled frame by frame and never loaded
// whole; input with a detections file or a labels file is LoadInput's sequences behind
// SequenceSource. `warnings` gets what LoadInput gives; a streamed source's own corrections are
// complete once it is exhausted (FrameSource::warnings).
std::vector<std::unique_ptr<FrameSource>> OpenInput(const InputArgs& args, bool require_detections,
                                                    InputWarnings* warnings);

// The simulated detector of the input options: --detector PROFILE (--simulate-perfect: "perfect";
// neither: "realistic") with --seed. LoadInput and OpenInput simulate --simulate with it
// (SimulateDetections, SimulatedDetectionsSource); so does detector-stats --compare, per profile.
SimulationOptions SimulationOf(const InputArgs& args);

// With `strict` (--strict), throws InputError listing every entry of `warnings` that reports
// unused input (InputWarningKind::kUnused), one "warning: <line>" per line; corrections within
// the tolerances (rotations re-orthonormalised, scores clamped) are accepted.
void CheckStrict(bool strict, const InputWarnings& warnings);

// Prints every entry as "warning: <line>" on stderr.
void PrintInputWarnings(const InputWarnings& warnings);
// The lines of `warnings` (InputWarning::Line()), e.g. for run.json.
std::vector<std::string> InputWarningLines(const InputWarnings& warnings);

}  // namespace rpt::cli
