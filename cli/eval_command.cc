// SPDX-License-Identifier: MIT
// `rpt eval`: a dataset (or generic labels) through the triangulator and the metrics. Prints the
// paper-style row and writes summary.{md,csv,json}, per_joint.csv, steps.csv, config.json, run.json and
// the chosen exports (--export: predictions.json by default, predictions.csv, trc/), and with --loss-table losses.csv
// (engine/loss_table.h), into the output folder. Checks the input and the results and prints a
// "warning: ..." line on stderr for each problem found (engine/diagnostics.h).
#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "core/printable_text.h"
#include "cli/config_args.h"
#include "cli/export_args.h"
#include "engine/diagnostics.h"
#include "engine/input.h"
#include "engine/output_place.h"
#include "engine/joint_adapter.h"
#include "engine/outputs/loss_tables.h"
#include "engine/outputs/step_tables.h"
#include "engine/outputs/results_writer.h"
#include "engine/input_digests.h"
#include "engine/outputs/run_info.h"
#include "engine/run.h"
#include "datasets/io/json_output.h"
#include "cli/input_options.h"
#include "cli/progress.h"
#include "cli/threads_option.h"

namespace rpt::cli {
namespace {

struct EvalArgs {
  engine::InputSpec input;
  ConfigArgs config;
  ExportArgs exports;
  std::string out;
  int threads = 0;
  bool json = false;
  bool quiet = false;
  bool loss_table = false;
  std::string adapter;  // joint-definition adapter file (rpt fit-adapter)
};

void RunEval(const EvalArgs& args) {
  const engine::Config config = ResolveConfig(args.config);
  const engine::ExportOptions exports = ExportOptionsOf(args.exports);
  std::shared_ptr<const engine::JointAdapter> adapter;
  if (!args.adapter.empty()) {
    adapter = std::make_shared<const engine::JointAdapter>(engine::ReadJointAdapter(args.adapter));
    if (adapter->fit.dataset != args.input.dataset) {
      std::fprintf(stderr, "warning: %s: fitted on %s, applied to %s: its offsets describe that dataset's joint "
                   "definitions\n", PrintableText(adapter->path, LineBreaks::kEscape).c_str(),
                   adapter->fit.dataset.empty() ? "another input" : ("dataset " + adapter->fit.dataset).c_str(),
                   args.input.dataset.empty() ? "another input" : ("dataset " + args.input.dataset).c_str());
    }
  }
  const std::string out_dir =
      !args.out.empty() ? args.out : "out/eval-" + (args.input.dataset.empty() ? "labels" : args.input.dataset);
  engine::CheckOutputOutsideInput(out_dir, args.input);  // before anything is read
  double read_s = 0;
  engine::Input input = OpenInputTimed(args.input, &read_s);
  const InputWarnings opened = input.Warnings();  // what the files read up front corrected or left unused
  PrintInputWarnings(opened);
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval = config.metrics;
  options.checks = engine::DetectionCheckOptions{};
  options.camera_sync = true;
  options.loss_table = args.loss_table;
  options.adapter = adapter;
  options.threads = args.threads;
  std::unique_ptr<Progress> progress = ProgressOf(input, !args.quiet);
  options.progress = ReportTo(progress.get());
  engine::RunInfo info = engine::CollectRunInfo(0);
  info.input_digests = engine::InputDigests(args.input);
  info.input_settings = engine::ResolvedInputSettings(args.input);  // compared by `rpt report` before it re-loads the input
  engine::RunFolder folder(out_dir, info.run_id, input.size(), exports);
  // Streamed: each frame is checked and triangulated, written, then dropped.
  options.require_frames = true;
  const engine::RunResult run = engine::Run(input, options, folder.sink());
  progress.reset();
  PrintInputWarnings(run.warnings.Except(opened));  // what the sources corrected or left unused, known now
  info.threads = run.threads;
  info.input_warnings = engine::InputWarningLines(run.warnings);
  engine::EvalDiagnostics diagnostics = engine::Diagnose(run);
  if (std::string clipped = engine::SpeedClipWarning(run, config.triangulator.clip_speed); !clipped.empty()) {
    diagnostics.warnings.push_back({"speed_clipped", std::move(clipped)});
  }
  nlohmann::ordered_json diagnostics_json = engine::DiagnosticsJson(diagnostics);
  diagnostics_json.update(engine::RunLossTablesJson(run));
  if (adapter) {
    nlohmann::ordered_json adapter_json = engine::JointAdapterJson(*adapter, /*with_frame_ids=*/false);
    adapter_json["adapted_persons"] = run.adapted_persons;
    adapter_json["unadapted_persons"] = run.unadapted_persons;
    diagnostics_json["joint_adapter"] = adapter_json;
  }
  folder.Finish(run, config, info, diagnostics_json);
  if (args.json) {
    // As summary.json (run_id first) and triangulate --json: the run and the folder it is in.
    nlohmann::ordered_json summary = {{"run_id", info.run_id}};
    summary.update(engine::SummaryJson(run));
    summary.update(diagnostics_json);
    summary["output"] = out_dir;
    std::cout << io::DumpJson(summary, 2) << "\n";  // invalid UTF-8 (a frame id) as U+FFFD, not an error
    std::cout.flush();
    engine::PrintWarnings(std::cerr, diagnostics);
    return;
  }
  std::printf("%zu sequence(s), %ld frames, %d cameras, %ld GT persons, %ld predicted persons\n", run.sequences.size(),
              run.frames, run.sequences.empty() ? 0 : run.sequences.front().cameras, run.gt_persons,
              run.output_persons);
  std::printf("%s\n", engine::PaperRow(run).c_str());
  // Tracking against the GT's person ids: a GT person matched to another track id than before
  // (a track that broke and resumed under a new id, or two people swapped) is an identity switch.
  if (run.identity.gt_identities > 0 && run.identity.track_ids > 0) {
    std::printf("tracking: %ld track ids for %ld GT persons (%ld of them matched), %ld identity switches over %ld "
                "matches\n",
                run.identity.track_ids, run.identity.gt_identities, run.identity.matched_identities,
                run.identity.id_switches, run.identity.tracked_matches);
  }
  const std::string invalid_causes = engine::InvalidCausesLine(run.metrics, config.metrics.match_threshold_mm);
  if (!invalid_causes.empty()) std::printf("%s\n", invalid_causes.c_str());
  std::printf("evaluated %ld frames in %.2f s (%.0f frames/s, %d thread(s) over %zu sequence(s))\n", run.frames,
              run.wall_seconds, run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0, run.threads,
              run.sequences.size());
  PrintInputReadTime(read_s);
  bool whole_body = false;  // only worth printing when face or hand joints were evaluated
  for (const auto& g : run.metrics.wholebody) whole_body |= (g.name == "Face" || g.name == "Hands") && g.num_persons > 0;
  for (const auto& g : run.metrics.wholebody) {
    if (!whole_body) break;
    if (g.num_persons > 0) {
      std::printf("  whole-body MPJPE %-6s %.1f mm (%d joints, %d persons)\n", g.name.c_str(), g.mpjpe_mm, g.num_joints,
                  g.num_persons);
    } else {
      std::printf("  whole-body MPJPE %-6s - (no matched person with these joints)\n", g.name.c_str());
    }
  }
  if (adapter) {
    std::printf("joint adapter %s, fitted on %s: moved %ld persons, left %ld without a body frame as they were\n",
                PrintableText(adapter->path, LineBreaks::kEscape).c_str(),
                PrintableText(engine::FitDescription(adapter->fit), LineBreaks::kEscape).c_str(), run.adapted_persons,
                run.unadapted_persons);
  }
  if (run.metrics.legacy_pcp) {
    // The actors the average is over: those of 1..legacy_pcp_actors with GT here (papers' tables
    // average all three; a selection without one of them averages fewer, said).
    std::string averaged;
    int count = 0;
    for (const auto& actor : run.metrics.legacy_pcp->actors) {
      if (!actor.averaged) continue;
      averaged += (count++ == 0 ? "" : ", ") + std::to_string(actor.actor_id + 1);
    }
    const int expected = config.metrics.legacy_pcp_actors;
    std::printf("  legacy PCP (actor%s %s%s) %.1f %%\n", count == 1 ? "" : "s", averaged.empty() ? "none" : averaged.c_str(),
                count < expected ? (" of 1-" + std::to_string(expected) + ": the others have no GT here").c_str() : "",
                run.metrics.legacy_pcp->average_pcp);
  }
  if (!args.quiet) {
    engine::PrintCheckSummary(std::cout, diagnostics);
    engine::PrintStepTimes(std::cout, run.timing, &run.counts);
  }
  if (run.losses) engine::PrintLossTable(std::cout, *run.losses);
  std::printf("results in %s\n", PrintableText(out_dir, LineBreaks::kEscape).c_str());
  if (const std::string stale = engine::StaleReportWarning(out_dir); !stale.empty()) {
    std::fflush(stdout);
    std::fprintf(stderr, "warning: %s\n", stale.c_str());
  }
  // Last, so they are what the user sees.
  std::fflush(stdout);
  engine::PrintWarnings(std::cerr, diagnostics);
}

}  // namespace

void RegisterEvalCommand(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = app.add_subcommand("eval", "Evaluate the triangulator on a dataset or on generic labels");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  AddExportOptions(command, &args->exports);
  command->add_option("--out", args->out, "output folder (default out/eval-<dataset>)");
  AddThreadsOption(command, &args->threads, "sequences evaluated", /*one_sequence_stages=*/true);
  command->add_flag("--json", args->json, "print the summary as one JSON object");
  command->add_flag("--quiet", args->quiet, "no progress, no step table");
  command->add_flag("--loss-table", args->loss_table,
                    "follow every GT person through the association and count where it is lost (losses.csv, "
                    "summary.json \"loss_table\"; docs/diagnostics.md)");
  command->add_option("--adapter", args->adapter,
                      "joint-definition adapter (rpt fit-adapter) applied to the predictions before the metrics; "
                      "refused on the frames it was fitted on (docs/joint_adapter.md)");
  command->callback([args] { RunEval(*args); });
}

}  // namespace rpt::cli
