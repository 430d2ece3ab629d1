// SPDX-License-Identifier: MIT
// `rpt bench`: single-threaded speed of the triangulator on the benchmark scenes (bench/), 2D to
// 3D including undistortion: median per frame and per step over several passes after a warm-up,
// the accuracy of the same run, and in the same run a straightforward baseline implementation
// with the speed-up over it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "bench/baseline_triangulator.h"
#include "bench/bench_scenes.h"
#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/follow_bench.h"
#include "cli/input_options.h"
#include "core/errors.h"
#include "core/pipeline/simd_kernels.h"
#include "core/pipeline/triangulator.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/detections.h"
#include "datasets/io/hdf5_preflight.h"
#include "datasets/io/inflate_budget.h"
#include "datasets/io/staged_output.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/synthetic/detector_options.h"
#include "engine/input.h"
#include "engine/input_digests.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/run_info.h"
#include "engine/outputs/step_tables.h"
#include "engine/run.h"
#include "metrics/accumulator.h"
#include "metrics/timing.h"

namespace rpt::cli {
namespace {

using OrderedJson = nlohmann::ordered_json;

struct BenchArgs {
  bool io = false;
  int io_frames = 10000;
  bool follow = false;
  double follow_rate = 0;  // lines per second; 0: back to back
  std::vector<std::string> scenes;
  bool scaling = false;
  int frames = 0;
  int repeat = 5;
  int baseline_frames = 30;
  bool no_baseline = false;
  bool json = false;
  std::string detector = "clean";
  bool detector_given = false;
  bool io_frames_given = false;
  bool simulate = false;      // with --dataset: its detections simulated from its ground truth (--detector)
  engine::InputSpec dataset;  // --dataset/--root/--param: a dataset's real frames as one more column
  ConfigArgs config;
};

struct SceneResult {
  bench::BenchScene scene;
  metrics::TimingSummary timing;
  metrics::MetricsResult metrics;
  double baseline_median_us = 0;
  metrics::MetricsResult baseline_metrics;
  // rpt on the frames the baseline ran on (the first --baseline-frames): the speed-up and the two
  // MPJPEs compare these (the first 30 of Shelf's 301 real frames are not its median frame).
  int baseline_frames = 0;
  double same_frames_us = 0;
  metrics::MetricsResult same_frames_metrics;
  bool has_gt = true;  // false: a dataset's frames without ground truth (no accuracy rows)
  // The median frame time the target is about: with the reader's grouping where it has one.
  double TargetedUs() const {
    return timing.paf_grouping_frames > 0 ? timing.frame_with_grouping_us_median : timing.frame_us_median;
  }
  long output_persons = 0;  // in the first timed pass: a run that triangulates nobody meets no target
  bool MeetsTarget() const { return output_persons > 0 && TargetedUs() <= scene.target_us; }
};

// rpt's frame times and accuracy on the baseline's frames, gathered while the passes run.
struct SameFrames {
  explicit SameFrames(const metrics::EvalOptions& options) : accuracy(options) {}
  std::vector<double> times_us;
  metrics::MetricsAccumulator accuracy;
  void Finalize(SceneResult* result) const {
    result->same_frames_us = metrics::Median(times_us);
    result->same_frames_metrics = accuracy.Finalize();
  }
};

SceneResult BenchScene(const bench::BenchScene& scene, const BenchArgs& args, const engine::Config& config) {
  const Sequence sequence = bench::MakeBenchSequence(scene, 1, args.detector);
  Triangulator triangulator(sequence.cameras, sequence.detection_joints,
                            engine::TriangulatorOptionsFor(config.triangulator, sequence));
  SceneResult result;
  result.scene = scene;
  Poses3D persons;
  FrameStats stats;
  metrics::TimingAccumulator timing;
  metrics::MetricsAccumulator accuracy(config.metrics);
  SameFrames same(config.metrics);
  const size_t baseline_frames =
      args.no_baseline ? 0 : std::min<size_t>(sequence.frames.size(), static_cast<size_t>(args.baseline_frames));
  for (int pass = 0; pass <= args.repeat; ++pass) {  // pass 0 warms up (caches, buffer growth)
    triangulator.Reset();
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      const SequenceFrame& frame = sequence.frames[f];
      triangulator.Process(frame.views, frame.timestamp_s, &persons, &stats);
      if (pass > 0) timing.Add(stats, frame.paf_grouping_us);
      if (pass == 1) {
        accuracy.Add(frame.id, frame.gt, sequence.gt_joints, persons, triangulator.output_joints());
        result.output_persons += persons.num_persons();
      }
      if (f >= baseline_frames) continue;
      if (pass > 0) same.times_us.push_back(stats.total_us);
      if (pass == 1) same.accuracy.Add(frame.id, frame.gt, sequence.gt_joints, persons, triangulator.output_joints());
    }
  }
  result.timing = timing.Finalize();
  result.metrics = accuracy.Finalize();
  same.Finalize(&result);
  result.baseline_frames = static_cast<int>(baseline_frames);
  if (!args.no_baseline) {
    const bench::BaselineTriangulator baseline(sequence.cameras, sequence.detection_joints);
    std::vector<double> times;
    metrics::MetricsAccumulator baseline_accuracy(config.metrics);
    for (size_t f = 0; f < baseline_frames; ++f) {
      const auto start = std::chrono::steady_clock::now();
      const Poses3D out = baseline.Process(sequence.frames[f].views);
      times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      baseline_accuracy.Add(sequence.frames[f].id, sequence.frames[f].gt, sequence.gt_joints, out, sequence.detection_joints);
    }
    result.baseline_median_us = metrics::Median(times);
    result.baseline_metrics = baseline_accuracy.Finalize();
  }
  return result;
}

// A dataset's frames (--dataset/--root/--param) timed like a scene: each pass opens the input
// again and pulls its frames one at a time, as `rpt eval` does, so a reader that groups raw
// candidates into persons (shelf-4da's part-affinity grouping) does it again in every pass and its
// time per frame (SequenceFrame::paf_grouping_us) is a row of its own. One triangulator per
// sequence, kept over the passes (Reset before each); pass 0 warms up; accuracy from pass 1; the
// baseline on the first --baseline-frames frames.
SceneResult BenchDataset(const BenchArgs& args, const engine::Config& config, InputWarnings* warnings) {
  SceneResult result;
  result.scene.name = args.dataset.dataset;
  std::optional<SameFrames> same;
  result.scene.target_us = bench::DatasetTargetUs(args.dataset.dataset);
  std::vector<std::unique_ptr<Triangulator>> triangulators;
  metrics::EvalOptions eval_options;
  std::optional<metrics::MetricsAccumulator> accuracy;
  metrics::TimingAccumulator timing;
  std::vector<std::pair<size_t, SequenceFrame>> baseline_frames;  // (sequence, frame)
  std::vector<std::vector<Camera>> cameras;
  std::vector<JointNames> detection_joints, gt_joints;
  long frames = 0, gt_persons = 0;
  SequenceFrame frame;
  Poses3D persons;
  FrameStats stats;
  for (int pass = 0; pass <= args.repeat; ++pass) {
    engine::Input input = engine::OpenInput(args.dataset);
    if (pass == 0) {
      std::vector<const SequenceHeader*> headers;
      for (int i = 0; i < input.size(); ++i) {
        const SequenceHeader& header = input.header(i);
        headers.push_back(&header);
        triangulators.push_back(std::make_unique<Triangulator>(
            header.cameras, header.detection_joints, engine::TriangulatorOptionsFor(config.triangulator, header)));
        cameras.push_back(header.cameras);
        detection_joints.push_back(header.detection_joints);
        gt_joints.push_back(header.gt_joints);
      }
      eval_options = engine::EvalOptionsFor(config.metrics, headers);
      accuracy.emplace(eval_options);
      same.emplace(eval_options);
    }
    if (input.size() != static_cast<int>(triangulators.size())) {
      throw InputError(args.dataset.root + ": the dataset changed between the passes");
    }
    long index = 0;  // of the frame in the pass, over the sequences
    const long baseline_count = args.no_baseline ? 0 : args.baseline_frames;
    for (int i = 0; i < input.size(); ++i) {
      Triangulator& triangulator = *triangulators[static_cast<size_t>(i)];
      triangulator.Reset();
      for (; input.source(i).Next(&frame); ++index) {
        triangulator.Process(frame.views, frame.timestamp_s, &persons, &stats);
        if (pass > 0) timing.Add(stats, frame.paf_grouping_us);
        if (pass > 0 && index < baseline_count) same->times_us.push_back(stats.total_us);
        if (pass != 1) continue;
        ++frames;
        gt_persons += frame.gt.num_persons();
        result.output_persons += persons.num_persons();
        accuracy->Add(frame.id, frame.gt, gt_joints[static_cast<size_t>(i)], persons, triangulator.output_joints());
        if (index < baseline_count) {
          same->accuracy.Add(frame.id, frame.gt, gt_joints[static_cast<size_t>(i)], persons,
                             triangulator.output_joints());
          baseline_frames.emplace_back(static_cast<size_t>(i), frame);
        }
      }
      input.Finished(i);
    }
    if (pass == 0) {  // once, not per pass
      *warnings = input.Warnings();
      if (!args.json) PrintInputWarnings(*warnings);
    }
  }
  if (frames == 0) throw InputError(args.dataset.dataset + ": no frames to time (check --param frames=...)");
  result.scene.frames = static_cast<int>(frames);
  result.scene.description = std::to_string(frames) + " frames of " + std::to_string(triangulators.size()) +
                             " sequence(s), " + std::to_string(cameras.empty() ? 0 : cameras.front().size()) +
                             " cameras; " +
                             (args.dataset.root.empty() ? "generated" : PrintableText(args.dataset.root));
  result.timing = timing.Finalize();
  result.metrics = accuracy->Finalize();
  result.has_gt = gt_persons > 0;
  same->Finalize(&result);
  result.baseline_frames = static_cast<int>(baseline_frames.size());
  if (!args.no_baseline) {
    std::vector<std::optional<bench::BaselineTriangulator>> baselines(cameras.size());
    std::vector<double> times;
    metrics::MetricsAccumulator baseline_accuracy(eval_options);
    for (const auto& [i, f] : baseline_frames) {
      if (!baselines[i]) baselines[i].emplace(cameras[i], detection_joints[i]);
      const auto start = std::chrono::steady_clock::now();
      const Poses3D out = baselines[i]->Process(f.views);
      times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      baseline_accuracy.Add(f.id, f.gt, gt_joints[i], out, detection_joints[i]);
    }
    result.baseline_median_us = metrics::Median(times);
    result.baseline_metrics = baseline_accuracy.Finalize();
  }
  return result;
}

// Writes a detections cache of `frames` x 5 views (shelf-like detections, repeated) to a temporary
// HDF5 file and times reading it back (median of 5 reads, file in the OS cache).
void RunIoBench(const BenchArgs& args) {
  const Sequence sequence = bench::MakeBenchSequence(bench::StandardScenes()[0], 1, args.detector);
  Detections detections;
  detections.joints = sequence.detection_joints;
  long persons = 0;
  for (int f = 0; f < args.io_frames; ++f) {
    const SequenceFrame& source = sequence.frames[f % sequence.frames.size()];
    FrameDetections frame{"frame_" + std::to_string(f), {}, source.views};
    for (const Camera& c : sequence.cameras) frame.cameras.push_back(c.name);
    for (const Poses2D& v : source.views) persons += v.num_persons();
    detections.frames.push_back(std::move(frame));
  }
  // Removed on every way out: return, exception (the destructor) and Ctrl-C (the interrupt handler).
  const io::ScratchFile scratch(std::filesystem::temp_directory_path() / "rpt_bench_io.h5");
  const std::filesystem::path& path = scratch.path();
  const auto write_start = std::chrono::steady_clock::now();
  WriteDetectionsHdf5(path, detections);
  const double write_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
  std::vector<double> reads;
  size_t frames_read = 0;
  for (int i = 0; i < 5; ++i) {
    io::ForgetPassedHdf5Files();  // every read as the first of the file: with its walk
    const auto start = std::chrono::steady_clock::now();
    const Detections loaded = ReadDetectionsHdf5(path);
    reads.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    frames_read = loaded.frames.size();
  }
  // The walk every read starts with (a child process checks the file's metadata first), alone.
  std::vector<double> walks;
  for (int i = 0; i < 5; ++i) {
    io::ForgetPassedHdf5Files();
    const auto start = std::chrono::steady_clock::now();
    io::PreflightHdf5(path.string(), path, io::InflateLimitFor(std::filesystem::file_size(path)));
    walks.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const double walk_s = metrics::Median(walks);
  const auto size = std::filesystem::file_size(path);
  if (frames_read != detections.frames.size()) throw InputError(path.string() + ": read back a different frame count");
  const double read_s = metrics::Median(reads);
  if (args.json) {
    OrderedJson j;
    j["frames"] = args.io_frames;
    j["views"] = sequence.cameras.size();
    j["persons"] = persons;
    j["file_mb"] = static_cast<double>(size) / 1e6;
    j["write_s"] = write_s;
    j["read_s_median"] = read_s;
    j["preflight_s_median"] = walk_s;
    j["frames_per_s"] = args.io_frames / read_s;
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf(
      "HDF5 detection cache: %d frames x %zu views, %ld persons, %.1f MB; write %.3f s; read %.3f s (median of 5)"
      " = %.0f frames/s; of each read, the metadata walk in a child process %.1f ms (median of 5)\n",
      args.io_frames, sequence.cameras.size(), persons, static_cast<double>(size) / 1e6, write_s, read_s,
      args.io_frames / read_s, walk_s * 1e3);
}

void RunBench(const BenchArgs& args) {
  // One mode per run: each of these was silently given up for another (a performance user's finding).
  if (args.io && (!args.scenes.empty() || args.scaling || args.follow || !args.dataset.dataset.empty())) {
    throw ConfigError("--io times reading an HDF5 detection cache: not with --scene, --scaling, --follow or --dataset");
  }
  if (args.io_frames_given && !args.io) throw ConfigError("--io-frames sets the --io cache's frames: add --io");
  if (args.io) {
    RunIoBench(args);
    return;
  }
  const engine::Config config = ResolveConfig(args.config);
  std::vector<bench::BenchScene> scenes;
  const std::vector<bench::BenchScene> all = [&] {
    std::vector<bench::BenchScene> list = bench::StandardScenes();
    for (const auto& s : bench::ScalingScenes()) list.push_back(s);
    return list;
  }();
  for (const std::string& name : args.scenes) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& s) { return s.name == name; });
    if (it == all.end()) {
      std::string known;
      for (const auto& s : all) AppendItem(&known, s.name);
      throw ConfigError("--scene " + name + ": unknown (known: " + known + ")");
    }
    scenes.push_back(*it);
  }
  const bool dataset = !args.dataset.dataset.empty();
  if (dataset && args.follow) {
    throw ConfigError("--dataset times the pipeline on a dataset's frames: not with --follow or --io");
  }
  if (!dataset && (!args.dataset.root.empty() || !args.dataset.params.empty() || args.simulate)) {
    throw ConfigError(
        "--root, --param and --simulate name a dataset's folder, reader parameters and detections: add "
        "--dataset NAME");
  }
  if (args.follow && args.scaling) throw ConfigError("--follow times the live input on one scene: not with --scaling");
  const bool generated = !args.scenes.empty() || args.scaling || !dataset;
  if (dataset && !generated && args.frames > 0) {
    throw ConfigError(
        "--frames sets the generated scenes' frames; a dataset's frames are chosen with its reader's "
        "parameter (--param frames=... where the reader has one)");
  }
  if (dataset && !generated && args.detector_given && !args.simulate) {
    throw ConfigError(
        "--detector sets the simulated detector of the generated scenes, or of the dataset with "
        "--simulate; the dataset's own detections have none (the synthetic dataset's: --param noise=...)");
  }
  if (scenes.empty() && args.follow) scenes.push_back(bench::StandardScenes().front());  // shelf-like
  if (scenes.empty() && (args.scaling || !dataset))
    scenes = args.scaling ? bench::ScalingScenes() : bench::StandardScenes();
  for (auto& s : scenes) {
    if (args.frames > 0) s.frames = args.frames;
  }
  if (args.follow_rate > 0 && !args.follow) throw ConfigError("--follow-rate paces the lines of --follow: add --follow");
  if (args.follow) {
    RunFollowBench(scenes, args.repeat, args.follow_rate, args.detector, config, args.json);
    return;
  }

  std::vector<SceneResult> results;
  for (const auto& scene : scenes) {
    if (!args.json) std::fprintf(stderr, "benchmarking %s ...\n", scene.name.c_str());
    results.push_back(BenchScene(scene, args, config));
  }
  InputWarnings dataset_warnings;
  if (dataset) {
    if (!args.json) std::fprintf(stderr, "benchmarking %s ...\n", args.dataset.dataset.c_str());
    results.push_back(BenchDataset(args, config, &dataset_warnings));
  }
  const auto grouped = [](const SceneResult& r) { return r.timing.paf_grouping_frames > 0; };
  const bool grouping = std::any_of(results.begin(), results.end(), grouped);
  engine::RunInfo info = engine::CollectRunInfo(1);
  if (dataset) {  // what was read, as eval's run.json records it
    info.input_warnings = engine::InputWarningLines(dataset_warnings);
    info.input_settings = engine::ResolvedInputSettings(args.dataset);
    info.input_digests = engine::InputDigests(args.dataset);
  }
  if (args.json) {
    OrderedJson j;
    j["run"] = engine::RunInfoJson(info);
    j["simd"] = simd::Enabled() ? simd::ActivePath() : "off";  // the instruction set the kernels ran on (chosen at run time)
    j["repeat"] = args.repeat;
    j["scenes"] = OrderedJson::array();
    for (const SceneResult& r : results) {
      OrderedJson s;
      s["name"] = r.scene.name;
      s["description"] = r.scene.description;
      s["frames"] = r.scene.frames;
      s["frame_time_us_median"] = r.timing.frame_us_median;
      s["frame_time_us_mean"] = r.timing.frame_us_mean;
      s["frame_time_us_p90"] = r.timing.frame_us_p90;
      s["step_time_us_median"] = engine::StepTimesJson(r.timing);
      // With a reader's grouping of raw candidates (its time is the first key of step_time_us_median):
      // the frame with it.
      if (r.timing.paf_grouping_frames > 0) s["frame_with_grouping_us_median"] = r.timing.frame_with_grouping_us_median;
      if (r.has_gt) {
        s["mpjpe_mm"] = r.metrics.mpjpe_mm;
        s["recall500"] = r.metrics.recall_500;
        s["invalid"] = r.metrics.invalid;
      }
      if (!args.no_baseline) {  // the baseline on the first baseline_frames frames, rpt on the same
        s["baseline_frames"] = r.baseline_frames;
        s["baseline_frame_time_us_median"] = r.baseline_median_us;
        s["frame_time_us_median_on_baseline_frames"] = r.same_frames_us;
        if (r.has_gt) {
          s["baseline_mpjpe_mm"] = r.baseline_metrics.mpjpe_mm;
          s["mpjpe_mm_on_baseline_frames"] = r.same_frames_metrics.mpjpe_mm;
        }
        s["speedup"] = r.baseline_median_us / r.same_frames_us;
      }
      if (r.scene.target_us > 0) {
        s["target_us"] = r.scene.target_us;
        // What the target is compared with: the frame time, with the reader's grouping where it has one.
        s["target_compares"] =
            r.timing.paf_grouping_frames > 0 ? "frame_with_grouping_us_median" : "frame_time_us_median";
        s["meets_target"] = r.MeetsTarget();
      }
      j["scenes"].push_back(s);
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("rpt bench: one thread, median over %d passes after a warm-up; revision %s; %s; %s; SIMD %s\n\n",
              args.repeat, info.git_revision.c_str(), info.cpu.c_str(), info.compiler.c_str(),
              simd::Enabled() ? simd::ActivePath().c_str() : "off");
  // A row whose value only some columns have ("-" in the others, and where it is not a number: the
  // MPJPE of a run that matched nobody).
  auto partial_row = [&](const char* label, auto has, auto value, const char* format) {
    std::printf("%-22s", label);
    for (const auto& r : results) {
      if (has(r) && std::isfinite(static_cast<double>(value(r)))) {
        std::printf(format, value(r));
      } else {
        std::printf(" %14s", "-");
      }
    }
    std::printf("\n");
  };
  std::printf("%-22s", "step (us)");
  for (const auto& r : results) std::printf(" %14s", r.scene.name.c_str());
  std::printf("\n");
  if (grouping) {  // the reader's part-affinity grouping, done before the pipeline's steps (as in rpt eval)
    partial_row(
        engine::kPafGroupingRow, grouped, [](const SceneResult& r) { return r.timing.paf_grouping_us_median; },
        " %14.2f");
  }
  for (int s = 0; s < kNumSteps; ++s) {
    std::printf("%-22s", std::string(kSteps[s].key).c_str());
    for (const auto& r : results) std::printf(" %14.2f", r.timing.step_us_median[s]);
    std::printf("\n");
  }
  auto row = [&](const char* label, auto value, const char* format) {
    std::printf("%-22s", label);
    for (const auto& r : results) std::printf(format, value(r));
    std::printf("\n");
  };
  row("total (median)", [](const SceneResult& r) { return r.timing.frame_us_median; }, " %14.2f");
  row("total (mean)", [](const SceneResult& r) { return r.timing.frame_us_mean; }, " %14.2f");
  if (grouping) {
    partial_row(
        "frame + grouping", grouped, [](const SceneResult& r) { return r.timing.frame_with_grouping_us_median; },
        " %14.2f");
  }
  // The scene's target (us per frame, median; with the grouping where there is one) and whether
  // the median meets it; "-" without one.
  std::printf("%-22s", "target (us)");
  for (const auto& r : results) {
    if (r.scene.target_us > 0) {
      std::printf(" %14.0f", r.scene.target_us);
    } else {
      std::printf(" %14s", "-");
    }
  }
  std::printf("\n%-22s", "target met");
  for (const auto& r : results) {
    std::printf(" %14s", r.scene.target_us <= 0  ? "-"
                         : r.MeetsTarget()       ? "yes"
                         : r.output_persons == 0 ? "NO (nobody)"
                                                 : "NO");
  }
  std::printf("\n");
  const auto has_gt = [](const SceneResult& r) { return r.has_gt; };
  partial_row(
      "MPJPE (mm)", has_gt, [](const SceneResult& r) { return r.metrics.mpjpe_mm; }, " %14.1f");
  partial_row(
      "Recall@500 (%)", has_gt, [](const SceneResult& r) { return r.metrics.recall_500; }, " %14.1f");
  partial_row(
      "Invalid (%)", has_gt, [](const SceneResult& r) { return r.metrics.invalid; }, " %14.1f");
  if (!args.no_baseline) {
    // The baseline on the first frames (--baseline-frames); rpt's time and MPJPE on those same frames.
    row(
        "baseline frames", [](const SceneResult& r) { return r.baseline_frames; }, " %14d");
    row("baseline (us)", [](const SceneResult& r) { return r.baseline_median_us; }, " %14.1f");
    row(
        "rpt on them (us)", [](const SceneResult& r) { return r.same_frames_us; }, " %14.2f");
    partial_row(
        "baseline MPJPE", has_gt, [](const SceneResult& r) { return r.baseline_metrics.mpjpe_mm; }, " %14.1f");
    partial_row(
        "rpt MPJPE on them", has_gt, [](const SceneResult& r) { return r.same_frames_metrics.mpjpe_mm; }, " %14.1f");
    row(
        "speed-up", [](const SceneResult& r) { return r.baseline_median_us / r.same_frames_us; }, " %13.1fx");
  }
}

}  // namespace

void RegisterBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* command = app.add_subcommand("bench", "Single-threaded speed on the benchmark scenes, with a baseline");
  command->add_option("--scene", args->scenes, "scene name (repeatable; default: the standard scenes)")->take_all();
  command->add_flag("--scaling", args->scaling, "the scaling series over cameras (2..31) and people (1..20)");
  command
      ->add_option("--frames", args->frames, "frames per generated scene (default: the scene's; a dataset's: --param)")
      ->check(CLI::Range(1, 1000000));
  command->add_option("--repeat", args->repeat, "timed passes over the frames")->check(CLI::Range(1, 1000))->capture_default_str();
  command->add_option("--baseline-frames", args->baseline_frames, "frames for the baseline (none: --no-baseline)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_flag("--no-baseline", args->no_baseline, "skip the baseline");
  command
      ->add_option("--detector", args->detector,
                   "simulated detector profile of the scenes, and of a dataset with --simulate (clean: the "
                   "workload of results/bench.md)")
      ->check(CLI::IsMember(synthetic::DetectorProfileNames()))
      ->capture_default_str()
      ->each([args](const std::string&) { args->detector_given = true; });
  command->add_flag("--json", args->json, "print the results as JSON");
  command->add_flag("--follow", args->follow,
                    "time the live input instead (triangulate --follow): lines fed one at a time through a pipe, "
                    "median line in -> line out latency vs. the triangulation time (default scene: shelf-like)");
  command->add_option("--follow-rate", args->follow_rate,
                      "with --follow: feed the lines at this many per second, as a camera does (default 0: each as soon "
                      "as the output line of the one before is back)")
      ->check(CLI::Range(0.0, 100000.0));
  command->add_flag("--io", args->io, "time reading an HDF5 detection cache instead (see --io-frames)");
  command->add_option("--io-frames", args->io_frames, "frames in the --io cache (5 views each)")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str()
      ->each([args](const std::string&) { args->io_frames_given = true; });
  command->add_flag("--simulate", args->simulate,
                    "with --dataset: simulate its 2D detections from its ground truth (--detector), for datasets "
                    "without detections of their own");
  AddDatasetOptions(command, &args->dataset);  // a dataset's real frames as one more column
  AddConfigOptions(command, &args->config);
  command->callback([args] {
    args->dataset.simulate = args->simulate;
    if (args->simulate) args->dataset.detector = args->detector;
    RunBench(*args);
  });
}

}  // namespace rpt::cli
