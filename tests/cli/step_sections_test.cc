// SPDX-License-Identifier: MIT
// The options sections of `rpt config --dump` and the step table (core/pipeline/steps.h) agree:
// every step's section is in the dump, and every section of the dump belongs to a step (or is
// listed below as not being a pipeline step's).
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "core/pipeline/steps.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

TEST(StepSections, ConfigDumpSectionsAreTheStepTablesSections) {
  const test::CommandResult r = test::RunRpt("config --dump");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::set<std::string> not_steps = {"metrics"};  // options outside the triangulator
  const std::regex top_level(R"re(^  "([a-z_]+)": \{)re");
  std::set<std::string> dumped;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, top_level)) dumped.insert(m[1]);
  }
  ASSERT_GE(dumped.size(), 10u) << "cannot find the sections in:\n" << r.out;
  std::set<std::string> from_table;
  for (const StepInfo& step : kAllSteps) {
    if (!step.section.empty()) from_table.insert(std::string(step.section));
  }
  for (const std::string& section : from_table) {
    EXPECT_TRUE(dumped.count(section)) << "step section '" << section << "' is missing from rpt config --dump";
  }
  for (const std::string& section : dumped) {
    EXPECT_TRUE(from_table.count(section) || not_steps.count(section))
        << "rpt config --dump section '" << section << "' belongs to no step of core/pipeline/steps.h";
  }
}

}  // namespace
}  // namespace rpt
