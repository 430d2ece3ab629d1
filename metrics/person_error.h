// SPDX-License-Identifier: MIT
// Per-person errors between one GT person and one prediction, on a set of joints mapped by name.
//
// Conventions: inputs (Poses3D) are metres; everything here is millimetres. A GT joint is valid iff
// its score > min_gt_score (0.1); a predicted joint is present iff its score > min_pred_score (0).
// Error of joint j: e_j = ||P_j - G_j||_2 (mm). A GT-invalid joint has no error (NaN); a GT-valid
// joint whose prediction is missing has e_j = +inf (wrong for PCK/PCP, excluded from MPJPE).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"

namespace rpt::metrics {

// Index in `available` of every name of `wanted` (same order).
// Throws rpt::ConfigError naming the first missing joint and `what` ("ground-truth", "prediction").
std::vector<int> MapJointNames(const JointNames& wanted, const JointNames& available, std::string_view what);

// Index in `available` of every name of `wanted`, -1 where absent (never throws).
std::vector<int> FindJointNames(const JointNames& wanted, const JointNames& available);

// One person restricted to a joint subset, in mm. Invariant: xyz_mm.cols() == valid.size().
struct EvalPerson {
  Eigen::Matrix3Xd xyz_mm;                      // one column per selected joint; meaningless where !valid
  Eigen::Array<bool, Eigen::Dynamic, 1> valid;  // GT: visible (score > min); prediction: present
  double mean_score = 0.0;                      // mean joint score over the selected joints (missing = 0)
};

// Selects the joints `joint_idx` (indices into poses' joint list; -1 = absent, i.e. invalid) of
// person `person_idx`, converts metres -> mm and marks joints with score > min_score as valid.
EvalPerson ExtractPerson(const Poses3D& poses, int person_idx, std::span<const int> joint_idx, double min_score);

// e_j for every selected joint (mm): NaN where the GT joint is invalid, +inf where the GT joint is
// valid but the predicted one is missing. `pred_offset_mm` is subtracted from the prediction first
// and `gt_offset_mm` from the GT (used for pelvis alignment; zero = absolute error).
Eigen::ArrayXd JointErrors(const EvalPerson& gt,
                           const EvalPerson& pred,
                           const Eigen::Vector3d& gt_offset_mm = Eigen::Vector3d::Zero(),
                           const Eigen::Vector3d& pred_offset_mm = Eigen::Vector3d::Zero());

// Mean of the finite entries of `joint_errors` (GT-valid and predicted), or +inf if there is none.
// This is MPJPE(p, g) of metrics.md 3 (absolute when the errors are absolute).
double MeanFiniteError(const Eigen::ArrayXd& joint_errors);

// MPJPE(p, g) in mm over GT-valid, predicted joints; +inf when they share no such joint.
double PersonMpjpe(const EvalPerson& gt, const EvalPerson& pred);

// Pelvis (mean of the two hip joints) in mm, or nullopt when either hip is absent (-1) or has
// score <= min_score.
std::optional<Eigen::Vector3d> PelvisMm(const Poses3D& poses,
                                        int person_idx,
                                        int hip_left_idx,
                                        int hip_right_idx,
                                        double min_score);

}  // namespace rpt::metrics
