// SPDX-License-Identifier: MIT
// MetricsAccumulator: feed frames one by one, then Finalize() into a MetricsResult.
//
// Inputs are Poses3D (metres, world frame, per-joint score; score 0 = missing) plus the joint names
// of the GT and of the predictions; joints are matched by NAME, so any prediction joint order works.
// Outputs are millimetres and percentages. Definitions: docs/metrics.md.
//
// Add() collects the frame's records (metrics/eval_records.h), resolves its matches and folds it
// into each metric family's running totals; Finalize() reduces the totals (metrics/reducers/, one
// file per family). Memory does not grow with frames, except for 8 bytes per frame (a hash of its
// id, to refuse a repeated one) and 24 bytes per counted prediction (average precision ranks all
// predictions of the run by score at the end).
//
// Example:
//   MetricsAccumulator accumulator(options);
//   for (each frame) accumulator.Add(frame_id, gt, gt_names, predictions, pred_names);
//   MetricsResult result = accumulator.Finalize();
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "metrics/eval_options.h"
#include "metrics/eval_records.h"
#include "metrics/frame_id_set.h"
#include "metrics/metrics_result.h"
#include "metrics/pcp.h"
#include "metrics/person_error.h"
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

class MetricsAccumulator {
 public:
  // Throws rpt::ConfigError with the problem of options.Check(), if any.
  explicit MetricsAccumulator(const EvalOptions& options = {});

  // Adds one frame. gt / predictions hold all persons of the frame (metres). `gt_names` and
  // `pred_names` name their joints (size == num_joints unless the Poses3D is empty).
  // `pred_scores` optionally gives one person score per prediction; when empty the score is the mean
  // joint score over the evaluated joints (missing joints count 0).
  // Throws rpt::ConfigError when an evaluated joint (or a joint required by the alignment or the
  // legacy PCP) is missing from a non-empty joint list, rpt::InputError on inconsistent sizes or a
  // repeated frame_id.
  void Add(std::string_view frame_id,
           const Poses3D& gt,
           const JointNames& gt_names,
           const Poses3D& predictions,
           const JointNames& pred_names,
           std::span<const double> pred_scores = {});

  // Adds the frames of `other` (e.g. another sequence evaluated on another thread): the result is
  // the one of adding its frames here after this one's, with the sums of the means (MPJPE, per-joint
  // and whole-body errors) added as one term each, so equal up to rounding (relative 1e-15).
  // Throws rpt::ConfigError when the options differ, rpt::InputError (and merges nothing) when a
  // frame id was added to both.
  void Merge(const MetricsAccumulator& other);

  // Computes all metrics from the frames added so far (can be called repeatedly).
  MetricsResult Finalize() const;

  // The records of the frame added last (its pairs with their errors and match flags, its kept GT
  // persons), e.g. to show each frame's matches; replaced by the next Add().
  const FrameRecords& LastFrame() const { return frame_; }

 private:
  // Joint index tables for one pair of joint lists (cached while the names do not change).
  struct Layout {
    JointNames gt_names, pred_names;
    std::vector<int> gt_eval, pred_eval;                   // evaluated joints
    std::vector<std::vector<int>> gt_group, pred_group;    // whole-body groups (joints in both lists)
    int gt_hip_left = -1, gt_hip_right = -1, pred_hip_left = -1, pred_hip_right = -1;
    std::vector<int> gt_legacy, pred_legacy;               // Shelf14 GT joints, COCO-17 prediction joints
  };

  void UpdateLayout(const JointNames& gt_names, const JointNames& pred_names);
  void CollectLegacyInputs(const Poses3D& gt, const Poses3D& predictions);
  PairRecord MakePair(const Poses3D& gt,
                      int gt_idx,
                      const EvalPerson& gt_person,
                      const Poses3D& predictions,
                      int pred_idx,
                      const EvalPerson& pred_person,
                      double error_mm,
                      double score) const;

  EvalOptions options_;
  JointNames evaluated_;
  GenericPcpLayout pcp_layout_;
  Layout layout_;
  bool layout_valid_ = false;
  std::vector<int> group_num_joints_;  // of the layout's joint lists; empty when one is empty
  std::vector<int> group_gt_only_joints_;  // per group: joints only the GT's list has (the same lists)
  FrameIdSet frame_ids_;

  FrameRecords frame_;   // the frame being (or last) added
  MetricTotals totals_;  // every frame so far, folded
};

}  // namespace rpt::metrics
