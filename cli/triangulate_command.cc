// SPDX-License-Identifier: MIT
// `rpt triangulate`: cameras and 2D detections in, 3D persons per frame with track ids out; no
// ground truth needed (docs/own_data.md). The input is a calibration plus a detections file
// (--cameras, --detections), a dataset read without its GT files (--dataset, --root) or labels
// used for their cameras and times only (--labels). It runs the same engine loop as `rpt eval`
// (engine::Run) without metrics, so its predictions equal eval's on the same input, and writes
// the chosen exports, steps.csv, summary.json, config.json and run.json into the output folder
// (one atomic swap, like eval's). Prints the input warnings, progress on long runs, the counts
// and the time per step.
#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/export_args.h"
#include "cli/input_options.h"
#include "cli/progress.h"
#include "cli/threads_option.h"
#include "datasets/io/json_output.h"
#include "engine/input.h"
#include "engine/input_digests.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/run_info.h"
#include "engine/outputs/step_tables.h"
#include "engine/run.h"

namespace rpt::cli {
namespace {

struct TriangulateArgs {
  engine::InputSpec input;
  ConfigArgs config;
  ExportArgs exports;
  std::string out;
  int threads = 0;
  bool json = false;
  bool quiet = false;
};

std::string DefaultOutDir(const engine::InputSpec& input, const engine::Input& opened) {
  if (!input.dataset.empty()) return "out/triangulate-" + input.dataset;
  return "out/triangulate-" + (opened.size() == 1 ? opened.header(0).name : std::string("labels"));
}

void RunTriangulate(const TriangulateArgs& args) {
  const engine::Config config = ResolveConfig(args.config);
  const engine::ExportOptions exports = ExportOptionsOf(args.exports);
  engine::Input input = engine::OpenInput(args.input);
  const InputWarnings opened = input.Warnings();
  PrintInputWarnings(opened);
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval.reset();  // no ground truth: no metrics
  options.threads = args.threads;
  std::unique_ptr<Progress> progress = ProgressOf(input, !args.quiet);
  options.progress = ReportTo(progress.get());
  engine::RunInfo info = engine::CollectRunInfo(0);
  info.input_digests = engine::InputDigests(args.input);  // compared by `rpt report` and `rpt render --run`
  const std::string out_dir = !args.out.empty() ? args.out : DefaultOutDir(args.input, input);
  engine::RunFolder folder(out_dir, info.run_id, input.size(), exports);
  const engine::RunResult run = engine::Run(input, options, folder.sink());
  progress.reset();
  PrintInputWarnings(run.warnings.Except(opened));
  info.threads = run.threads;
  info.input_warnings = engine::InputWarningLines(run.warnings);
  folder.Finish(run, config, info);
  if (args.json) {
    std::cout << io::DumpJson(engine::TriangulationSummaryJson(run), 2) << "\n";
    std::cout.flush();
  } else {
    std::printf("%zu sequence(s), %ld frames, %d cameras, %ld persons triangulated (%.2f per frame)\n",
                run.sequences.size(), run.frames, run.sequences.empty() ? 0 : run.sequences.front().cameras,
                run.output_persons, run.frames > 0 ? static_cast<double>(run.output_persons) / run.frames : 0.0);
    std::printf("triangulated %ld frames in %.2f s (%.0f frames/s, %d thread(s) over %zu sequence(s))\n", run.frames,
                run.wall_seconds, run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0, run.threads,
                run.sequences.size());
    if (!args.quiet) engine::PrintStepTimes(std::cout, run.timing, &run.counts);
    std::printf("results in %s\n", out_dir.c_str());
    std::fflush(stdout);
  }
  if (run.frames > 0 && run.output_persons == 0) {
    std::fprintf(stderr,
                 "warning: no person was triangulated in any of the %ld frames: check that the cameras and the "
                 "detections belong together (camera names, pixel units, image sizes; `rpt inspect`)\n",
                 run.frames);
  }
}

}  // namespace

void RegisterTriangulateCommand(CLI::App& app) {
  auto args = std::make_shared<TriangulateArgs>();
  CLI::App* command = app.add_subcommand(
      "triangulate", "Triangulate 2D detections into 3D persons with track ids (your own cameras; no ground truth)");
  AddDetectionInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  AddExportOptions(command, &args->exports);
  command->add_option("--out", args->out, "output folder (default out/triangulate-<dataset or detections>)");
  AddThreadsOption(command, &args->threads, "sequences triangulated");
  command->add_flag("--json", args->json, "print the summary as one JSON object");
  command->add_flag("--quiet", args->quiet, "no progress, no step table");
  command->callback([args] { RunTriangulate(*args); });
}

}  // namespace rpt::cli
