// SPDX-License-Identifier: MIT
#include "metrics/eval_options.h"

#include <set>
#include <string>

#include "core/options_check.h"

namespace rpt::metrics {

const JointNames& EvalOptions::EvaluatedJoints() const {
  return evaluated_joints.empty() ? EvaluationJoints13() : evaluated_joints;
}

std::string EvalOptions::Check() const {
  OptionsChecker checker("metrics");
  VisitFields(checker, *this);
  std::set<std::string> seen;
  for (const std::string& name : evaluated_joints) {
    if (name.empty()) checker.Require("contains an empty name", "evaluated_joints");
    if (!seen.insert(name).second) checker.Require("lists '" + name + "' twice", "evaluated_joints");
  }
  if (!legacy_pcp_gt_joints.empty() && legacy_pcp_gt_joints.size() != 14) {
    checker.Require("must list 14 names (Shelf14 order) or be empty, got " +
                        std::to_string(legacy_pcp_gt_joints.size()),
                    "legacy_pcp_gt_joints");
  }
  return checker.error();
}

}  // namespace rpt::metrics
