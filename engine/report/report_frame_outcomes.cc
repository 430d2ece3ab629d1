// SPDX-License-Identifier: MIT
#include "engine/report/report_frame_outcomes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/nan.h"
#include "metrics/accumulator.h"
#include "metrics/eval_records.h"
#include "metrics/matching.h"

namespace rpt::engine {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The thresholds of the recall curve (mm).
std::vector<double> RecallThresholdsMm() {
  std::vector<double> thresholds;
  for (double t = 10; t <= 500; t += 10) thresholds.push_back(t);
  return thresholds;
}

}  // namespace

RunOutcomes EvaluateFrameOutcomes(const std::vector<Sequence>& sequences,
                                  const std::vector<std::vector<Poses3D>>& predictions,
                                  const JointNames& prediction_joints, const metrics::EvalOptions& options) {
  metrics::MetricsAccumulator accumulator(options);
  const bool greedy = options.matching == metrics::MatchingMode::kGreedy;
  const std::vector<double> thresholds_mm = RecallThresholdsMm();
  std::vector<int> matches_at_threshold(thresholds_mm.size(), 0);

  RunOutcomes out;
  out.frames.resize(sequences.size());
  for (size_t s = 0; s < sequences.size(); ++s) {
    const Sequence& sequence = sequences[s];
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      const SequenceFrame& frame = sequence.frames[f];
      accumulator.Add(frame.id, frame.gt, sequence.gt_joints, predictions[s][f], prediction_joints);
      const metrics::FrameRecords& records = accumulator.LastFrame();
      FrameOutcome outcome;
      outcome.num_gt = static_cast<int>(records.kept_gt_idx.size());
      outcome.gt_state.assign(frame.gt.num_persons(), -1);
      for (const int g : records.kept_gt_idx) outcome.gt_state[g] = 0;
      outcome.pred_invalid.assign(records.num_predictions, records.counted);
      outcome.pred_error_mm.assign(records.num_predictions, kInf);
      double sum = 0;
      int count = 0;
      for (const metrics::PairRecord& pair : records.pairs) {
        if (pair.flags & metrics::kNearest) outcome.pred_error_mm[pair.pred_idx] = pair.error_mm;
        if (!(pair.flags & metrics::kMatch)) continue;
        outcome.pred_invalid[pair.pred_idx] = false;
        outcome.gt_state[records.kept_gt_idx[pair.gt_idx]] = 1;
        ++outcome.num_matched;
        if (!std::isnan(pair.report_error_mm)) {
          sum += pair.report_error_mm;
          ++count;
        }
      }
      for (const bool invalid : outcome.pred_invalid) outcome.num_invalid += invalid ? 1 : 0;
      outcome.mpjpe_mm = count > 0 ? sum / count : kNaN;
      out.frames[s].push_back(std::move(outcome));

      // Recall against the distance threshold: the run's greedy matching redone at each threshold
      // (per frame, as the accumulator does: a pair competes only with pairs of its frame).
      if (greedy) {
        const std::vector<metrics::MatchRecord> nearest = metrics::NearestMatchRecords(records);
        for (size_t t = 0; t < thresholds_mm.size(); ++t) {
          const std::vector<bool> is_match = metrics::GreedyMatch(nearest, thresholds_mm[t]);
          matches_at_threshold[t] += static_cast<int>(std::count(is_match.begin(), is_match.end(), true));
        }
      }
    }
  }
  out.metrics = accumulator.Finalize();
  if (greedy && out.metrics.num_gt_persons > 0) {
    out.recall_threshold_mm = thresholds_mm;
    for (const int matches : matches_at_threshold) out.recall.push_back(100.0 * matches / out.metrics.num_gt_persons);
  }
  return out;
}

}  // namespace rpt::engine
