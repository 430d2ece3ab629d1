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

// Only the dataset reader: --dataset, --root, --param (rpt bench on a dataset's frames).
void AddDatasetOptions(CLI::App* command, engine::InputSpec* spec);

// --cameras (a calibration file instead of a dataset), how it is read (--cameras-format,
// --cameras-units, --cameras-image-width, --cameras-image-height) and --fps; part of
// AddDetectionInputOptions, and of the commands that show what the input holds (rpt inspect).
void AddCamerasOptions(CLI::App* command, engine::InputSpec* spec);

// Prints every entry as "warning: <line>" on stderr.
void PrintInputWarnings(const InputWarnings& warnings);

// engine::OpenInput, timed: a detections or labels file read whole before the first frame (a
// long recording's JSON takes seconds to minutes) is announced on a terminal ("reading FILE
// (N MB) ...") when it is large; *seconds is the time the opening took.
engine::Input OpenInputTimed(const engine::InputSpec& spec, double* seconds);

// After a run's "... frames in S s (R frames/s ...)" line: when opening the input took a second or
// more, says so (the run's rate leaves it out).
void PrintInputReadTime(double seconds);

}  // namespace rpt::cli
