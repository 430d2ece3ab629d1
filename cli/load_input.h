// SPDX-License-Identifier: MIT
// The input options shared by eval, inspect and convert: which dataset (or generic labels), where
// its 2D detections come from, and loading all of it into validated Sequences.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

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
};

void AddInputOptions(CLI::App* command, InputArgs* args);

// Reads the sequences and attaches detections. With `require_detections`, a sequence without
// any detection is an InputError explaining the options. Throws InputError / ConfigError.
std::vector<Sequence> LoadInput(const InputArgs& args, bool require_detections);

}  // namespace rpt::cli
