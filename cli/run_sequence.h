// SPDX-License-Identifier: MIT
// Runs sequences through the triangulator and the metrics: the loop shared by demo, eval,
// check, sweep and bench. Independent sequences are triangulated in parallel (OpenMP, one
// Triangulator per sequence); metrics are then accumulated in sequence order, so results do not
// depend on the thread count.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/pipeline/options.h"
#include "core/poses.h"
#include "datasets/detection_checks.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"
#include "metrics/accumulator.h"
#include "metrics/eval_options.h"
#include "metrics/step_counts.h"
#include "metrics/timing.h"

namespace rpt::cli {

struct RunOptions {
  TriangulatorOptions triangulator;  // room_check comes from the sequence unless its size is set
  metrics::EvalOptions eval;
  bool progress = true;              // progress on stderr for long runs
  int warmup_frames = 0;             // frames per sequence excluded from timing
  int threads = 0;                   // sequences in parallel; 0 = OpenMP default
};

// One sequence, triangulated.
struct TriangulatedSequence {
  JointNames output_joints;
  std::vector<Poses3D> predictions;  // per frame
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;  // every frame (warm-up frames included)
};

// One sequence's own numbers in a run of several (RunResult::per_sequence).
struct SequenceResult {
  std::string name;
  metrics::MetricsResult metrics;
  metrics::TimingSummary timing;
  long frames = 0;
};

struct RunResult {
  metrics::MetricsResult metrics;
  metrics::TimingSummary timing;  // over all frames of all sequences
  metrics::StepCountSummary counts;  // items per step per frame, over all frames of all sequences
  long frames = 0;
  double wall_seconds = 0;  // whole run (triangulation in parallel + metrics), steady clock
  int threads = 1;          // threads used for the sequences
  long gt_persons = 0;      // GT person-frames
  long output_persons = 0;  // triangulated person-frames
  std::vector<TriangulatedSequence> sequences;
  // With more than one sequence: each evaluated on its own, in input order (empty otherwise).
  std::vector<SequenceResult> per_sequence;
};

// The evaluation options of a run: metrics.evaluated_joints when set, else the joints the
// sequences' dataset evaluates (Sequence::evaluated_joints; empty = the paper's 13). Throws
// ConfigError when sequences disagree.
metrics::EvalOptions EvalOptionsFor(const std::vector<Sequence>& sequences, const metrics::EvalOptions& options);

// Triangulates every frame of one sequence (single thread). Throws ConfigError/InputError.
TriangulatedSequence TriangulateSequence(const Sequence& sequence, const RunOptions& options);

// Sees one input frame and its prediction (before smoothing.mode = offline smoothing, which
// needs the whole sequence), before the next frame is pulled.
using FrameVisitor = std::function<void(const SequenceFrame& frame, const Poses3D& prediction)>;

// Triangulates the frames of `source` as they are pulled (single thread): one input frame is
// alive at a time, only the predictions are kept, so memory is flat in the number of input
// frames apart from the predictions. Gives the same predictions as TriangulateSequence on the
// materialised sequence. Throws ConfigError/InputError.
TriangulatedSequence TriangulateSource(FrameSource& source, const RunOptions& options,
                                       const FrameVisitor& on_frame = {});

// Triangulates all sequences (in parallel) and evaluates them together.
RunResult RunSequences(const std::vector<Sequence>& sequences, const RunOptions& options);

// An evaluation of streamed input (RunSources).
struct StreamedRun {
  RunResult run;
  // Per source: its header and per frame the id, the time and the GT; the 2D detections and
  // labels are dropped once the frame is triangulated and checked.
  std::vector<Sequence> sequences;
  std::vector<SequenceCheck> checks;  // the input checks (DetectionChecker), one per source
  InputWarnings warnings;             // the corrections the sources applied (complete)
};

// What RunSequences does, on frame sources (datasets/frame_source.h): each source is pulled frame
// by frame (sources in parallel), each frame validated, checked (DetectionChecker with
// `check_options`) and triangulated, then dropped but for its id, time and GT. Input memory is
// flat in the number of frames; what grows is the GT and the predictions the metrics and
// outputs need. Same numbers as RunSequences on the materialised sequences.
StreamedRun RunSources(std::vector<std::unique_ptr<FrameSource>> sources, const RunOptions& options,
                       const DetectionCheckOptions& check_options = {});

}  // namespace rpt::cli
