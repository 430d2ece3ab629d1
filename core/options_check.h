// SPDX-License-Identifier: MIT
// Check() of any options struct that follows core/option_spec.h: every number must be finite and
// inside the range its OptionSpec gives, every 3-vector finite. Problems read
// "section.key: problem", the one convention of every options check in the project.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/option_spec.h"

namespace rpt {

// The values an OptionSpec accepts: "[0, 1]", "(0, 1]", ">= 0", "> 0", "<= 3"; "" when any.
inline std::string DescribeRange(const OptionSpec& spec) {
  std::ostringstream s;
  s << std::setprecision(10);  // 1000000000, not 1e+09
  const bool has_min = std::isfinite(spec.min), has_max = std::isfinite(spec.max);
  if (has_min && has_max) {
    s << (spec.min_exclusive ? "(" : "[") << spec.min << ", " << spec.max << "]";
  } else if (has_min) {
    s << (spec.min_exclusive ? "> " : ">= ") << spec.min;
  } else if (has_max) {
    s << "<= " << spec.max;
  }
  return s.str();
}

// The problem with one value ("" when it is fine).
template <class T>
std::string CheckOptionValue(const T& value, const OptionSpec& spec) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    const double x = static_cast<double>(value);
    const bool below = spec.min_exclusive ? !(x > spec.min) : !(x >= spec.min);
    if (!std::isfinite(x) || below || x > spec.max) {
      std::ostringstream s;
      s << std::setprecision(10);
      const bool two_sided = std::isfinite(spec.min) && std::isfinite(spec.max);
      s << x << (two_sided ? " is outside " : " must be ") << DescribeRange(spec);
      return s.str();
    }
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    if (!value.allFinite()) return "must be finite";
  }
  return {};
}

// A visitor for VisitFields that keeps the first problem, as "section.key: problem".
class OptionsChecker {
 public:
  explicit OptionsChecker(std::string_view section) : section_(section) {}

  template <class T>
  void operator()(std::string_view key, const T& value, const OptionSpec& spec) {
    if (error_.empty()) Require(CheckOptionValue(value, spec), key);
  }
  // For the checks between fields: records `problem` (unless empty) for `key`.
  void Require(const std::string& problem, std::string_view key) {
    if (error_.empty() && !problem.empty()) error_ = section_ + "." + std::string(key) + ": " + problem;
  }
  const std::string& error() const { return error_; }

 private:
  std::string section_;
  std::string error_;
};

// The first problem of `options` (section name `section`), "" when valid.
template <class Options>
std::string CheckOptionRanges(std::string_view section, const Options& options) {
  OptionsChecker checker(section);
  VisitFields(checker, options);
  return checker.error();
}

}  // namespace rpt
