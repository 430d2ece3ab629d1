// SPDX-License-Identifier: MIT
// `rpt report RUN_DIR`: one self-contained report.html for an `rpt eval` or `rpt triangulate` output folder
// (docs/report.md).
// Reads the recorded files, re-loads the run's input from the command line in run.json (for GT,
// cameras and detections; without it the report keeps the recorded tables and says why), evaluates
// the recorded predictions frame by frame with the run's config.json, and writes the page.
#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "engine/config.h"
#include "engine/output_place.h"
#include "engine/report/report_data.h"
#include "engine/report/report_html.h"
#include "engine/report/report_run.h"
#include "cli/recorded_input.h"
#include "engine/run.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/text_file.h"

namespace rpt::cli {
namespace {

struct ReportArgs {
  std::string run_dir;
  std::string out;  // default RUN_DIR/report.html
  bool require_same_input = false;
  engine::ReportDataOptions data;
};

void RunReport(const ReportArgs& args) {
  const engine::RecordedRun run = engine::ReadRecordedRun(args.run_dir);
  if (!args.out.empty()) engine::CheckOutputOutsideRunFolder(args.out, run.dir);
  engine::Config config;
  engine::LoadConfigFile(run.dir / "config.json", &config);
  std::string why_no_input;
  std::vector<std::string> warnings;
  const std::optional<std::vector<Sequence>> sequences =
      ReloadRecordedInput(run, args.require_same_input, &why_no_input, &warnings);
  metrics::EvalOptions eval_options = config.metrics;
  if (sequences) {
    std::vector<const SequenceHeader*> headers;
    for (const Sequence& s : *sequences) headers.push_back(&s);
    eval_options = engine::EvalOptionsFor(config.metrics, headers);
  }
  const nlohmann::ordered_json data = engine::BuildReportData(run, sequences ? &*sequences : nullptr, why_no_input,
                                                      eval_options, args.data, &warnings);
  const std::filesystem::path out = args.out.empty() ? run.dir / "report.html" : std::filesystem::path(args.out);
  const std::string page = engine::ReportHtml(data);
  // RUN_DIR/report.html is rpt's name inside a run folder (a link there is replaced, a FIFO too);
  // --out FILE is the user's.
  io::WriteTextFile(out, args.out.empty() ? io::NamedBy::kRpt : io::NamedBy::kUser, page);
  int scenes = data.contains("scenes") ? static_cast<int>(data["scenes"].size()) : 0;
  std::printf("report in %s (%.1f MB, %d frame(s) with 3D scene and camera views)\n",
              PrintableText(out.string(), LineBreaks::kEscape).c_str(), page.size() / 1e6, scenes);
  std::fflush(stdout);
  for (const std::string& line : warnings) std::fprintf(stderr, "warning: %s\n", PrintableText(line).c_str());
}

}  // namespace

void RegisterReportCommand(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* command = app.add_subcommand(
      "report",
      "Write one self-contained report.html (plots, 3D viewer, camera overlays) for an `rpt eval` or `rpt triangulate` "
      "folder");
  command->add_option("RUN_DIR", args->run_dir, "output folder of `rpt eval` or `rpt triangulate`")->required();
  command->add_option("--out", args->out, "the page to write (default RUN_DIR/report.html)");
  command->add_flag("--require-same-input", args->require_same_input,
                    "refuse (exit 2) when the input on disk differs from the digests run.json records (default: warn)");
  command->add_option("--max-frames", args->data.max_scene_frames,
                      "frames that carry a 3D scene and camera views, evenly spaced over the run (bounds the size)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  command->add_option("--max-scene-mb", args->data.max_scene_mb,
                      "the 3D scenes' share of the page: fewer frames carry one when --max-frames of them take more")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 1000.0));
  command->callback([args] { RunReport(*args); });
}

}  // namespace rpt::cli
