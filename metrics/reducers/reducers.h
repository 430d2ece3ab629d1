// SPDX-License-Identifier: MIT
// The metric families. Each frame's records (metrics/eval_records.h) are folded into the running
// totals of every family as the frame is added; Finalize() reduces the totals to MetricsResult, one
// Reduce<Family>() per family that fills its own fields. One file per family in metrics/reducers/
// holds its totals' Fold() and Merge() and its Reduce function.
//
// The folds visit a frame's pairs in order and add into the running sums directly, so every sum
// adds the same terms in the same order as one pass over all pairs of the run would. Merge() adds
// another run's totals (its sums as one term each: equal to adding its frames up to rounding).
//
// To add a metric: its field in MetricsResult; its totals below (when it needs some), with Fold()
// and Merge(), as a member of MetricTotals (and in MetricTotals' Fold / Merge, reducers.cc);
// Reduce<Metric>() in a new file here, declared below and listed in MetricReducers(); the file in
// metrics/CMakeLists.txt.
#pragma once

#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "core/nan.h"
#include "metrics/eval_options.h"
#include "metrics/eval_records.h"
#include "metrics/metrics_result.h"
#include "metrics/pcp.h"

namespace rpt::metrics {

// counts.cc: frames, GT persons, predictions, matches at the gate, GT-valid joints.
struct CountTotals {
  int num_frames = 0;
  int num_frames_with_gt = 0;
  int num_gt = 0;            // kept GT persons
  int num_dropped_gt = 0;    // GT persons without a valid evaluated joint
  int num_pred_counted = 0;  // predictions counted for Invalid / AP
  int num_pred_total = 0;
  int num_matches = 0;                  // kMatch pairs
  std::vector<int> gt_valid_per_joint;  // GT-valid count per evaluated joint over all kept GT
  void Fold(const FrameRecords& frame);
  void Merge(const CountTotals& other);
};

// invalid.cc: the counted predictions that are not matches, by cause (InvalidCauses).
struct InvalidTotals {
  double gate_mm = 0;  // match_threshold_mm
  InvalidCauses causes;
  void Fold(const FrameRecords& frame);
  void Merge(const InvalidTotals& other);
};

// recall.cc: matches at 100 and 500 mm.
struct RecallTotals {
  int num_matches_100 = 0;
  int num_matches_500 = 0;
  void Fold(const FrameRecords& frame);
  void Merge(const RecallTotals& other);
};

// mpjpe.cc: the reported MPJPE of the matches.
struct MpjpeTotals {
  double sum_mm = 0.0;
  int count = 0;
  int num_unaligned = 0;  // matches without a pelvis to align
  void Fold(const FrameRecords& frame);
  void Merge(const MpjpeTotals& other);
};

// pck.cc: GT-valid joints of the matches.
struct PckTotals {
  int hits_100 = 0;
  int hits_500 = 0;
  int matched_valid = 0;
  int missing = 0;  // not predicted
  void Fold(const FrameRecords& frame);
  void Merge(const PckTotals& other);
};

// per_joint.cc: per evaluated joint, over the matches.
struct PerJointTotals {
  std::vector<double> error_sum_mm;  // reported errors
  std::vector<int> error_count, hits_100, matched_gt;
  void Fold(const FrameRecords& frame);
  void Merge(const PerJointTotals& other);
};

// ap.cc: one entry per counted prediction (its nearest-GT pair), in the order added. AP ranks them
// all by score at the end; whether an entry is a true positive at a threshold is decided in its
// frame (greedy matching, as for the matches).
struct ApTotals {
  struct Entry {
    double score;
    double error_mm;
    std::uint8_t is_tp;  // bit k: true positive at kApThresholdsMm[k]
  };
  std::deque<Entry> entries;  // grows in blocks, without a vector's doubling
  void Fold(const FrameRecords& frame);
  void Merge(const ApTotals& other);
};

// pcp.cc: generic PCP part counts.
struct PcpTotals {
  std::vector<int> total;            // evaluable parts over all kept GT
  std::vector<int> correct_nearest;  // correct against each GT's nearest prediction
  std::vector<int> correct_matched;  // correct in the matches
  void Fold(const FrameRecords& frame);
  void Merge(const PcpTotals& other);
};

// legacy_pcp.cc: the legacy Shelf/Campus PCP counts, when legacy_pcp != kNone.
struct LegacyPcpTotals {
  std::optional<LegacyPcpEvaluator> evaluator;
  void Fold(const FrameRecords& frame);
  void Merge(const LegacyPcpTotals& other);
};

// wholebody.cc: per whole-body group, over the matches.
struct WholeBodyTotals {
  std::vector<double> sum_mm;  // of the pairs' group means
  std::vector<int> count;
  std::vector<long> joints, filled;   // the joints measured, and of those filled (not triangulated)
  std::vector<int> group_num_joints;  // of the last frame that gave both joint lists; empty before
  std::vector<int> group_gt_only_joints;  // the same frame's joints only the GT has
  void Fold(const FrameRecords& frame);
  void Merge(const WholeBodyTotals& other);
};

// The running totals of every family.
struct MetricTotals {
  explicit MetricTotals(const EvalOptions& options);  // sizes the per-joint, per-part and per-group totals
  CountTotals counts;
  RecallTotals recall;
  InvalidTotals invalid;
  MpjpeTotals mpjpe;
  PckTotals pck;
  PerJointTotals per_joint;
  ApTotals ap;
  PcpTotals pcp;
  LegacyPcpTotals legacy_pcp;
  WholeBodyTotals wholebody;
  void Fold(const FrameRecords& frame);   // every family
  void Merge(const MetricTotals& other);  // every family
};

using MetricReducer = void (*)(const MetricTotals& totals, const EvalOptions& options, MetricsResult* result);

void ReduceCounts(const MetricTotals&, const EvalOptions&, MetricsResult*);     // num_*
void ReduceRecall(const MetricTotals&, const EvalOptions&, MetricsResult*);     // recall_100/500
void ReduceInvalid(const MetricTotals&, const EvalOptions&, MetricsResult*);    // invalid, invalid_causes
void ReduceF1(const MetricTotals&, const EvalOptions&, MetricsResult*);         // f1
void ReduceMpjpe(const MetricTotals&, const EvalOptions&, MetricsResult*);      // mpjpe_mm
void ReducePck(const MetricTotals&, const EvalOptions&, MetricsResult*);        // pck_100/500
void ReducePerJoint(const MetricTotals&, const EvalOptions&, MetricsResult*);   // joints
void ReduceAp(const MetricTotals&, const EvalOptions&, MetricsResult*);         // ap
void ReducePcp(const MetricTotals&, const EvalOptions&, MetricsResult*);        // pcp, pcp_parts
void ReduceLegacyPcp(const MetricTotals&, const EvalOptions&, MetricsResult*);  // legacy_pcp
void ReduceWholeBody(const MetricTotals&, const EvalOptions&, MetricsResult*);  // wholebody

// Every reducer, in the order Finalize() runs them (each writes its own fields only).
std::span<const MetricReducer> MetricReducers();

// 100 * numerator / denominator, NaN when the denominator is zero.
inline double Percent(double numerator, double denominator) {
  return denominator > 0 ? 100.0 * numerator / denominator : kNaN;
}

}  // namespace rpt::metrics
