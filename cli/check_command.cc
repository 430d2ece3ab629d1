// SPDX-License-Identifier: MIT
// `rpt check --thresholds FILE`: re-runs every evaluation listed in the file and exits 1 when a
// metric falls below its floor ("min") or rises above its ceiling ("max"), printing expected vs
// achieved. Entries whose data is missing (e.g. ../shared/data on a machine without it) are
// reported as skipped.
//
// File format:
//   {"evaluations": [{"name": "...", "dataset": "synthetic", "root": "relative/to/this/file",
//                     "params": {"cameras": "5"}, "set": {"merge.top_k": "0"},
//                     "simulate": false, "detector": "realistic", "seed": 1,
//                     "labels": "...", "detections": "...",
//                     "min": {"recall500": 99.0}, "max": {"mpjpe_mm": 30.0, "frame_time_us_median": 2000}}]}
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/json_text.h"
#include "cli/load_input.h"
#include "cli/results_writer.h"
#include "cli/run_sequence.h"
#include "core/errors.h"
#include "datasets/io/json_file.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct CheckArgs {
  std::string thresholds;
  std::string only;
  bool json = false;
};


// Exit status of the check (0 all pass, 1 a threshold failed).
int RunCheck(const CheckArgs& args) {
  const Json root = io::LoadJsonFile(args.thresholds);
  const fs::path base = fs::path(args.thresholds).parent_path();
  if (!root.contains("evaluations") || !root["evaluations"].is_array()) {
    throw InputError(args.thresholds + ": expected {\"evaluations\": [...]}");
  }
  int failures = 0, checked = 0, skipped = 0;
  // Evaluations often read the same files: one line per file and kind for the whole check.
  InputWarnings warnings;
  Json report = Json::array();
  std::printf("%-40s %-22s %6s %10s %10s  %s\n", "evaluation", "metric", "bound", "expected", "achieved", "status");
  for (size_t i = 0; i < root["evaluations"].size(); ++i) {
    const Json& e = root["evaluations"][i];
    const std::string where = args.thresholds + ": /evaluations/" + std::to_string(i);
    if (!e.is_object() || !e.contains("name")) throw InputError(where + ": expected an object with a \"name\"");
    const std::string name = e["name"].get<std::string>();
    if (!args.only.empty() && name.find(args.only) == std::string::npos) continue;
    InputArgs input;
    input.dataset = e.value("dataset", "");
    input.labels = e.contains("labels") ? (base / e["labels"].get<std::string>()).string() : "";
    input.detections = e.contains("detections") ? (base / e["detections"].get<std::string>()).string() : "";
    input.simulate = e.value("simulate", false);
    input.simulate_perfect = e.value("simulate_perfect", false);  // deprecated: "detector": "perfect"
    input.detector = e.value("detector", "");
    input.seed = e.value("seed", 1);
    if (e.contains("root")) input.root = (base / e["root"].get<std::string>()).string();
    const Json params = e.value("params", Json::object());  // named: items() must not outlive it
    for (const auto& [key, value] : params.items()) input.params.push_back(key + "=" + JsonValueText(value));
    const bool needs_files = !input.root.empty() || !input.labels.empty() || !input.detections.empty();
    const std::string needed = !input.root.empty() ? input.root : !input.labels.empty() ? input.labels : input.detections;
    if (needs_files && !fs::exists(needed)) {
      std::printf("%-40s %-22s %6s %10s %10s  skipped (%s absent)\n", name.c_str(), "-", "-", "-", "-", needed.c_str());
      ++skipped;
      continue;
    }
    ConfigArgs config_args;
    const Json set = e.value("set", Json::object());
    for (const auto& [key, value] : set.items()) config_args.overrides.push_back(key + "=" + JsonValueText(value));
    const Config config = ResolveConfig(config_args);
    RunOptions options;
    options.triangulator = config.triangulator;
    options.eval = config.metrics;
    options.progress = false;
    options.threads = 1;  // timings comparable across machines with different core counts
    InputWarnings loaded;
    const RunResult run = RunSequences(LoadInput(input, true, &loaded), options);
    warnings.MergeRepeated(loaded);
    const nlohmann::ordered_json summary = SummaryJson(run);
    for (const char* bound : {"min", "max"}) {
      const Json limits = e.value(bound, Json::object());
      for (const auto& [metric, expected] : limits.items()) {
        if (!expected.is_number()) throw InputError(where + "/" + bound + "/" + metric + ": expected a number");
        if (!summary.contains(metric)) throw InputError(where + "/" + bound + ": unknown metric '" + metric + "'");
        const bool is_null = summary[metric].is_null();
        const double achieved = is_null ? std::nan("") : summary[metric].get<double>();
        const double limit = expected.get<double>();
        const bool pass = !is_null && (std::string(bound) == "min" ? achieved >= limit : achieved <= limit);
        ++checked;
        failures += pass ? 0 : 1;
        std::printf("%-40s %-22s %6s %10.2f %10.2f  %s\n", name.c_str(), metric.c_str(), bound, limit, achieved,
                    pass ? "ok" : "FAILED");
        report.push_back({{"evaluation", name}, {"metric", metric}, {"bound", bound}, {"expected", limit},
                          {"achieved", is_null ? Json(nullptr) : Json(achieved)}, {"pass", pass}});
      }
    }
  }
  std::fflush(stdout);  // the table first, then the readers' corrections (stderr)
  PrintInputWarnings(warnings);
  std::printf("%d checks, %d failed, %d evaluations skipped\n", checked, failures, skipped);
  if (args.json) std::cout << report.dump(2) << "\n";
  return failures > 0 ? 1 : 0;
}

}  // namespace

void RegisterCheckCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* command = app.add_subcommand("check", "Re-run the evaluations of a thresholds file; exit 1 on a regression");
  command->add_option("--thresholds", args->thresholds, "thresholds JSON (e.g. results/thresholds.json)")->required();
  command->add_option("--only", args->only, "only evaluations whose name contains this text");
  command->add_flag("--json", args->json, "also print the checks as JSON");
  command->callback([args, exit_code] { *exit_code = RunCheck(*args); });
}

}  // namespace rpt::cli
