// SPDX-License-Identifier: MIT
// `rpt triangulate`: cameras and 2D detections in, 3D persons per frame with track ids out; no
// ground truth needed (docs/own_data.md). The input is a calibration plus a detections file
// (--cameras, --detections), a dataset read without its GT files (--dataset, --root) or labels
// used for their cameras and times only (--labels). It runs the same engine loop as `rpt eval`
// (engine::Run) without metrics, so its predictions equal eval's on the same input, and writes
// the chosen exports, steps.csv, summary.json, config.json and run.json into the output folder
// (one atomic swap, like eval's). Prints the input warnings, progress on long runs, the counts
// and the time per step.
//
// With --follow the detections come as JSON lines from standard input or a named pipe, and each
// frame goes out as one JSON line on standard output as soon as it is triangulated (the same run
// loop on a live source, engine/live_input.h); the summary goes to stderr.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/export_args.h"
#include "cli/input_options.h"
#include "cli/interrupt.h"
#include "cli/progress.h"
#include "cli/threads_option.h"
#include "core/option_codec.h"
#include "core/pipeline/steps.h"
#include "core/printable_text.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "engine/diagnostics.h"
#include "engine/input.h"
#include "engine/output_place.h"
#include "engine/input_digests.h"
#include "engine/live_input.h"
#include "engine/live_latency.h"
#include "engine/outputs/frame_lines_writer.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/run_info.h"
#include "engine/outputs/step_tables.h"
#include "engine/run.h"
#include "metrics/step_counts.h"

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
  std::string follow;  // --follow PATH: live input ("-" = standard input)
  double wait_for_lines_s = 0;  // --wait-for-lines: at the end of a regular file, wait for more
  bool skip_bad_lines = false;
  int spin_us = engine::kDefaultSpinUs;
};

// The line format, for --help (docs/own_data.md, "Live input", has the details).
constexpr const char* kFollowHelp =
    "Live input (--follow PATH, - = standard input): line 1 names the joints, every other line is one frame:\n"
    "  {\"joints\": [\"nose\", \"eye_left\", ...]}\n"
    "  {\"id\": \"f1\", \"time\": 0.04, \"views\": [{\"camera\": \"cam0\", \"poses\": [[[u, v, score], ...], ...]}]}\n"
    "\"id\" (default: the line number) and \"time\" (seconds; default: frame index / --fps, else unknown) are\n"
    "optional; cameras are --cameras' names; pixels of the original image, a joint null or of score 0 is\n"
    "missing. Output on stdout, one line per frame as soon as it is done, after a first line with the\n"
    "joints and units: {\"id\", \"time\" (s), \"persons\": [[[x, y, z, score], ...]] (m, world frame),\n"
    "\"track_ids\", \"provenance\"}. Ends at the end of the input (exit 0; a file still being written:\n"
    "--wait-for-lines) or on Ctrl-C (exit 130), with a summary on stderr; a bad line is an error naming it\n"
    "(exit 2) unless --skip-bad-lines.";

std::string DefaultOutDir(const engine::InputSpec& input, const engine::Input& opened) {
  if (!input.dataset.empty()) return "out/triangulate-" + input.dataset;
  return "out/triangulate-" + (opened.size() == 1 ? opened.header(0).name : std::string("labels"));
}

// The default output folder is named after the detections ("openpose", "detections"), the same for
// every take of a lab's layout (takeA/openpose, takeB/openpose): a run there of other input paths is
// not replaced silently (a loop over takes kept only the last). An explicit --out replaces as
// documented.
void CheckDefaultOutputHoldsThisInput(const std::string& out_dir,
                                      const std::vector<std::pair<std::string, std::string>>& digests) {
  const std::filesystem::path run_json = std::filesystem::path(out_dir) / "run.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(run_json, ec)) return;
  nlohmann::json recorded;
  try {
    recorded = io::LoadJsonFile(run_json);
  } catch (const InputError&) {
    return;  // not a run.json of ours: replaced as any folder is
  }
  const auto paths = recorded.find("input_digests");
  if (paths == recorded.end() || !paths->is_object()) return;
  std::vector<std::string> before, now;
  for (auto it = paths->begin(); it != paths->end(); ++it) before.push_back(it.key());
  for (const auto& [path, digest] : digests) now.push_back(path);
  std::sort(before.begin(), before.end());
  std::sort(now.begin(), now.end());
  if (before == now) return;
  throw InputError(PrintableText(out_dir, LineBreaks::kEscape) + ": the default output folder holds the run of other input (" +
                   JoinNames(before) + "); it is named after the detections, the same for every take: give --out DIR "
                   "(one per take), or remove the folder");
}

void CheckFollowArgs(const TriangulateArgs& args) {
  if (args.json) throw ConfigError("--json: not with --follow (standard output holds the frame lines)");
  if (args.threads > 1) {
    throw ConfigError(
        "--threads: not with --follow (a live stream runs frame by frame on one thread, each frame out as soon as it "
        "is triangulated)");
  }
}

// A run of frames in which no person was triangulated: what to check; "" when some were.
std::string NobodyTriangulatedWarning(const engine::RunResult& run, const UndistortOptions& undistort) {
  if (run.frames == 0 || run.output_persons > 0) return "";
  return run.counts.count_per_frame[static_cast<size_t>(Step::kUndistort)] == 0
             // Nothing to triangulate: the cameras are not to blame (that warning sent users to the calibration).
             ? "no person was triangulated in any of the " + std::to_string(run.frames) +
                   " frames: the detections hold no usable 2D pose in any camera (every view empty, or no pose "
                   "with undistort.min_core_joints = " +
                   std::to_string(undistort.min_core_joints) +
                   " core joints scored at least undistort.min_joint_score = " +
                   FormatOption(undistort.min_joint_score) +
                   ": scores on another scale, such as heatmap values of 0-0.1, are all below it; "
                   "--set undistort.min_joint_score=... lowers it)"
             : "no person was triangulated in any of the " + std::to_string(run.frames) +
                   " frames: check that the cameras and the detections belong together (camera names, pixel "
                   "units, image sizes; `rpt inspect`), the unit of the calibration's translations "
                   "(--cameras-units: millimetres read as metres put the cameras 1000 times too far) and the "
                   "calibration's convention (R and t map world to "
                   "camera: x_cam = R X + t; in rpt's JSON, T is the camera's centre in the world; "
                   "docs/cameras.md)";
}

// The camera-agreement, upright, mirror-image and camera-sync warnings of every sequence
// (engine/camera_agreement.h, upright_check.h, camera_sync_check.h) and the run's speed-clipping
// warning (engine/diagnostics.h), printed on stderr; returned for run.json.
std::vector<std::string> PrintRunChecks(const engine::RunResult& run, const engine::Config& config) {
  std::vector<std::string> lines;
  for (const engine::SequenceResult& sequence : run.sequences) {
    std::vector<std::string> warnings = engine::CameraAgreementWarnings(sequence.name, sequence.camera_agreement);
    if (std::string upright = engine::UprightWarning(sequence.name, sequence.upright); !upright.empty()) {
      warnings.push_back(std::move(upright));
    }
    if (std::string mirrored = engine::MirroredWarning(sequence.name, sequence.upright); !mirrored.empty()) {
      warnings.push_back(std::move(mirrored));
    }
    if (std::string hands = engine::SwappedHandsWarning(sequence.name, sequence.upright); !hands.empty()) {
      warnings.push_back(std::move(hands));
    }
    warnings.insert(warnings.end(), sequence.camera_sync.begin(), sequence.camera_sync.end());
    for (std::string& line : warnings) {
      std::fprintf(stderr, "warning: %s\n", line.c_str());
      lines.push_back(std::move(line));
    }
  }
  if (std::string clipped = engine::SpeedClipWarning(run, config.triangulator.clip_speed); !clipped.empty()) {
    std::fprintf(stderr, "warning: %s\n", clipped.c_str());
    lines.push_back(std::move(clipped));
  }
  std::fflush(stderr);
  return lines;
}

// A live run's warning as it happens (its end, where the counts are printed, may be hours away).
void PrintAtOnce(const std::string& line) {
  std::fprintf(stderr, "warning: %s (said as it happens; counted at the end)\n", PrintableText(line).c_str());
  std::fflush(stderr);
}

// After Ctrl-C, how long the line in hand may wait for a reader that does not take the output.
constexpr double kStopGraceS = 2.0;

// --follow: the live input through the same run loop, the frame lines on stdout, the summary on
// stderr. Returns the exit code: 0 at the end of the input, 128 + the signal after Ctrl-C.
int RunFollow(const TriangulateArgs& args) {
  CheckFollowArgs(args);
  // A reader that closes standard output is a write error (exit 2, outputs cleaned up), as for every
  // command's printed results, not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  const engine::Config config = ResolveConfig(args.config);
  const engine::ExportOptions exports = ExportOptionsOf(args.exports);
  auto stop = std::make_shared<io::StopRequest>();
  const StopOnInterrupt on_interrupt([stop] { stop->Request(); });
  DetectionLinesCounts counts;
  std::optional<engine::Input> input;
  try {
    const TriangulateOptions& limits = config.triangulator.triangulate;
    input.emplace(engine::OpenLiveInput(args.input,
                                        {.path = args.follow,
                                         .skip_bad_lines = args.skip_bad_lines,
                                         .spin_us = args.spin_us,
                                         .wait_for_lines_s = args.wait_for_lines_s,
                                         .max_persons_per_view = limits.max_persons_per_view,
                                         .max_pairs_per_frame = limits.max_pairs_per_frame,
                                         .on_first_bad_line =
                                             [](const std::string& error) {
                                               PrintAtOnce("a bad line skipped (the first of --skip-bad-lines): " +
                                                           error);
                                             },
                                         .on_early_warning = PrintAtOnce},
                                        stop, &counts));
  } catch (const InputError&) {
    if (on_interrupt.signal_number() == 0) throw;
    std::fprintf(stderr, "interrupted (%s) before the joints line: nothing triangulated\n",
                 StopOnInterrupt::SignalName(on_interrupt.signal_number()));
    return 128 + on_interrupt.signal_number();
  }
  const InputWarnings opened = input->Warnings();
  PrintInputWarnings(opened);
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval.reset();  // no ground truth: no metrics
  options.camera_agreement = true;
  options.camera_sync = true;
  options.upright_check = true;
  options.threads = 1;
  options.early_warning = PrintAtOnce;  // times going back or in ms: said now, counted at the end
  // A reader that stops taking the output cannot hold a Ctrl-C: 2 s more for the line in hand.
  engine::FrameLinesWriter lines(STDOUT_FILENO, "stdout", exports, stop, kStopGraceS);
  engine::LiveLatency latency(&counts);
  engine::RunInfo info = engine::CollectRunInfo(1);
  std::optional<engine::RunFolder> folder;
  if (!args.out.empty()) {
    engine::CheckOutputOutsideInput(args.out, args.input);
    folder.emplace(args.out, info.run_id, input->size(), exports);
  }
  engine::SinkList sinks({&lines, &latency, folder ? folder->sink() : nullptr});
  const engine::RunResult run = [&] {
    try {
      return engine::Run(*input, options, &sinks);
    } catch (const InputError&) {  // a bad line, a reader that closed stdout: how far the stream got
      std::fprintf(stderr, "%s: %ld lines read, %ld frames written to stdout before the error\n",
                   PrintableText(input->header(0).name, LineBreaks::kEscape).c_str(), counts.lines,
                   std::max(0L, lines.lines() - 1));
      throw;
    }
  }();
  PrintInputWarnings(run.warnings.Except(opened));
  const std::vector<std::string> agreement = PrintRunChecks(run, config);
  if (folder) {
    info.threads = run.threads;
    info.input_warnings = engine::InputWarningLines(run.warnings);
    info.input_warnings.insert(info.input_warnings.end(), agreement.begin(), agreement.end());
    folder->Finish(run, config, info);
  }
  const int signal_number = on_interrupt.signal_number();
  std::fprintf(stderr, "%s: %ld lines, %ld frames, %ld persons triangulated (%.2f per frame)%s; %s\n",
               PrintableText(input->header(0).name, LineBreaks::kEscape).c_str(), counts.lines, run.frames,
               run.output_persons, run.frames > 0 ? static_cast<double>(run.output_persons) / run.frames : 0.0,
               counts.bad_lines > 0 ? (", " + std::to_string(counts.bad_lines) + " bad line(s) skipped").c_str() : "",
               signal_number != 0 ? (std::string("stopped by ") + StopOnInterrupt::SignalName(signal_number)).c_str()
                                  : "end of input");
  if (run.frames > 0) {
    std::fprintf(stderr,
                 "per frame (median): triangulation %.1f us, line in -> line out %.1f us (p90 %.1f us, max %.1f us)\n",
                 run.timing.frame_us_median, latency.median_us(), latency.p90_us(), latency.max_us());
  }
  if (lines.abandoned()) {
    std::fprintf(stderr,
                 "warning: stdout did not take the output for %.0f s after the stop: the last frame's line %s\n",
                 kStopGraceS,
                 lines.cut_bytes() > 0 ? ("is cut after " + std::to_string(lines.cut_bytes()) + " bytes").c_str()
                                       : "was not written");
  }
  if (const std::string nobody = NobodyTriangulatedWarning(run, config.triangulator.undistort); !nobody.empty()) {
    std::fprintf(stderr, "warning: %s\n", nobody.c_str());
  }
  if (folder) std::fprintf(stderr, "results in %s\n", PrintableText(args.out, LineBreaks::kEscape).c_str());
  return signal_number != 0 ? 128 + signal_number : 0;
}

void RunTriangulate(const TriangulateArgs& args) {
  const engine::Config config = ResolveConfig(args.config);
  const engine::ExportOptions exports = ExportOptionsOf(args.exports);
  double read_s = 0;
  engine::Input input = OpenInputTimed(args.input, &read_s);
  const InputWarnings opened = input.Warnings();
  PrintInputWarnings(opened);
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval.reset();  // no ground truth: no metrics
  options.camera_agreement = true;
  options.camera_sync = true;
  options.upright_check = true;
  options.threads = args.threads;
  std::unique_ptr<Progress> progress = ProgressOf(input, !args.quiet);
  options.progress = ReportTo(progress.get());
  engine::RunInfo info = engine::CollectRunInfo(0);
  info.input_digests = engine::InputDigests(args.input);  // compared by `rpt report` and `rpt render --run`
  info.input_settings = engine::ResolvedInputSettings(args.input);
  const std::string out_dir = !args.out.empty() ? args.out : DefaultOutDir(args.input, input);
  engine::CheckOutputOutsideInput(out_dir, args.input);
  if (args.out.empty()) CheckDefaultOutputHoldsThisInput(out_dir, info.input_digests);
  engine::RunFolder folder(out_dir, info.run_id, input.size(), exports);
  options.require_frames = true;
  const engine::RunResult run = engine::Run(input, options, folder.sink());
  progress.reset();
  PrintInputWarnings(run.warnings.Except(opened));
  const std::vector<std::string> agreement = PrintRunChecks(run, config);
  info.threads = run.threads;
  info.input_warnings = engine::InputWarningLines(run.warnings);
  info.input_warnings.insert(info.input_warnings.end(), agreement.begin(), agreement.end());
  // Nobody triangulated: said on stderr after the results, and in --json's warnings.
  const std::string nobody = NobodyTriangulatedWarning(run, config.triangulator.undistort);
  folder.Finish(run, config, info);
  // Tracks started over the run (a person lost longer than track.max_missing_frames comes back
  // under a new id: a count well above the people in the scene says ids break).
  const long tracks = metrics::CounterTotal(run.counts, "new_tracks");
  const int cameras = run.sequences.empty() ? 0 : run.sequences.front().cameras;
  if (args.json) {
    // The summary plus what a script aggregating many takes needs: the run, the folder, the counts
    // the text line gives, and every warning (the input's, the cameras', nobody triangulated).
    nlohmann::ordered_json summary = engine::TriangulationSummaryJson(run);
    summary["run_id"] = info.run_id;
    summary["output"] = out_dir;
    summary["cameras"] = cameras;
    summary["track_ids"] = tracks;
    nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
    for (const std::string& line : engine::InputWarningLines(run.warnings)) {
      warnings.push_back({{"code", "input"}, {"message", line}});
    }
    for (const std::string& line : agreement) warnings.push_back({{"code", "cameras"}, {"message", line}});
    if (!nobody.empty()) warnings.push_back({{"code", "no_predictions"}, {"message", nobody}});
    summary["warnings"] = warnings;
    std::cout << io::DumpJson(summary, 2) << "\n";
    std::cout.flush();
  } else {
    std::printf("%zu sequence(s), %ld frames, %d cameras, %ld persons triangulated (%.2f per frame), %ld track ids\n",
                run.sequences.size(), run.frames, cameras, run.output_persons,
                run.frames > 0 ? static_cast<double>(run.output_persons) / run.frames : 0.0, tracks);
    std::printf("triangulated %ld frames in %.2f s (%.0f frames/s, %d thread(s) over %zu sequence(s))\n", run.frames,
                run.wall_seconds, run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0, run.threads,
                run.sequences.size());
    PrintInputReadTime(read_s);
    if (!args.quiet) engine::PrintStepTimes(std::cout, run.timing, &run.counts);
    std::printf("results in %s\n", PrintableText(out_dir, LineBreaks::kEscape).c_str());
    std::fflush(stdout);
  }
  if (const std::string stale = engine::StaleReportWarning(out_dir); !stale.empty()) {
    std::fprintf(stderr, "warning: %s\n", stale.c_str());
  }
  if (!nobody.empty()) std::fprintf(stderr, "warning: %s\n", nobody.c_str());
}

}  // namespace

void RegisterTriangulateCommand(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<TriangulateArgs>();
  CLI::App* command = app.add_subcommand(
      "triangulate", "Triangulate 2D detections into 3D persons with track ids (your own cameras; no ground truth)");
  AddDetectionInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  AddExportOptions(command, &args->exports);
  command->add_option("--out", args->out, "output folder (default out/triangulate-<dataset or detections>, which does not replace a run of other input there)");
  AddThreadsOption(command, &args->threads, "sequences triangulated", /*one_sequence_stages=*/true);
  command->add_flag("--json", args->json, "print the summary as one JSON object");
  command->add_flag("--quiet", args->quiet, "no progress, no step table");
  command->add_option("--follow", args->follow,
                      "live input: frames as JSON lines from PATH (a named pipe or a file; - = standard input), "
                      "one JSON line of 3D persons per frame on standard output as soon as it is done (format below)")
      ->option_text("PATH");
  command->add_flag("--skip-bad-lines", args->skip_bad_lines,
                    "with --follow: skip lines that cannot be read and count them (printed at the end) instead of "
                    "stopping at the first (exit 2)");
  CLI::Option* spin = command->add_option("--spin-us", args->spin_us,
                      "with --follow: after each read, poll for the next line without sleeping for up to this many "
                      "microseconds (lower latency for lines that follow soon; 0 = sleep at once)")
      ->capture_default_str()
      ->option_text("US");
  CLI::Option* wait = command->add_option("--wait-for-lines", args->wait_for_lines_s,
                      "with --follow FILE (a regular file): at its end, wait up to this many seconds for more lines "
                      "(a detector still writing it, like tail -f; inf = until Ctrl-C) before the run ends; 0 = "
                      "the file's end ends the run")
      ->capture_default_str()
      ->option_text("SECONDS");
  command->footer(kFollowHelp);
  command->callback([args, exit_code, spin, wait] {
    if (!args->follow.empty()) {
      *exit_code = RunFollow(*args);
    } else {
      if (args->skip_bad_lines) throw ConfigError("--skip-bad-lines: only with --follow");
      if (spin->count() > 0) throw ConfigError("--spin-us: only with --follow");
      if (wait->count() > 0) throw ConfigError("--wait-for-lines: only with --follow");
      RunTriangulate(*args);
    }
  });
}

}  // namespace rpt::cli
