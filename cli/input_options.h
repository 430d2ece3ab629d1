// SPDX-License-Identifier: MIT
// The input options shared by the commands that read a dataset (--dataset, --root, --param,
// --labels, --cameras, --detections, --simulate, ...; engine/input.h opens what they name) and how
// the input's warnings are printed.
#pragma once

#include <CLI/CLI.hpp>

#include "datasets/input_warnings.h"
#include "engine/input.h"

namespace rpt::cli {

void AddInputOptions(CLI::App* command, engine::InputSpec* spec);

// The input options of the commands that need no ground truth (rpt triangulate): --dataset, --root,
// --param, --labels, --cameras, --fps, --detections, --strict; sets spec->ground_truth = false.
void AddDetectionInputOptions(CLI::App* command, engine::InputSpec* spec);

// --cameras (a calibration file instead of a dataset), how it is read (--cameras-format,
// --cameras-units, --cameras-image-width, --cameras-image-height) and --fps; part of
// AddDetectionInputOptions, and of the commands that show what the input holds (rpt inspect).
void AddCamerasOptions(CLI::App* command, engine::InputSpec* spec);

// Prints every entry as "warning: <line>" on stderr.
void PrintInputWarnings(const InputWarnings& warnings);

}  // namespace rpt::cli
