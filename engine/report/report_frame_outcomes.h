// SPDX-License-Identifier: MIT
// Per-frame outcomes of an evaluation for the HTML report: which GT persons were missed, which
// predictions are invalid, each frame's MPJPE, and recall as a function of the distance threshold.
// Everything comes from the metrics code (each frame's pairs and matches as MetricsAccumulator::Add
// resolved them, LastFrame()), so the report's per-frame numbers follow the run's matching rule and
// add up to its summary.
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"
#include "metrics/eval_options.h"
#include "metrics/metrics_result.h"

namespace rpt::engine {

// One frame.
struct FrameOutcome {
  double mpjpe_mm = 0;              // mean over this frame's matches (aligned if set); NaN when none
  int num_gt = 0;                   // kept GT persons (at least one valid evaluated joint)
  int num_matched = 0;              // matches at metrics.match_threshold_mm
  int num_invalid = 0;              // counted predictions without a match
  std::vector<int> gt_state;        // per GT person (Poses3D order): 1 matched, 0 missed, -1 not evaluated
  std::vector<bool> pred_invalid;   // per prediction: counted and not matched
  std::vector<double> pred_error_mm;  // per prediction: MPJPE to its nearest GT (absolute), +inf without one
};

struct RunOutcomes {
  std::vector<std::vector<FrameOutcome>> frames;  // per sequence, per frame
  metrics::MetricsResult metrics;                 // the whole run, as the summary
  std::vector<double> recall_threshold_mm;        // recall curve: thresholds ...
  std::vector<double> recall;                     // ... and recall (%) at each; empty with hungarian matching
};

// Evaluates `predictions` (per sequence, per frame; joints `prediction_joints`) against the GT of
// `sequences` with `options` (as RunSequences resolves them: EvalOptionsFor). Throws ConfigError /
// InputError as MetricsAccumulator does.
RunOutcomes EvaluateFrameOutcomes(const std::vector<Sequence>& sequences,
                                  const std::vector<std::vector<Poses3D>>& predictions,
                                  const JointNames& prediction_joints, const metrics::EvalOptions& options);

}  // namespace rpt::engine
