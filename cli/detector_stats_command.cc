// SPDX-License-Identifier: MIT
// `rpt detector-stats`: how the 2D detections of an input err against its projected ground
// truth (datasets/detector_stats/statistics.h), as markdown tables or JSON. Works on real
// detections and on simulated ones (--simulate --detector PROFILE). --compare PROFILE,... puts
// the input's detections and simulated profiles on the same ground truth and cameras side by
// side in one table, which is how the simulated detector is fitted to real ones
// (docs/detector_model.md). The tables and the JSON live in cli/detector_stats_{markdown,comparison,json}.cc.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "datasets/io/json_output.h"
#include "engine/detector_stats_comparison.h"
#include "engine/outputs/detector_stats_json.h"
#include "engine/outputs/detector_stats_markdown.h"
#include "cli/input_options.h"
#include "engine/input.h"
#include "core/errors.h"
#include "core/text.h"
#include "datasets/detections.h"
#include "datasets/detector_stats/statistics.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/simulate_detections.h"
#include "core/printable_text.h"

namespace rpt::cli {
namespace {

using OrderedJson = nlohmann::ordered_json;
using detector_stats::DetectorStats;

struct DetectorStatsArgs {
  engine::InputSpec input;
  std::string joints;  // comma-separated
  double gate = 0.5;
  int min_joints_in_image = 2;
  bool json = false;
  std::vector<std::string> compare;  // simulated profiles to put next to the input's detections
};

std::string Describe(const engine::InputSpec& input) {
  std::string text = !input.dataset.empty() ? "dataset " + input.dataset : "labels " + input.labels;
  for (const std::string& param : input.params) text += " " + param;
  if (input.simulate) {
    const std::string profile = input.simulate_perfect ? "perfect" : input.detector.empty() ? "realistic" : input.detector;
    text += ", simulated detector " + QuoteName(profile) + ", seed " + std::to_string(input.seed);
  } else if (!input.detections.empty()) {
    text += ", detections " + input.detections;
  } else {
    text += ", the dataset's detections";
  }
  return text;
}

DetectorStats ComputeStats(const std::vector<Sequence>& sequences, const DetectorStatsArgs& args) {
  detector_stats::StatsOptions options;
  std::stringstream list(args.joints);
  for (std::string item; std::getline(list, item, ',');) {
    if (!item.empty()) options.joints.push_back(item);
  }
  options.association.gate_relative = args.gate;
  options.min_joints_in_image = args.min_joints_in_image;
  detector_stats::StatsAccumulator accumulator(options);
  for (const Sequence& sequence : sequences) accumulator.Add(sequence);
  return accumulator.Finalize();
}

// The input's own name for the column header: the dataset, else the labels file.
std::string InputColumnName(const engine::InputSpec& input) {
  if (!input.dataset.empty()) return "input: " + input.dataset;
  return "input: " + std::filesystem::path(input.labels).filename().string();
}

void RunComparison(const DetectorStatsArgs& args) {
  if (args.input.simulate || args.input.simulate_perfect) {
    throw ConfigError(
        "--compare excludes --simulate: it measures the input's own detections and simulates each listed "
        "profile itself on the same ground truth (seed: --seed)");
  }
  for (size_t i = 0; i < args.compare.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (args.compare[i] == args.compare[k]) throw ConfigError("--compare lists " + QuoteName(args.compare[i]) + " twice");
    }
  }
  engine::InputSpec input = args.input;
  input.seed_given = false;  // --seed seeds the profiles simulated here, not the input
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(input, {}, &input_warnings);
  PrintInputWarnings(input_warnings);
  std::vector<engine::DetectorStatsColumn> columns;
  std::vector<engine::InputSpec> inputs;
  columns.push_back({InputColumnName(input), ComputeStats(sequences, args)});
  inputs.push_back(input);
  for (const std::string& profile : args.compare) {
    // The input as `--simulate --detector PROFILE` would give it (--simulate-perfect is refused
    // above): simulated and described from the same options.
    engine::InputSpec described = input;
    described.simulate = true;
    described.detector = profile;
    described.detections.clear();
    std::vector<Sequence> simulated = sequences;  // same GT and cameras
    for (Sequence& s : simulated) SimulateDetections(engine::SimulationOf(described), &s);
    columns.push_back({profile, ComputeStats(simulated, args)});
    inputs.push_back(described);
  }
  if (args.json) {
    OrderedJson j = OrderedJson::object();
    for (size_t c = 0; c < columns.size(); ++c) {
      OrderedJson entry;
      entry["input"] = Describe(inputs[c]);
      entry.update(engine::DetectorStatsJson(columns[c].stats));
      j[c == 0 ? std::string("input") : args.compare[c - 1]] = std::move(entry);
    }
    std::cout << io::DumpJson(j, 2) << "\n";
    return;
  }
  engine::PrintDetectorStatsComparison(columns, Describe(args.input), args.input.seed);
}

void RunDetectorStats(const DetectorStatsArgs& args) {
  if (!args.compare.empty()) {
    RunComparison(args);
    return;
  }
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(args.input, {}, &input_warnings);
  PrintInputWarnings(input_warnings);
  const DetectorStats stats = ComputeStats(sequences, args);
  if (args.json) {
    OrderedJson j;
    j["input"] = Describe(args.input);
    j.update(engine::DetectorStatsJson(stats));
    std::cout << io::DumpJson(j, 2) << "\n";
    return;
  }
  engine::PrintDetectorStatsMarkdown(stats, Describe(args.input));
}

}  // namespace

void RegisterDetectorStatsCommand(CLI::App& app) {
  auto args = std::make_shared<DetectorStatsArgs>();
  CLI::App* command = app.add_subcommand(
      "detector-stats", "Measure how the 2D detections of an input err against its projected ground truth");
  AddInputOptions(command, &args->input);
  command->add_option("--joints", args->joints,
                      "statistic joints, comma-separated (default: the dataset's evaluated joints)");
  command->add_option("--gate", args->gate, "association gate: mean joint distance / GT box diagonal")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--min-joints-in-image", args->min_joints_in_image,
                      "a GT person counts as in view with this many statistic joints in the image")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--compare", args->compare,
                      "PROFILE[,PROFILE...]: one table of the input's detections next to these simulated detector "
                      "profiles (" + Join(synthetic::DetectorProfileNames(), "|") +
                          ") on the same ground truth and cameras (seed: --seed; not with --simulate)")
      ->delimiter(',')
      ->check(CLI::IsMember(synthetic::DetectorProfileNames()));
  command->add_flag("--json", args->json,
                    "print the statistics as JSON (with --compare: an object keyed \"input\" and by profile)");
  command->callback([args] { RunDetectorStats(*args); });
}

}  // namespace rpt::cli
