// SPDX-License-Identifier: MIT
// What `rpt report` reads from an `rpt eval` or `rpt triangulate` output folder: the recorded files
// (summary.json, per_joint.csv (not for a run without GT), config.json, run.json, predictions.json), and the input of the run re-loaded from
// the command line that run.json records (GT, cameras, detections are not copied into the folder:
// the dataset stays their one source).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt::engine {

struct RecordedPredictions {
  std::string run_id;  // "" when the file has none
  JointNames joints;
  std::vector<std::string> frame_ids;  // every frame of every sequence, in run order
  std::vector<Poses3D> frames;         // same order
};

struct RecordedRun {
  std::filesystem::path dir;
  nlohmann::ordered_json summary;   // summary.json
  nlohmann::ordered_json config;    // config.json (the resolved configuration of the run)
  nlohmann::ordered_json run_info;  // run.json
  nlohmann::ordered_json per_joint; // per_joint.csv as [{"joint", "mean_error_mm", "pck100", "count"}]; [] without GT
  RecordedPredictions predictions;
};

// Reads the folder. Throws InputError naming the file (and the JSON path or CSV line) when a file
// is missing or malformed.
RecordedRun ReadRecordedRun(const std::filesystem::path& dir);

// The dataset name of the recorded command ("--dataset NAME"), "" when none (generic labels).
std::string RecordedDataset(const RecordedRun& run);

// The argument vector of the recorded command: run.json's "argv" (paths with spaces stay whole),
// or for older run.json files "command" split at spaces. Empty, with the reason in *problem, when
// "argv" is not a list of strings.
std::vector<std::string> RecordedWords(const RecordedRun& run, std::string* problem = nullptr);

// Splits the recorded predictions per sequence (frame counts of `sequences`, ids checked). Returns
// false and sets *why when they do not line up (the input changed since the run).
bool SplitPredictions(const RecordedPredictions& predictions, const std::vector<Sequence>& sequences,
                      std::vector<std::vector<Poses3D>>* per_sequence, std::string* why);

}  // namespace rpt::engine
