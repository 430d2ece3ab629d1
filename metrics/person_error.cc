// SPDX-License-Identifier: MIT
#include "metrics/person_error.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"

namespace rpt::metrics {

std::vector<int> MapJointNames(const JointNames& wanted, const JointNames& available, std::string_view what) {
  std::vector<int> indices = FindJointNames(wanted, available);
  for (size_t i = 0; i < wanted.size(); ++i) {
    if (indices[i] < 0) {
      std::string names;
      for (size_t a = 0; a < available.size() && a < 20; ++a) names += (a ? ", " : "") + available[a];
      if (available.size() > 20) names += ", ... (" + std::to_string(available.size()) + " joints)";
      throw ConfigError("metrics: evaluated joint '" + wanted[i] + "' is not among the " + std::string(what) +
                        " joints (" + names + "); choose the joints with --set metrics.evaluated_joints=NAME,NAME,... "
                        "(labels written by rpt convert do not carry a dataset's own choice)");
    }
  }
  return indices;
}

std::vector<int> FindJointNames(const JointNames& wanted, const JointNames& available) {
  std::vector<int> indices(wanted.size(), -1);
  for (size_t i = 0; i < wanted.size(); ++i) indices[i] = FindJoint(available, wanted[i]);
  return indices;
}

EvalPerson ExtractPerson(const Poses3D& poses, int person_idx, std::span<const int> joint_idx, double min_score) {
  const auto joints = poses.Person(person_idx);
  const int n = static_cast<int>(joint_idx.size());
  EvalPerson person;
  person.xyz_mm.setZero(3, n);
  person.valid.setConstant(n, false);
  double score_sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const int j = joint_idx[k];
    if (j < 0) continue;
    const double score = joints(3, j);
    score_sum += score;
    person.valid(k) = score > min_score;
    person.xyz_mm.col(k) = 1000.0 * joints.col(j).head<3>();
  }
  person.mean_score = n > 0 ? score_sum / n : 0.0;
  return person;
}

Eigen::ArrayXd JointErrors(const EvalPerson& gt,
                           const EvalPerson& pred,
                           const Eigen::Vector3d& gt_offset_mm,
                           const Eigen::Vector3d& pred_offset_mm) {
  const Eigen::Index n = gt.xyz_mm.cols();
  Eigen::ArrayXd errors(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!gt.valid(j)) {
      errors(j) = std::numeric_limits<double>::quiet_NaN();
    } else if (!pred.valid(j)) {
      errors(j) = std::numeric_limits<double>::infinity();
    } else {
      errors(j) = ((pred.xyz_mm.col(j) - pred_offset_mm) - (gt.xyz_mm.col(j) - gt_offset_mm)).norm();
    }
  }
  return errors;
}

double MeanFiniteError(const Eigen::ArrayXd& joint_errors) {
  double sum = 0.0;
  int count = 0;
  for (const double e : joint_errors) {
    if (std::isfinite(e)) {
      sum += e;
      ++count;
    }
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::infinity();
}

double PersonMpjpe(const EvalPerson& gt, const EvalPerson& pred) { return MeanFiniteError(JointErrors(gt, pred)); }

std::optional<Eigen::Vector3d> PelvisMm(const Poses3D& poses,
                                        int person_idx,
                                        int hip_left_idx,
                                        int hip_right_idx,
                                        double min_score) {
  if (hip_left_idx < 0 || hip_right_idx < 0) return std::nullopt;
  const auto joints = poses.Person(person_idx);
  if (joints(3, hip_left_idx) <= min_score || joints(3, hip_right_idx) <= min_score) return std::nullopt;
  return Eigen::Vector3d(500.0 * (joints.col(hip_left_idx).head<3>() + joints.col(hip_right_idx).head<3>()));
}

}  // namespace rpt::metrics
