// SPDX-License-Identifier: MIT
// MetricsResult: every metric of an evaluation (percentages, millimetres and counts), the output of
// MetricsAccumulator::Finalize(). Definitions: docs/metrics.md.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "metrics/pcp.h"

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
  int num_gt_only_joints = 0;  // joints of the group only the GT's list has (the same frame): not measured
  double filled_share = 0.0;  // of the joints measured, the share filled from a neighbour (not triangulated)
};

struct PcpPartResult {
  std::string name;
  int correct = 0;
  int total = 0;       // evaluable (GT endpoints valid) parts over all GT persons
  double pcp = 0.0;    // percent
};

// Why the counted predictions that are not matches (Invalid's numerator) are not, by their nearest
// GT person (MPJPE) and the gate G = match_threshold_mm; the five counts sum to the false positives.
struct InvalidCauses {
  int duplicate = 0;        // nearest GT within G, but matched to another prediction (a second copy)
  int near_matched_gt = 0;  // nearest GT at G to 2G and matched to another prediction: a ghost beside a found person
  int near_missed_gt = 0;   // nearest GT at G to 2G and matched to none: that person placed off, or mixed
  int far_from_gt = 0;      // nearest GT at 2G or farther: a phantom, or a person the GT does not label
  int no_gt = 0;            // no GT person to compare with (a frame without GT, or no joint in common)
  int Total() const { return duplicate + near_matched_gt + near_missed_gt + far_from_gt + no_gt; }
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
  InvalidCauses invalid_causes;     // the counted predictions that are not matches, by cause

  std::vector<JointResult> joints;       // evaluated joints, in EvalOptions order
  std::vector<PcpPartResult> pcp_parts;  // GenericPcpParts() order
  std::vector<GroupResult> wholebody;    // WholeBodyGroups() order; empty when disabled
  std::optional<LegacyPcpResult> legacy_pcp;  // when legacy_pcp != kNone
};

}  // namespace rpt::metrics
