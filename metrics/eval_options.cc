// SPDX-License-Identifier: MIT
#include "metrics/eval_options.h"

#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

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

std::string FirstDifferentOption(const EvalOptions& a, const EvalOptions& b) {
  // VisitFields visits both in the same order: remember a's fields, compare b's to them.
  std::vector<const void*> fields_of_a;
  auto collect = [&](std::string_view, const auto& value, const OptionSpec&) { fields_of_a.push_back(&value); };
  VisitFields(collect, a);
  size_t i = 0;
  std::string first;
  auto compare = [&](std::string_view key, const auto& value, const OptionSpec&) {
    const auto& value_of_a = *static_cast<const std::remove_cvref_t<decltype(value)>*>(fields_of_a[i++]);
    if (first.empty() && !(value_of_a == value)) first = key;
  };
  VisitFields(compare, b);
  return first;
}

}  // namespace rpt::metrics
