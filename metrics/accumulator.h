// SPDX-License-Identifier: MIT
// MetricsAccumulator: feed frames one by one, then Finalize() into a MetricsResult.
//
// Inputs are Poses3D (metres, world frame, per-joint score; score 0 = missing) plus the joint names
// of the GT and of the predictions; joints are matched by NAME, so any prediction joint order works.
// Outputs are millimetres and percentages. Definitions: docs/metrics.md.
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
#include <unordered_set>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "metrics/eval_options.h"
#include "metrics/matching.h"
#include "metrics/pcp.h"
#include "metrics/person_error.h"

namespace rpt::metrics {

// AP thresholds (mm), VoxelPose Panoptic protocol.
inline constexpr std::array<double, 6> kApThresholdsMm = {25, 50, 75, 100, 125, 150};

// Whole-body groups (H3WB, COCO-WholeBody indices): All 0-132, Body 0-22, Face 23-90, Hands 91-132.
struct WholeBodyGroup {
  std::string name;
  int first_index;  // into CocoWholeBodyJoints()
  int last_index;   // inclusive
};
const std::vector<WholeBodyGroup>& WholeBodyGroups();

// Per evaluated joint, over the matched pairs.
struct JointResult {
  std::string name;
  double mean_error_mm = 0.0;  // mean over matched pairs with the joint GT-valid and predicted (aligned if set)
  double pck_100 = 0.0;        // percent; denominator follows EvalOptions::pck_denominator
  int count = 0;               // number of errors averaged in mean_error_mm
  int num_gt = 0;              // PCK denominator for this joint
};

// Whole-body MPJPE of one group, over the matched pairs (matching uses the evaluated body joints).
struct GroupResult {
  std::string name;
  double mpjpe_mm = 0.0;  // mean of per-person means over the group's GT-valid, predicted joints
  int num_persons = 0;    // matched pairs with at least one such joint
  int num_joints = 0;     // joints of the group present in both joint lists (last frame added)
};

struct PcpPartResult {
  std::string name;
  int correct = 0;
  int total = 0;       // evaluable (GT endpoints valid) parts over all GT persons
  double pcp = 0.0;    // percent
};

// All values are percentages except *_mm and the counts. A ratio with a zero denominator is NaN.
struct MetricsResult {
  double pcp = 0.0;        // generic 13-joint PCP (all GT persons)
  double pck_100 = 0.0;    // joint-level, strict <
  double pck_500 = 0.0;
  double mpjpe_mm = 0.0;   // mean over matched pairs of the per-person MPJPE
  double recall_100 = 0.0; // person-level: matched with MPJPE < 100 mm, over all GT persons
  double recall_500 = 0.0;
  double invalid = 0.0;    // predictions that are not matches, over counted predictions
  double f1 = 0.0;         // 2 TP / (2 TP + FP + FN) = harmonic mean of (100 - invalid) and recall at the gate
  std::array<double, kApThresholdsMm.size()> ap{};  // AP at kApThresholdsMm

  int num_frames = 0;               // frames added
  int num_frames_with_gt = 0;       // frames with at least one kept GT person
  int num_gt_persons = 0;           // kept GT persons (at least one valid evaluated joint)
  int num_dropped_gt_persons = 0;   // GT persons without any valid evaluated joint
  int num_predictions = 0;          // predictions counted (Invalid / AP denominator)
  int num_predictions_total = 0;    // all predictions added, including uncounted ones
  int num_matches = 0;              // TP pairs at match_threshold_mm
  int num_missing_pred_joints = 0;  // GT-valid joints of matched pairs that the prediction lacks
  int num_unaligned_matches = 0;    // matched pairs left out of aligned MPJPE (pelvis unavailable)

  std::vector<JointResult> joints;       // evaluated joints, in EvalOptions order
  std::vector<PcpPartResult> pcp_parts;  // GenericPcpParts() order
  std::vector<GroupResult> wholebody;    // WholeBodyGroups() order; empty when disabled
  std::optional<LegacyPcpResult> legacy_pcp;  // when legacy_pcp != kNone
};

class MetricsAccumulator {
 public:
  // Throws rpt::ConfigError when options.Check() fails.
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

  // Computes all metrics from the frames added so far (can be called repeatedly).
  MetricsResult Finalize() const;

 private:
  // Flags of a pair record.
  enum : std::uint8_t {
    kNearest = 1,         // the prediction's nearest GT (greedy matching, AP)
    kHungarianMatch = 2,  // Hungarian pair at match_threshold_mm
    kHungarian100 = 4,    // Hungarian pair at 100 mm
    kHungarian500 = 8,    // Hungarian pair at 500 mm
  };
  // One candidate (prediction, GT) pair, with everything Finalize() needs about it.
  struct PairRecord {
    MatchRecord match;                 // gt_id, error (absolute MPJPE), score
    std::uint8_t flags = 0;
    int pred_idx = -1;                 // prediction index within its frame
    int gt_idx = -1;                   // kept-GT index within its frame (-1 = none)
    bool counted = true;               // prediction counts for Invalid / AP
    double report_error_mm = 0.0;      // MPJPE used for reporting (aligned if set; NaN = unaligned)
    Eigen::ArrayXd joint_errors;       // absolute, evaluated joints (NaN GT-invalid, +inf missing)
    Eigen::ArrayXd report_joint_errors;  // aligned if set
    std::vector<double> group_errors;  // per whole-body group mean (NaN = no joint)
    std::vector<PartOutcome> pcp;      // generic PCP outcomes of this pair
  };
  // Joint index tables for one pair of joint lists (cached while the names do not change).
  struct Layout {
    JointNames gt_names, pred_names;
    std::vector<int> gt_eval, pred_eval;                   // evaluated joints
    std::vector<std::vector<int>> gt_group, pred_group;    // whole-body groups (joints in both lists)
    int gt_hip_left = -1, gt_hip_right = -1, pred_hip_left = -1, pred_hip_right = -1;
    std::vector<int> gt_legacy, pred_legacy;               // Shelf14 GT joints, COCO-17 prediction joints
  };

  void UpdateLayout(const JointNames& gt_names, const JointNames& pred_names);
  void AddLegacyFrame(const Poses3D& gt, const Poses3D& predictions);
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
  std::optional<LegacyPcpEvaluator> legacy_;
  std::unordered_set<std::string> frame_ids_;

  std::vector<PairRecord> records_;
  int num_frames_ = 0;
  int num_frames_with_gt_ = 0;
  int num_gt_ = 0;
  int num_dropped_gt_ = 0;
  int num_pred_counted_ = 0;
  int num_pred_total_ = 0;
  std::vector<int> gt_valid_per_joint_;     // GT-valid count per evaluated joint over all kept GT
  std::vector<int> pcp_total_;              // evaluable parts over all kept GT
  std::vector<int> pcp_correct_nearest_;    // correct parts against the nearest prediction
  std::vector<int> group_num_joints_;       // joints of each group present in both lists
};

}  // namespace rpt::metrics
