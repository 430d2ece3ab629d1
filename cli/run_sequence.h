// SPDX-License-Identifier: MIT
// Runs one sequence through the triangulator and the metrics: the loop shared by demo, eval,
// check, sweep and bench.
#pragma once

#include <vector>

#include "core/pipeline/options.h"
#include "core/poses.h"
#include "datasets/sequence.h"
#include "metrics/accumulator.h"
#include "metrics/eval_options.h"
#include "metrics/timing.h"

namespace rpt::cli {

struct RunOptions {
  TriangulatorOptions triangulator;  // room_check comes from the sequence unless its size is set
  metrics::EvalOptions eval;
  bool keep_predictions = false;     // fill SequenceRun::predictions
  bool progress = true;              // progress on stderr for long runs
  int warmup_frames = 0;             // frames excluded from timing
};

struct SequenceRun {
  metrics::MetricsResult metrics;
  metrics::TimingSummary timing;
  metrics::TimingAccumulator timing_frames;  // raw per-frame times (for merging runs)
  long gt_persons = 0;      // GT person-frames
  long output_persons = 0;  // triangulated person-frames
  JointNames output_joints;
  std::vector<Poses3D> predictions;  // per frame when keep_predictions
};

// Throws ConfigError for invalid options, InputError for inconsistent sequences.
SequenceRun RunSequence(const Sequence& sequence, const RunOptions& options);

}  // namespace rpt::cli
