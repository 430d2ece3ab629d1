// SPDX-License-Identifier: MIT
// The step table (core/pipeline/steps.h) is the one list of pipeline steps: these tests fail when
// docs/algorithm.md (its step table and its "## N. Title" headings), the source tree or the
// binding of each step to its function and options section (core/pipeline/step_functions.h,
// whose static_asserts check the rest when it compiles) disagree with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/step_functions.h"
#include "core/pipeline/steps.h"

namespace rpt {
namespace {

const std::filesystem::path kSourceDir = RPT_SOURCE_DIR;

std::vector<std::string> ReadLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// "`text`" -> "text"; "–" and "" stay as they are.
std::string Unquote(std::string cell) {
  if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`') cell = cell.substr(1, cell.size() - 2);
  return cell;
}

std::vector<std::string> Cells(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream in(row.substr(1));  // after the leading '|'
  for (std::string cell; std::getline(in, cell, '|');) {
    const size_t begin = cell.find_first_not_of(' ');
    const size_t end = cell.find_last_not_of(' ');
    cells.push_back(begin == std::string::npos ? "" : cell.substr(begin, end - begin + 1));
  }
  return cells;
}

// The rows of the table under "## The steps".
std::vector<std::vector<std::string>> DocsStepRows(const std::vector<std::string>& lines) {
  std::vector<std::vector<std::string>> rows;
  bool in_section = false;
  for (const std::string& line : lines) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## The steps";
    if (!in_section || line.rfind("| ", 0) != 0 || line.rfind("| # ", 0) == 0) continue;
    rows.push_back(Cells(line));
  }
  return rows;
}

TEST(StepTable, KeysAreUniqueAndFilesAreNamedAfterThem) {
  std::set<std::string_view> keys;
  for (const StepInfo& step : kAllSteps) {
    EXPECT_TRUE(keys.insert(step.key).second) << "duplicate step key " << step.key;
    EXPECT_EQ(step.file, "core/pipeline/" + std::string(step.key) + ".cc") << "file stem = step key";
    EXPECT_FALSE(step.title.empty()) << step.key;
  }
  for (int s = 0; s < kNumSteps; ++s) EXPECT_FALSE(kSteps[s].item.empty()) << kSteps[s].key << ": counted item";
}

TEST(StepTable, EveryStepsSourceFileExists) {
  for (const StepInfo& step : kAllSteps) {
    const std::filesystem::path file = kSourceDir / std::string(step.file);
    EXPECT_TRUE(std::filesystem::exists(file)) << file;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(file).replace_extension(".h"))) << file;
  }
}

TEST(StepTable, DocsStepTableAgrees) {
  const std::vector<std::vector<std::string>> rows = DocsStepRows(ReadLines(kSourceDir / "docs/algorithm.md"));
  ASSERT_EQ(rows.size(), kAllSteps.size()) << "docs/algorithm.md, section 'The steps': one row per step";
  for (size_t i = 0; i < rows.size(); ++i) {
    const StepInfo& step = kAllSteps[i];
    const std::vector<std::string>& row = rows[i];
    ASSERT_GE(row.size(), 6u) << "docs/algorithm.md, step table row " << i + 1;
    EXPECT_EQ(row[0], step.number) << "row " << i + 1 << " (" << step.key << "): paper step number";
    EXPECT_EQ(Unquote(row[1]), step.key) << "row " << i + 1 << ": step key";
    EXPECT_EQ(Unquote(row[2]), step.section.empty() ? "–" : step.section) << step.key << ": options section";
    EXPECT_EQ(Unquote(row[3]), step.file) << step.key << ": file";
    EXPECT_EQ(row[5], step.item) << step.key << ": counted item";
  }
}

TEST(StepTable, DocsHeadingsAgree) {
  // "## 6-7. Reprojection and scoring", "### 15. Bone lengths", "## 11a. ...", "## Undistortion".
  const std::regex numbered(R"(^#{2,3} ([0-9]+(?:-[0-9]+)?[ab]?)\. (.+)$)");
  std::map<std::string, std::string> title_of;  // number -> title
  std::set<std::string> plain;                   // unnumbered heading titles
  for (const std::string& line : ReadLines(kSourceDir / "docs/algorithm.md")) {
    std::smatch m;
    if (std::regex_match(line, m, numbered)) {
      EXPECT_TRUE(title_of.emplace(m[1], m[2]).second) << "two headings for step " << m[1];
    } else if (line.rfind("## ", 0) == 0 || line.rfind("### ", 0) == 0) {
      plain.insert(line.substr(line.find(' ') + 1));
    }
  }
  std::set<std::string> numbers;
  for (const StepInfo& step : kAllSteps) {
    if (step.number == "–") {
      if (step.key == "remember") continue;  // bookkeeping, described in "The steps"
      EXPECT_TRUE(plain.count(std::string(step.title))) << "docs/algorithm.md: no heading '## " << step.title << "'";
      continue;
    }
    numbers.insert(std::string(step.number));
    const auto it = title_of.find(std::string(step.number));
    ASSERT_NE(it, title_of.end()) << "docs/algorithm.md: no heading '## " << step.number << ". " << step.title << "'";
    EXPECT_EQ(it->second, step.title) << "docs/algorithm.md: heading of step " << step.number;
  }
  for (const auto& [number, title] : title_of) {
    EXPECT_TRUE(numbers.count(number)) << "docs/algorithm.md: heading '" << number << ". " << title
                                       << "' names no step of core/pipeline/steps.h";
  }
}

// Step S's binding: VisitSections names its options member like the step table's section, its
// file defines its function (and its header declares it), and the Triangulator runs it through
// the binding only.
template <Step S>
void CheckBinding(const std::string& triangulator_source) {
  using Binding = StepBinding<S>;
  const StepInfo& info = Info(S);
  SCOPED_TRACE(std::string(info.key));
  if constexpr (std::is_null_pointer_v<std::remove_cv_t<decltype(Binding::options)>>) {
    EXPECT_TRUE(info.section.empty());
  } else {
    const TriangulatorOptions options;
    const void* bound = &(options.*Binding::options);
    std::string visited;
    auto visitor = [&](const char* name, const auto& section) {
      if (static_cast<const void*>(&section) == bound) visited = name;
    };
    VisitSections(visitor, options);
    EXPECT_EQ(visited, info.section) << "VisitSections' name of TriangulatorOptions::" << Binding::options_name;
  }
  const std::string function(Binding::function_name);
  const std::filesystem::path file = kSourceDir / std::string(info.file);
  EXPECT_NE(ReadFile(file).find("int steps::" + function + "("), std::string::npos)
      << info.file << " must define steps::" << function;
  EXPECT_NE(ReadFile(std::filesystem::path(file).replace_extension(".h")).find("int " + function + "("),
            std::string::npos)
      << "its header must declare steps::" << function;
  EXPECT_NE(triangulator_source.find("<Step::k" + function + ">("), std::string::npos)
      << "Triangulator::Process runs the step through its binding (Run<Step::k" << function << ">)";
  EXPECT_EQ(triangulator_source.find("steps::" + function + "("), std::string::npos)
      << "Triangulator::Process calls steps::" << function << " directly, past its binding";
}

TEST(StepTable, EveryStepIsBoundToItsFunctionAndOptionsSection) {
  const std::string triangulator = ReadFile(kSourceDir / "core/pipeline/triangulator.cc");
  [&]<size_t... I>(std::index_sequence<I...>) { (CheckBinding<static_cast<Step>(I)>(triangulator), ...); }
  (std::make_index_sequence<kNumSteps>{});
  // Step 3 runs once, when the model is built.
  EXPECT_NE(ReadFile(kSourceDir / std::string(kChooseCoreJoints.file)).find("steps::ChooseCoreJoints("),
            std::string::npos);
  EXPECT_NE(ReadFile(kSourceDir / "core/pipeline/model.cc").find("steps::ChooseCoreJoints(m.resolved.triangulate,"),
            std::string::npos)
      << "BuildModel runs step 3 with its section";
}

// The options sections (config files, `rpt config --dump`, docs/options.md) come in the order the
// steps that read them run.
TEST(StepTable, OptionsSectionsFollowTheStepOrder) {
  std::vector<std::string> from_steps;
  for (const StepInfo& step : kAllSteps) {
    const std::string section(step.section);
    if (section.empty()) continue;
    if (std::find(from_steps.begin(), from_steps.end(), section) == from_steps.end()) from_steps.push_back(section);
  }
  std::vector<std::string> visited;
  auto visitor = [&visited](const char* name, const auto&) { visited.emplace_back(name); };
  const TriangulatorOptions options;
  VisitSections(visitor, options);
  EXPECT_EQ(visited, from_steps);
}

}  // namespace
}  // namespace rpt
