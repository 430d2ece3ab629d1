// SPDX-License-Identifier: MIT
// `rpt check --thresholds FILE`: validates the whole thresholds file (engine/thresholds_file.h; exit 2
// naming the file and JSON path when it is invalid), then re-runs every evaluation listed and exits 1
// when a metric falls below its floor ("min") or rises above its ceiling ("max"), printing expected
// vs achieved. An evaluation that fails to run is named in the table and the others still run (exit
// 1 at the end). Entries whose data is missing (e.g. ../shared/data on a machine without it) are
// reported as skipped, or as failures with --fail-on-skip. --junit FILE writes one JUnit testcase per
// check for CI systems.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/printable_text.h"
#include "datasets/io/json_output.h"
#include "datasets/io/staged_output.h"
#include "cli/commands.h"
#include "engine/outputs/junit_xml.h"
#include "cli/input_options.h"
#include "engine/input.h"
#include "engine/outputs/results_writer.h"
#include "engine/run.h"
#include "engine/thresholds_file.h"
#include "core/errors.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct CheckArgs {
  std::string thresholds;
  std::string only;
  bool json = false;
  bool fail_on_skip = false;
  bool strict = false;  // input not used fails the evaluation (engine::CheckStrict)
  std::string junit;
};

// A name from the thresholds file on one terminal line.
std::string Shown(const std::string& name) { return PrintableText(name, LineBreaks::kEscape); }

std::string CheckName(const engine::ThresholdCheck& check) {
  char limit[32];
  std::snprintf(limit, sizeof(limit), "%g", check.limit);
  return check.metric + " " + check.bound + " " + limit;
}

// Per evaluation outcome: every check passes, fails, errors or is skipped.
class CheckReport {
 public:
  // The table and totals go to `table` (stdout; stderr with --json, whose JSON is then stdout's only content).
  explicit CheckReport(std::FILE* table) : table_(table) {}

  void Checked(const engine::ThresholdEvaluation& e, const engine::ThresholdCheck& check, double achieved, bool pass) {
    ++checked_;
    failures_ += pass ? 0 : 1;
    std::fprintf(table_, "%-*s %-22s %6s %10.2f %10.2f  %s\n", name_width_, Shown(e.name).c_str(),
                 Shown(check.metric).c_str(), Shown(check.bound).c_str(), check.limit, achieved, pass ? "ok" : "FAILED");
    json_.push_back({{"evaluation", e.name}, {"metric", check.metric}, {"bound", check.bound},
                     {"expected", check.limit}, {"achieved", std::isnan(achieved) ? Json(nullptr) : Json(achieved)},
                     {"status", pass ? "pass" : "fail"}, {"pass", pass}});
    char message[128];
    std::snprintf(message, sizeof(message), "expected %s %g, achieved %.4g", check.bound == "min" ? ">=" : "<=",
                  check.limit, achieved);
    cases_.push_back({e.name, CheckName(check), pass ? engine::JunitCase::Outcome::kPass : engine::JunitCase::Outcome::kFailure,
                      pass ? "" : message});
  }

  void Skipped(const engine::ThresholdEvaluation& e, bool as_failure) {
    ++skipped_;
    const std::string why = e.required_path + " absent";
    std::fprintf(table_, "%-*s %-22s %6s %10s %10s  %s (%s)\n", name_width_, Shown(e.name).c_str(), "-", "-", "-", "-",
                 as_failure ? "SKIPPED, failing" : "skipped", Shown(why).c_str());
    AddJson(e, "skip", why, !as_failure);
    AddCases(e, as_failure ? engine::JunitCase::Outcome::kFailure : engine::JunitCase::Outcome::kSkipped,
             as_failure ? "skipped (" + why + "), --fail-on-skip" : "skipped (" + why + ")");
  }

  void Errored(const engine::ThresholdEvaluation& e, const std::string& what) {
    ++errored_;
    // One table line, whatever the message (a --strict error lists its warnings on several lines).
    std::fprintf(table_, "%-*s %-22s %6s %10s %10s  ERROR: %s\n", name_width_, Shown(e.name).c_str(), "-", "-", "-", "-",
                 Shown(what).c_str());
    AddJson(e, "error", what, false);
    AddCases(e, engine::JunitCase::Outcome::kError, what);
  }

  // The name column fits the longest name (at least 40, at most 100 characters): longer names ran
  // into the metric column.
  void FitNames(const std::vector<engine::ThresholdEvaluation>& evaluations) {
    for (const engine::ThresholdEvaluation& e : evaluations)
      name_width_ = std::max(name_width_, std::min(100, static_cast<int>(Shown(e.name).size())));
  }
  void PrintHeader() const {
    std::fprintf(table_, "%-*s %-22s %6s %10s %10s  %s\n", name_width_, "evaluation", "metric", "bound", "expected",
                 "achieved", "status");
  }

  void PrintTotals(bool fail_on_skip) const {
    std::fprintf(table_, "%d checks, %d failed, %d evaluations skipped", checked_, failures_, skipped_);
    // A misspelt root is skipped like data that is absent on purpose: say how to make it count.
    if (skipped_ > 0 && !fail_on_skip) std::fprintf(table_, " (their data is absent; --fail-on-skip fails them)");
    if (errored_ > 0) std::fprintf(table_, ", %d evaluations failed to run", errored_);
    std::fprintf(table_, "\n");
  }

  int ExitCode(bool fail_on_skip) const {
    return failures_ > 0 || errored_ > 0 || (fail_on_skip && skipped_ > 0) ? 1 : 0;
  }
  // What --json prints: every check (status pass / fail), every evaluation skipped or failed to run
  // (status skip / error, with its checks), the totals and the exit code.
  Json json(bool fail_on_skip) const {
    return {{"checks", json_},
            {"totals", {{"checks", checked_}, {"failed", failures_}, {"skipped", skipped_}, {"errors", errored_}}},
            {"exit_code", ExitCode(fail_on_skip)}};
  }
  const std::vector<engine::JunitCase>& cases() const { return cases_; }

 private:
  // One case per check of an evaluation that did not produce numbers (one for the evaluation when it has none).
  void AddCases(const engine::ThresholdEvaluation& e, engine::JunitCase::Outcome outcome, const std::string& message) {
    if (e.checks.empty()) cases_.push_back({e.name, "evaluation", outcome, message});
    for (const engine::ThresholdCheck& check : e.checks) cases_.push_back({e.name, CheckName(check), outcome, message});
  }

  // One JSON entry per check of an evaluation that did not produce numbers (metric null when it has none).
  void AddJson(const engine::ThresholdEvaluation& e, const char* status, const std::string& message, bool pass) {
    const auto entry = [&](const engine::ThresholdCheck* check) {
      json_.push_back({{"evaluation", e.name},
                       {"metric", check ? Json(check->metric) : Json(nullptr)},
                       {"bound", check ? Json(check->bound) : Json(nullptr)},
                       {"expected", check ? Json(check->limit) : Json(nullptr)},
                       {"achieved", nullptr},
                       {"status", status},
                       {"pass", pass},
                       {"message", message}});
    };
    if (e.checks.empty()) entry(nullptr);
    for (const engine::ThresholdCheck& check : e.checks) entry(&check);
  }

  std::FILE* table_;
  int checked_ = 0, failures_ = 0, skipped_ = 0, errored_ = 0;
  int name_width_ = 40;
  Json json_ = Json::array();
  std::vector<engine::JunitCase> cases_;
};

// Runs one evaluation and checks its bounds; throws what the readers or the pipeline throw.
void RunEvaluation(const engine::ThresholdEvaluation& e, bool strict, InputWarnings* warnings, CheckReport* report) {
  engine::RunOptions options;
  options.triangulator = e.config.triangulator;
  options.eval = e.config.metrics;
  options.threads = 1;  // timings comparable across machines with different core counts
  options.require_frames = true;
  engine::InputSpec input = e.input;
  input.strict = strict;
  engine::Input opened = engine::OpenInput(input);
  const engine::RunResult run = engine::Run(opened, options);
  warnings->MergeRepeated(run.warnings);
  const nlohmann::ordered_json summary = engine::SummaryJson(run);
  for (const engine::ThresholdCheck& check : e.checks) {
    // A metric the run does not report (e.g. legacy_pcp without metrics.legacy_pcp) fails its check.
    const bool is_null = !summary.contains(check.metric) || summary[check.metric].is_null();
    const double achieved = is_null ? std::nan("") : summary[check.metric].get<double>();
    const bool pass = !is_null && (check.bound == "min" ? achieved >= check.limit : achieved <= check.limit);
    report->Checked(e, check, achieved, pass);
  }
}

// Exit status of the check (0 all pass, 1 a check failed, an evaluation failed or, with --fail-on-skip, was skipped).
int RunCheck(const CheckArgs& args) {
  const engine::ThresholdsFile file = engine::ReadThresholdsFile(args.thresholds);
  if (!args.only.empty() &&
      std::none_of(file.evaluations.begin(), file.evaluations.end(),
                   [&](const engine::ThresholdEvaluation& e) { return e.name.find(args.only) != std::string::npos; })) {
    // A typo would otherwise check nothing and pass.
    throw ConfigError("--only " + QuoteName(args.only) + ": no evaluation of " + args.thresholds +
                      " has it in its name");
  }
  // Parameter values (a frame range, a day) are checked by the readers as they open: every
  // evaluation whose data is here is opened once before any runs, so that such a mistake in the
  // file is exit 2 naming its place, not one failed evaluation among the others' results.
  for (const engine::ThresholdEvaluation& e : file.evaluations) {
    if (!args.only.empty() && e.name.find(args.only) == std::string::npos) continue;
    if (!e.required_path.empty() && !fs::exists(e.required_path)) continue;
    try {
      engine::OpenInput(e.input);
    } catch (const ConfigError& error) {
      throw ConfigError(args.thresholds + ": " + e.json_path + " (" + QuoteName(e.name) + "): " + error.what());
    } catch (const std::exception&) {
      // Bad data, not a bad file: reported in the table when the evaluation runs.
    }
  }
  // The JUnit file's folder is checked before anything runs: a typo there cost the whole run and
  // turned a regression (exit 1) into exit 2.
  if (!args.junit.empty()) io::StagedFile probe(args.junit, io::NamedBy::kUser);
  CheckReport report(args.json ? stderr : stdout);
  // Evaluations often read the same files: one line per file and kind for the whole check.
  InputWarnings warnings;
  report.FitNames(file.evaluations);
  report.PrintHeader();
  for (const engine::ThresholdEvaluation& e : file.evaluations) {
    if (!args.only.empty() && e.name.find(args.only) == std::string::npos) continue;
    if (!e.required_path.empty() && !fs::exists(e.required_path)) {
      report.Skipped(e, args.fail_on_skip);
      continue;
    }
    try {
      RunEvaluation(e, args.strict, &warnings, &report);
    } catch (const std::exception& error) {
      report.Errored(e, error.what());
    }
    std::fflush(stdout);
  }
  std::fflush(stdout);  // the table first, then the readers' corrections (stderr)
  PrintInputWarnings(warnings);
  report.PrintTotals(args.fail_on_skip);
  if (args.json) std::cout << io::DumpJson(report.json(args.fail_on_skip), 2) << "\n";
  if (!args.junit.empty()) engine::WriteJunitXml(args.junit, "rpt check " + args.thresholds, report.cases());
  return report.ExitCode(args.fail_on_skip);
}

}  // namespace

void RegisterCheckCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* command = app.add_subcommand("check", "Re-run the evaluations of a thresholds file; exit 1 on a regression");
  command->add_option("--thresholds", args->thresholds, "thresholds JSON (e.g. results/thresholds.json)")->required();
  command->add_option("--only", args->only, "only evaluations whose name contains this text");
  command->add_flag("--json", args->json,
                    "print the checks as JSON on stdout (every check, skip and error with its status, the totals, "
                    "the exit code); the table goes to stderr");
  command->add_flag("--fail-on-skip", args->fail_on_skip,
                    "evaluations skipped for missing data count as failures (exit 1)");
  command->add_flag("--strict", args->strict,
                    "an evaluation whose input is not all used (entries skipped, frames matching nothing) fails");
  command->add_option("--junit", args->junit, "also write the checks as JUnit XML to this file (one testcase per check)");
  command->footer(engine::ThresholdsSchemaText());
  command->callback([args, exit_code] { *exit_code = RunCheck(*args); });
}

}  // namespace rpt::cli
