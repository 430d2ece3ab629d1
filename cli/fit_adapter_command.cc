// SPDX-License-Identifier: MIT
// `rpt fit-adapter`: fits a joint-definition adapter (engine/joint_adapter_fit.h,
// docs/joint_adapter.md) on one part of a dataset (selected with its parameters, e.g.
// --param frames=0-149 or --param days=1,2) and writes it to --out; `rpt eval --adapter FILE`
// applies it to another part. Prints the split it was fitted on and each joint's offset.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/input_options.h"
#include "cli/threads_option.h"
#include "core/printable_text.h"
#include "engine/input.h"
#include "engine/joint_adapter.h"
#include "engine/joint_adapter_fit.h"
#include "engine/outputs/run_info.h"
#include "engine/run.h"

namespace rpt::cli {
namespace {

struct FitAdapterArgs {
  engine::InputSpec input;
  ConfigArgs config;
  std::string out;
  std::string statistic = "median";
  long min_samples = 20;
  int threads = 0;
};

void RunFitAdapter(const FitAdapterArgs& args) {
  const engine::Config config = ResolveConfig(args.config);
  engine::Input input = engine::OpenInput(args.input);
  PrintInputWarnings(input.Warnings());
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval = config.metrics;
  options.threads = args.threads;
  engine::JointAdapterFitOptions fit;
  fit.statistic = args.statistic == "mean" ? OffsetStatistic::kMean : OffsetStatistic::kMedian;
  fit.min_samples = args.min_samples;
  engine::JointAdapter adapter = engine::FitJointAdapter(input, options, fit);
  adapter.fit.dataset = args.input.dataset;
  adapter.fit.root = args.input.root.empty() ? args.input.labels : args.input.root;
  adapter.fit.params = args.input.params;
  adapter.fit.command = engine::CurrentCommandLine();
  adapter.fit.git_revision = engine::CollectRunInfo(0).git_revision;
  engine::WriteJointAdapter(args.out, adapter);

  std::printf("fitted on %s\n", PrintableText(engine::FitDescription(adapter.fit), LineBreaks::kEscape).c_str());
  if (adapter.fit.persons_without_body_frame > 0) {
    std::printf("  %ld matched persons left out: no body frame (hips or shoulders missing or degenerate)\n",
                adapter.fit.persons_without_body_frame);
  }
  std::printf("offsets (%s of the residuals, body frame: x right, y forward, z up; mm):\n",
              engine::OffsetStatisticName(adapter.statistic));
  std::printf("  %-18s %8s %8s %8s %8s %8s %8s\n", "joint", "x", "y", "z", "|offset|", "spread", "samples");
  for (size_t j = 0; j < adapter.joints.size(); ++j) {
    const Eigen::Vector3d mm = 1000.0 * adapter.offset_m[j];
    if (adapter.samples[j] < adapter.fit.min_samples) {
      std::printf("  %-18s %8s %8s %8s %8s %8s %8ld\n", PrintableText(adapter.joints[j], LineBreaks::kEscape).c_str(),
                  "-", "-", "-", "-", "-", adapter.samples[j]);
      continue;
    }
    std::printf("  %-18s %8.1f %8.1f %8.1f %8.1f %8.1f %8ld\n",
                PrintableText(adapter.joints[j], LineBreaks::kEscape).c_str(), mm.x(), mm.y(), mm.z(), mm.norm(),
                1000.0 * adapter.spread_m[j], adapter.samples[j]);
  }
  std::printf("wrote %s (apply with: rpt eval ... --adapter %s, on other frames)\n",
              PrintableText(args.out, LineBreaks::kEscape).c_str(), PrintableText(args.out, LineBreaks::kEscape).c_str());
}

}  // namespace

void RegisterFitAdapterCommand(CLI::App& app) {
  auto args = std::make_shared<FitAdapterArgs>();
  CLI::App* command = app.add_subcommand(
      "fit-adapter",
      "Fit a joint-definition adapter (per joint, an offset in the person's body frame) on part of a dataset; "
      "apply it with `rpt eval --adapter` to other frames (docs/joint_adapter.md)");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  command->add_option("--out", args->out, "the adapter file to write (JSON)")->required();
  command->add_option("--statistic", args->statistic, "how a joint's residuals become its offset: median (per body "
                                                      "axis; default) or mean")
      ->check(CLI::IsMember({"median", "mean"}));
  command->add_option("--min-samples", args->min_samples, "joints with fewer matched residuals get no offset (default 20)")
      ->check(CLI::NonNegativeNumber);
  AddThreadsOption(command, &args->threads, "sequences triangulated");
  command->callback([args] { RunFitAdapter(*args); });
}

}  // namespace rpt::cli
