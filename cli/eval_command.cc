// SPDX-License-Identifier: MIT
// `rpt eval`: a dataset (or generic labels) through the triangulator and the metrics. Prints the
// paper-style row and writes summary.{md,csv,json}, per_joint.csv, steps.csv, config.json, run.json and
// predictions.json into the output folder. Checks the input and the results and prints a
// "warning: ..." line on stderr for each problem found (cli/diagnostics.h).
#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/diagnostics.h"
#include "cli/load_input.h"
#include "cli/report.h"
#include "cli/results_writer.h"
#include "cli/run_info.h"
#include "cli/run_sequence.h"
#include "datasets/io/json_output.h"
#include "cli/thread_count.h"

namespace rpt::cli {
namespace {

struct EvalArgs {
  InputArgs input;
  ConfigArgs config;
  std::string out;
  int threads = 0;
  bool json = false;
  bool quiet = false;
};

void RunEval(const EvalArgs& args) {
  const Config config = ResolveConfig(args.config);
  InputWarnings warnings;
  std::vector<std::unique_ptr<FrameSource>> sources = OpenInput(args.input, /*require_detections=*/true, &warnings);
  PrintInputWarnings(warnings);
  RunOptions options;
  options.triangulator = config.triangulator;
  options.eval = config.metrics;
  options.threads = args.threads;
  options.progress = !args.quiet;
  DetectionCheckOptions check_options;
  check_options.max_gap_s = config.triangulator.track.max_gap_s;  // one notion of continuity
  // Streamed: each frame is checked and triangulated, then dropped but for its id, time and GT.
  StreamedRun streamed = RunSources(std::move(sources), options, check_options);
  CheckStrict(args.input.strict, streamed.warnings);
  PrintInputWarnings(streamed.warnings);  // what streamed sources corrected or left unused, known now
  warnings.Merge(streamed.warnings);
  const RunResult& run = streamed.run;
  const std::vector<Sequence>& sequences = streamed.sequences;
  RunInfo info = CollectRunInfo(run.threads);
  info.input_warnings = InputWarningLines(warnings);
  const std::string out_dir =
      !args.out.empty() ? args.out : "out/eval-" + (args.input.dataset.empty() ? "labels" : args.input.dataset);
  const EvalDiagnostics diagnostics = Diagnose(std::move(streamed.checks), sequences, run);
  const nlohmann::ordered_json diagnostics_json = DiagnosticsJson(diagnostics);
  WriteEvalOutputs(out_dir, sequences, run, config, info, diagnostics_json);
  if (args.json) {
    nlohmann::ordered_json summary = SummaryJson(run);
    summary.update(diagnostics_json);
    std::cout << io::DumpJson(summary, 2) << "\n";  // invalid UTF-8 (a frame id) as U+FFFD, not an error
    std::cout.flush();
    PrintWarnings(std::cerr, diagnostics);
    return;
  }
  long frames = 0;
  for (const Sequence& s : sequences) frames += static_cast<long>(s.frames.size());
  std::printf("%zu sequence(s), %ld frames, %zu cameras, %ld GT persons, %ld predicted persons\n", sequences.size(),
              frames, sequences.front().cameras.size(), run.gt_persons, run.output_persons);
  std::printf("%s\n", PaperRow(run).c_str());
  std::printf("evaluated %ld frames in %.2f s (%.0f frames/s, %d thread(s) over %zu sequence(s))\n", run.frames,
              run.wall_seconds, run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0, run.threads, sequences.size());
  bool whole_body = false;  // only worth printing when face or hand joints were evaluated
  for (const auto& g : run.metrics.wholebody) whole_body |= (g.name == "Face" || g.name == "Hands") && g.num_persons > 0;
  for (const auto& g : run.metrics.wholebody) {
    if (whole_body) std::printf("  whole-body MPJPE %-6s %.1f mm\n", g.name.c_str(), g.mpjpe_mm);
  }
  if (run.metrics.legacy_pcp) std::printf("  legacy PCP (actors 1-3) %.1f %%\n", run.metrics.legacy_pcp->average_pcp);
  if (!args.quiet) {
    PrintCheckSummary(std::cout, diagnostics);
    PrintStepTimes(std::cout, run.timing, &run.counts);
  }
  std::printf("results in %s\n", out_dir.c_str());
  // Last, so they are what the user sees.
  std::fflush(stdout);
  PrintWarnings(std::cerr, diagnostics);
}

}  // namespace

void RegisterEvalCommand(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = app.add_subcommand("eval", "Evaluate the triangulator on a dataset or on generic labels");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  command->add_option("--out", args->out, "output folder (default out/eval-<dataset>)");
  AddThreadsOption(command, &args->threads, "sequences evaluated");
  command->add_flag("--json", args->json, "print the summary as one JSON object");
  command->add_flag("--quiet", args->quiet, "no progress, no step table");
  command->callback([args] { RunEval(*args); });
}

}  // namespace rpt::cli
