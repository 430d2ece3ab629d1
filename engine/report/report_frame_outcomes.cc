// SPDX-License-Identifier: MIT
#include "engine/report/report_frame_outcomes.h"

#include <cmath>
#include <limits>

#include "metrics/accumulator.h"
#include "metrics/eval_records.h"
#include "metrics/person_error.h"

namespace rpt::engine {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Index in `gt` of each kept GT person (the accumulator's rule: at least one valid evaluated joint).
std::vector<int> KeptGt(const Poses3D& gt, const std::vector<int>& evaluated_idx, double min_gt_score) {
  std::vector<int> kept;
  for (int g = 0; g < gt.num_persons(); ++g) {
    if (metrics::ExtractPerson(gt, g, evaluated_idx, min_gt_score).valid.any()) kept.push_back(g);
  }
  return kept;
}

}  // namespace

RunOutcomes EvaluateFrameOutcomes(const std::vector<Sequence>& sequences,
                                  const std::vector<std::vector<Poses3D>>& predictions,
                                  const JointNames& prediction_joints, const metrics::EvalOptions& options) {
  metrics::MetricsAccumulator accumulator(options);
  struct FrameRange {
    size_t first_pair, end_pair;
    std::vector<int> kept_gt;
    bool counted;
  };
  std::vector<std::vector<FrameRange>> ranges(sequences.size());
  for (size_t s = 0; s < sequences.size(); ++s) {
    const Sequence& sequence = sequences[s];
    std::vector<int> evaluated_idx;
    for (const SequenceFrame& frame : sequence.frames) {
      const size_t f = ranges[s].size();
      FrameRange range;
      range.first_pair = accumulator.records().pairs.size();
      accumulator.Add(frame.id, frame.gt, sequence.gt_joints, predictions[s][f], prediction_joints);
      range.end_pair = accumulator.records().pairs.size();
      if (evaluated_idx.empty()) evaluated_idx = metrics::FindJointNames(accumulator.records().evaluated, sequence.gt_joints);
      range.kept_gt = KeptGt(frame.gt, evaluated_idx, options.min_gt_score);
      range.counted = !range.kept_gt.empty() || options.count_preds_without_gt;
      ranges[s].push_back(std::move(range));
    }
  }
  const metrics::EvalRecords& records = accumulator.records();
  const metrics::MatchSets matches = metrics::SelectMatches(records, options);

  RunOutcomes out;
  out.metrics = accumulator.Finalize();
  out.frames.resize(sequences.size());
  for (size_t s = 0; s < sequences.size(); ++s) {
    for (size_t f = 0; f < ranges[s].size(); ++f) {
      const FrameRange& range = ranges[s][f];
      const Poses3D& gt = sequences[s].frames[f].gt;
      const int num_pred = predictions[s][f].num_persons();
      FrameOutcome outcome;
      outcome.num_gt = static_cast<int>(range.kept_gt.size());
      outcome.gt_state.assign(gt.num_persons(), -1);
      for (const int g : range.kept_gt) outcome.gt_state[g] = 0;
      outcome.pred_invalid.assign(num_pred, range.counted);
      outcome.pred_error_mm.assign(num_pred, kInf);
      double sum = 0;
      int count = 0;
      for (size_t r = range.first_pair; r < range.end_pair; ++r) {
        const metrics::PairRecord& pair = records.pairs[r];
        if (pair.flags & metrics::kNearest) outcome.pred_error_mm[pair.pred_idx] = pair.match.error_mm;
        if (!matches.at_gate[r]) continue;
        outcome.pred_invalid[pair.pred_idx] = false;
        outcome.gt_state[range.kept_gt[pair.gt_idx]] = 1;
        ++outcome.num_matched;
        if (!std::isnan(pair.report_error_mm)) {
          sum += pair.report_error_mm;
          ++count;
        }
      }
      for (const bool invalid : outcome.pred_invalid) outcome.num_invalid += invalid ? 1 : 0;
      outcome.mpjpe_mm = count > 0 ? sum / count : kNaN;
      out.frames[s].push_back(std::move(outcome));
    }
  }

  // Recall against the distance threshold: the run's greedy matching redone at each threshold.
  if (options.matching == metrics::MatchingMode::kGreedy && records.num_gt > 0) {
    metrics::EvalOptions at_threshold = options;
    for (double t = 10; t <= 500; t += 10) {
      at_threshold.match_threshold_mm = t;
      const metrics::MatchSets m = metrics::SelectMatches(records, at_threshold);
      out.recall_threshold_mm.push_back(t);
      out.recall.push_back(100.0 * metrics::CountMatches(m.at_gate) / records.num_gt);
    }
  }
  return out;
}

}  // namespace rpt::engine
