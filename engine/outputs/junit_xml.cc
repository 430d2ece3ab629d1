// SPDX-License-Identifier: MIT
#include "engine/outputs/junit_xml.h"

#include "core/errors.h"
#include "engine/outputs/text_escaping.h"
#include "datasets/io/text_file.h"

namespace rpt::engine {

std::string JunitXml(const std::string& suite_name, const std::vector<JunitCase>& cases) {
  int failures = 0, errors = 0, skipped = 0;
  for (const JunitCase& c : cases) {
    failures += c.outcome == JunitCase::Outcome::kFailure ? 1 : 0;
    errors += c.outcome == JunitCase::Outcome::kError ? 1 : 0;
    skipped += c.outcome == JunitCase::Outcome::kSkipped ? 1 : 0;
  }
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) + "\"";
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuites name=\"" + XmlAttributeText(suite_name) + "\"" + counts + ">\n";
  xml += "  <testsuite name=\"" + XmlAttributeText(suite_name) + "\"" + counts + ">\n";
  for (const JunitCase& c : cases) {
    xml += "    <testcase classname=\"" + XmlAttributeText(c.classname) + "\" name=\"" + XmlAttributeText(c.name) + "\"";
    const char* element = c.outcome == JunitCase::Outcome::kFailure ? "failure"
                          : c.outcome == JunitCase::Outcome::kError ? "error"
                          : c.outcome == JunitCase::Outcome::kSkipped ? "skipped"
                                                                        : nullptr;
    if (element == nullptr) {
      xml += "/>\n";
      continue;
    }
    xml += ">\n      <" + std::string(element) + " message=\"" + XmlAttributeText(c.message) + "\"/>\n    </testcase>\n";
  }
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

void WriteJunitXml(const std::filesystem::path& path, const std::string& suite_name,
                   const std::vector<JunitCase>& cases) {
  io::WriteTextFile(path, io::NamedBy::kUser, JunitXml(suite_name, cases));
}

}  // namespace rpt::engine
