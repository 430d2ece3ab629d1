// SPDX-License-Identifier: MIT
// JUnit XML (the format CI systems read test results from) for `rpt check --junit FILE`.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rpt::engine {

struct JunitCase {
  enum class Outcome { kPass, kFailure, kError, kSkipped };
  std::string classname;  // the evaluation
  std::string name;       // the check, e.g. "recall500 min 99"
  Outcome outcome = Outcome::kPass;
  std::string message;    // why it failed / errored / was skipped
};

// Every name and message goes through XmlText (engine/outputs/text_escaping.h).
// <testsuites><testsuite name=suite_name tests failures errors skipped><testcase .../>...</testsuite></testsuites>.
std::string JunitXml(const std::string& suite_name, const std::vector<JunitCase>& cases);

// Writes JunitXml() to `path`; throws InputError when it cannot be written.
void WriteJunitXml(const std::filesystem::path& path, const std::string& suite_name,
                   const std::vector<JunitCase>& cases);

}  // namespace rpt::engine
