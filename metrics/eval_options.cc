// SPDX-License-Identifier: MIT
#include "metrics/eval_options.h"

#include <cmath>
#include <set>
#include <string>

#include "core/errors.h"

namespace rpt::metrics {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw ConfigError("metrics options: " + message);
}

}  // namespace

const JointNames& EvalOptions::EvaluatedJoints() const {
  return evaluated_joints.empty() ? EvaluationJoints13() : evaluated_joints;
}

void EvalOptions::Check() const {
  std::set<std::string> seen;
  for (const std::string& name : evaluated_joints) {
    Require(!name.empty(), "evaluated_joints contains an empty name");
    Require(seen.insert(name).second, "evaluated_joints lists '" + name + "' twice");
  }
  Require(std::isfinite(min_gt_score) && min_gt_score >= 0.0, "min_gt_score must be finite and >= 0");
  Require(std::isfinite(min_pred_score) && min_pred_score >= 0.0, "min_pred_score must be finite and >= 0");
  Require(match_threshold_mm > 0.0, "match_threshold_mm must be > 0");
  Require(std::isfinite(pcp_alpha) && pcp_alpha > 0.0, "pcp_alpha must be finite and > 0");
  Require(std::isfinite(legacy_pcp.alpha) && legacy_pcp.alpha > 0.0, "legacy_pcp.alpha must be finite and > 0");
  Require(legacy_pcp.num_averaged_actors >= 1, "legacy_pcp.num_averaged_actors must be >= 1");
  Require(legacy_pcp.gt_joints.empty() || legacy_pcp.gt_joints.size() == 14,
          "legacy_pcp.gt_joints must list 14 names (Shelf14 order) or be empty");
}

}  // namespace rpt::metrics
