// SPDX-License-Identifier: MIT
// The one Check() convention of every options struct of the project (triangulator, metrics,
// dataset parameters, synthetic scene and rig):
//
//   std::string Check() const;  // "" when valid, else "section.key: problem" for the first problem
//
// A struct with a VisitFields starts its Check() with CheckOptionRanges (every number finite and
// inside its OptionSpec range, every 3-vector finite, in the words of core/option_codec.h:
// "filter.min_match_score: '1.5' is not a number in [0, 1]"), then adds the checks between fields
// with OptionsChecker::Require. Callers that cannot go on with invalid options throw with
// ThrowIfInvalid (a ConfigError, exit code 2).
#pragma once

#include <string>
#include <string_view>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/option_spec.h"

namespace rpt {

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

// The first range problem of `options` (section name `section`), "" when valid.
template <class Options>
std::string CheckOptionRanges(std::string_view section, const Options& options) {
  OptionsChecker checker(section);
  VisitFields(checker, options);
  return checker.error();
}

// Throws ConfigError with the problem of options.Check(), if any.
template <class Options>
void ThrowIfInvalid(const Options& options) {
  if (const std::string problem = options.Check(); !problem.empty()) throw ConfigError(problem);
}

}  // namespace rpt
