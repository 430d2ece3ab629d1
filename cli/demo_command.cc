// SPDX-License-Identifier: MIT
// `rpt demo`: the triangulator on a generated scene (no downloads). Prints persons present vs
// found, the mean joint error and the time per frame and per step.
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/progress.h"
#include "engine/outputs/step_tables.h"
#include "engine/outputs/results_writer.h"
#include "engine/run.h"
#include "core/errors.h"
#include "core/text.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "datasets/synthetic/detector_options.h"

namespace rpt::cli {
namespace {

struct DemoOptions {
  int cameras = 5;
  int people = 4;
  int frames = 300;
  std::string joints = "body";
  std::string detector;  // profile; empty = realistic
  std::string noise;     // deprecated alias of detector
  std::string distortion = "none";
  uint64_t seed = 1;
  bool json = false;
  ConfigArgs config;
};

void RunDemo(DemoOptions o) {
  const std::string from_noise = o.noise == "none" ? "perfect" : o.noise;
  if (!o.noise.empty() && !o.detector.empty() && from_noise != o.detector) {
    throw ConfigError("--noise " + o.noise + " (deprecated) contradicts --detector " + o.detector);
  }
  if (o.detector.empty()) o.detector = o.noise.empty() ? "realistic" : from_noise;
  // The demo is the built-in synthetic dataset with the demo's options as its parameters (the
  // choices are checked by CLI11 against the same names).
  SyntheticParams params;
  params.cameras = o.cameras;
  params.people = o.people;
  params.frames = o.frames;
  EnumFromName(o.joints, &params.joints);
  EnumFromName(o.distortion, &params.distortion);
  params.noise = o.detector;
  params.seed = o.seed;
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(OpenSyntheticSequence(params));
  const engine::Config config = ResolveConfig(o.config);
  engine::RunOptions run_options;
  run_options.triangulator = config.triangulator;
  run_options.eval = config.metrics;
  Progress progress("demo", o.frames, !o.json);
  run_options.progress = ReportTo(&progress);
  const engine::RunResult run = engine::Run(std::move(sources), run_options);
  const metrics::MetricsResult& m = run.metrics;

  if (o.json) {
    nlohmann::ordered_json j;  // the demo's own keys first, then the standard summary
    j["cameras"] = o.cameras;
    j["people"] = o.people;
    j["joints"] = o.joints;
    j["output_joints"] = run.sequences.front().output_joints.size();
    j["detector"] = o.detector;
    j["distortion"] = o.distortion;
    j["seed"] = o.seed;
    j["persons_present"] = run.gt_persons;
    j["persons_found"] = run.output_persons;
    j["persons_matched"] = m.num_matches;
    j.update(engine::SummaryJson(run));
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("rpt demo: %d cameras, %d people, %d frames, %s joints (%zu in the output, with the derived ones), "
              "%s simulated detector, lens distortion %s, seed %llu\n",
              o.cameras, o.people, o.frames, o.joints.c_str(), run.sequences.front().output_joints.size(), o.detector.c_str(),
              o.distortion.c_str(), static_cast<unsigned long long>(o.seed));
  std::printf("persons present %ld, found %ld, matched %d (recall@500 %.1f %%, invalid %.1f %%)\n", run.gt_persons,
              run.output_persons, m.num_matches, m.recall_500, m.invalid);
  std::printf("mean joint error (MPJPE, %zu joints) %.1f mm, PCK@100 %.1f %%\n", m.joints.size(), m.mpjpe_mm,
              m.pck_100);
  if (o.joints == "wholebody") {
    for (const auto& g : m.wholebody) std::printf("  whole-body MPJPE %-6s %.1f mm\n", g.name.c_str(), g.mpjpe_mm);
  }
  std::printf("time per frame: median %.1f us, mean %.1f us (%.0f FPS, 2D to 3D, one thread)\n",
              run.timing.frame_us_median, run.timing.frame_us_mean, run.timing.fps);
  engine::PrintStepTimes(std::cout, run.timing, &run.counts);
  std::printf("\nNext: your own cameras and detections (rpt triangulate --cameras FILE --detections PATH; "
              "docs/own_data.md), or a public dataset with its ground truth (rpt eval --dataset NAME --root DIR; "
              "rpt datasets lists them).\n");
}

}  // namespace

void RegisterDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* demo = app.add_subcommand("demo", "Triangulate a generated scene and report accuracy and speed");
  demo->add_option("--cameras", options->cameras, "number of cameras")->check(CLI::Range(2, 64))->capture_default_str();
  demo->add_option("--people", options->people, "number of people")->check(CLI::Range(1, 30))->capture_default_str();
  demo->add_option("--frames", options->frames, "number of frames")->check(CLI::Range(1, 1000000))->capture_default_str();
  demo->add_option("--joints", options->joints, "body (17 COCO + 3) or wholebody (133 + 3)")
      ->check(CLI::IsMember({"body", "wholebody"}))
      ->capture_default_str();
  std::vector<std::string> profiles = synthetic::DetectorProfileNames();
  demo->add_option("--detector", options->detector,
                   "simulated detector profile: " + Join(profiles, ", ") + " (default realistic; docs/detector_model.md)")
      ->check(CLI::IsMember(profiles));
  profiles.push_back("none");
  demo->add_option("--noise", options->noise, "deprecated alias of --detector ('none' = perfect)")
      ->check(CLI::IsMember(profiles));
  demo->add_option("--distortion", options->distortion, "lens model: none, opencv or fisheye")
      ->check(CLI::IsMember({"none", "opencv", "fisheye"}))
      ->capture_default_str();
  demo->add_option("--seed", options->seed, "random seed")->capture_default_str();
  demo->add_flag("--json", options->json, "print one JSON object instead of text");
  AddConfigOptions(demo, &options->config);
  demo->callback([options] { RunDemo(*options); });
}

}  // namespace rpt::cli
