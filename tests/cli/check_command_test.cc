// SPDX-License-Identifier: MIT
// rpt check: the thresholds file is validated before anything runs, a failing evaluation is named
// while the others still run, --fail-on-skip, and --junit writes well-formed JUnit XML.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/outputs/junit_xml.h"
#include "tests/cli/cli_test_util.h"
#include "tests/cli/xml_check.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

// A tiny synthetic evaluation that passes its one check.
const char* const kTinyEvaluation = R"({"name": "tiny", "dataset": "synthetic",
    "params": {"frames": 10, "people": 2, "noise": "clean"}, "min": {"recall500": 50}})";

struct CheckRun {
  test::CommandResult result;
  fs::path file;
};

CheckRun RunCheck(const fs::path& dir, const std::string& name, const std::string& json, const std::string& flags = "") {
  const fs::path file = dir / name;
  std::ofstream(file) << json;
  return {test::RunRpt("check --thresholds " + file.string() + " " + flags), file};
}

class CheckCommandTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::TempDir("check_command"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CheckCommandTest, InvalidFilesExitWith2NamingFileAndJsonPathBeforeAnythingRuns) {
  struct Case {
    std::string evaluation;  // the second evaluation (the first is valid and would run)
    std::string expected;    // in the message, after "<file>: "
  };
  const Case cases[] = {
      {R"({"name": "x", "datset": "synthetic"})",
       "/evaluations/1/datset: unknown key 'datset' (did you mean 'dataset'?)"},
      {R"({"name": "x", "dataset": "shelff"})",
       "/evaluations/1/dataset: unknown dataset 'shelff' (did you mean 'shelf'?)"},
      {R"({"name": "x", "dataset": "synthetic", "min": {"recal500": 1}})",
       "/evaluations/1/min/recal500: unknown metric 'recal500' (did you mean 'recall500'?)"},
      {R"({"name": "x", "dataset": "synthetic", "max": {"mpjpe_mm": "30"}})",
       "/evaluations/1/max/mpjpe_mm: expected a number, got string"},
      {R"({"name": "x", "dataset": "synthetic", "simulate": "yes"})",
       "/evaluations/1/simulate: expected true or false"},
      {R"({"name": 3, "dataset": "synthetic"})", "/evaluations/1/name: expected a string"},
      {R"({"dataset": "synthetic"})", "/evaluations/1: missing \"name\""},
      {R"({"name": "x", "dataset": "synthetic", "seed": -1})", "/evaluations/1/seed: expected a non-negative integer"},
      {R"({"name": "x", "dataset": "synthetic", "set": {"merge.no_such_option": 1}})", "/evaluations/1/set: "},
      {R"({"name": "x", "dataset": "synthetic", "params": {"cameras": [1]}})",
       "/evaluations/1/params/cameras: expected"},
      {R"({"name": "x", "dataset": "synthetic", "min": {"legacy_pcp": 90}})",
       "/evaluations/1/min/legacy_pcp: legacy_pcp is computed only with metrics.legacy_pcp set"},
      {R"({"name": "x", "dataset": "synthetic", "params": {"camras": 3}})",
       "/evaluations/1/params/camras: unknown parameter 'camras' (did you mean 'cameras'?) (synthetic has: cameras, "
       "people"},
      // Files that would pass without checking what they say.
      {R"({"name": "x", "dataset": "synthetic"})",
       "/evaluations/1: no \"min\" or \"max\" bound: the evaluation would check nothing"},
      {R"({"name": "x", "dataset": "synthetic", "min": {"recall500": 90}, "max": {"recall500": 50}})",
       "/evaluations/1/min/recall500: min 90.0 is above max 50.0: the check can never pass"},
      {R"({"name": "tiny", "dataset": "synthetic", "min": {"pcp": 1}})",
       "/evaluations/1/name: the name 'tiny' is also /evaluations/0's"},
      {R"({"name": "x", "dataset": "synthetic", "detector": "clean", "min": {"pcp": 1}})",
       "/evaluations/1: as rpt eval's options: --detector needs --simulate"},
      {R"({"name": "x", "dataset": "synthetic", "simulate": true, "detector": "bogus", "min": {"pcp": 1}})",
       "/evaluations/1: as rpt eval's options: --detector 'bogus': unknown profile; known: perfect, clean, realistic, "
       "hard"},
      {R"({"name": "x", "dataset": "synthetic", "root": "nowhere", "min": {"pcp": 1}})",
       "/evaluations/1: as rpt eval's options: --root "},  // ... the synthetic dataset is generated and reads no folder
      // A value the reader refuses when it opens: found before anything runs too.
      {R"({"name": "x", "dataset": "synthetic", "params": {"frames": "abc"}, "min": {"pcp": 1}})",
       "/evaluations/1 ('x'): --param frames=abc: synthetic.frames: 'abc' is not an integer"},
  };
  for (const Case& c : cases) {
    const CheckRun run = RunCheck(dir_, "bad.json", std::string(R"({"evaluations": [)") + kTinyEvaluation + ", " +
                                                        c.evaluation + "]}");
    EXPECT_EQ(run.result.exit_code, 2) << c.evaluation << "\n" << run.result.err;
    EXPECT_NE(run.result.err.find(run.file.string() + ": " + c.expected), std::string::npos)
        << c.evaluation << "\n" << run.result.err;
    EXPECT_EQ(run.result.out, "") << "nothing runs before the file is valid";
  }
  const CheckRun empty = RunCheck(dir_, "empty.json", R"({"evaluations": []})");
  EXPECT_EQ(empty.result.exit_code, 2);
  EXPECT_NE(empty.result.err.find(empty.file.string() + ": /evaluations: no evaluations: the file would check nothing"),
            std::string::npos)
      << empty.result.err;
  const CheckRun top = RunCheck(dir_, "top.json", R"({"evaluation": []})");
  EXPECT_EQ(top.result.exit_code, 2);
  EXPECT_NE(top.result.err.find(": /evaluation: unknown key 'evaluation' (did you mean 'evaluations'?)"),
            std::string::npos)
      << top.result.err;
}

TEST_F(CheckCommandTest, AFailingEvaluationIsNamedAndTheOthersStillRun) {
  std::ofstream(dir_ / "broken_labels.json") << "{ not json";
  const CheckRun run = RunCheck(dir_, "thresholds.json",
                                std::string(R"({"evaluations": [{"name": "broken", "labels": "broken_labels.json",
                                    "simulate": true, "min": {"pcp": 1}}, )") +
                                    kTinyEvaluation + "]}");
  EXPECT_EQ(run.result.exit_code, 1) << run.result.out << run.result.err;
  EXPECT_NE(run.result.out.find("broken"), std::string::npos);
  EXPECT_NE(run.result.out.find("ERROR: "), std::string::npos) << run.result.out;
  EXPECT_NE(run.result.out.find("broken_labels.json"), std::string::npos) << "the error names the file";
  EXPECT_NE(run.result.out.find("recall500"), std::string::npos) << "the next evaluation still ran";
  EXPECT_NE(run.result.out.find("1 checks, 0 failed, 0 evaluations skipped, 1 evaluations failed to run"),
            std::string::npos)
      << run.result.out;
}

// --only with a text no evaluation has checks nothing: in CI that typo would pass, so it is an error.
TEST_F(CheckCommandTest, OnlyMatchingNothingIsAnError) {
  const std::string json = std::string(R"({"evaluations": [)") + kTinyEvaluation + "]}";
  const CheckRun typo = RunCheck(dir_, "thresholds.json", json, "--only tyni");
  EXPECT_EQ(typo.result.exit_code, 2) << typo.result.out;
  EXPECT_NE(typo.result.err.find("--only 'tyni': no evaluation of " + typo.file.string() + " has it in its name"),
            std::string::npos)
      << typo.result.err;
  const CheckRun matching = RunCheck(dir_, "thresholds.json", json, "--only tin");
  EXPECT_EQ(matching.result.exit_code, 0) << matching.result.out << matching.result.err;
}

TEST_F(CheckCommandTest, FailOnSkipTurnsSkippedEvaluationsIntoFailures) {
  const std::string json = std::string(R"({"evaluations": [)") + kTinyEvaluation +
                           R"(, {"name": "absent data", "dataset": "shelf", "root": "no/such/folder",
                               "simulate": true, "min": {"pcp": 1}}]})";
  const CheckRun lenient = RunCheck(dir_, "thresholds.json", json);
  EXPECT_EQ(lenient.result.exit_code, 0) << lenient.result.out << lenient.result.err;
  EXPECT_NE(lenient.result.out.find("skipped (" + (dir_ / "no/such/folder").string() + " absent)"), std::string::npos)
      << lenient.result.out;
  const CheckRun strict = RunCheck(dir_, "thresholds.json", json, "--fail-on-skip");
  EXPECT_EQ(strict.result.exit_code, 1) << strict.result.out << strict.result.err;
  EXPECT_NE(strict.result.out.find("SKIPPED, failing"), std::string::npos) << strict.result.out;
}

TEST_F(CheckCommandTest, JunitHasOneWellFormedTestcasePerCheck) {
  std::ofstream(dir_ / "broken_labels.json") << "{ not json";
  const std::string json = R"({"evaluations": [
      {"name": "tiny <\"&'>", "dataset": "synthetic", "params": {"frames": 10, "people": 2, "noise": "clean"},
       "min": {"recall500": 50, "pcp": 100.5}, "max": {"mpjpe_mm": 500}},
      {"name": "absent", "dataset": "shelf", "root": "no/such/folder", "simulate": true, "min": {"pcp": 1}},
      {"name": "broken", "labels": "broken_labels.json", "simulate": true, "min": {"pcp": 1}}]})";
  const fs::path junit = dir_ / "check.xml";
  const CheckRun run = RunCheck(dir_, "thresholds.json", json, "--junit " + junit.string());
  EXPECT_EQ(run.result.exit_code, 1) << run.result.out << run.result.err;
  const test::XmlElement root = test::XmlReader::Parse(test::ReadAll(junit));
  EXPECT_EQ(root.name, "testsuites");
  ASSERT_EQ(root.children.size(), 1u);
  const test::XmlElement& suite = root.children[0];
  EXPECT_EQ(suite.attributes.at("tests"), "5");
  EXPECT_EQ(suite.attributes.at("failures"), "1");
  EXPECT_EQ(suite.attributes.at("errors"), "1");
  EXPECT_EQ(suite.attributes.at("skipped"), "1");
  ASSERT_EQ(suite.children.size(), 5u);
  // "min" checks in key order, then "max".
  EXPECT_EQ(suite.children[0].attributes.at("classname"), "tiny <\"&'>");
  EXPECT_EQ(suite.children[0].attributes.at("name"), "pcp min 100.5");
  ASSERT_EQ(suite.children[0].children.size(), 1u);
  EXPECT_EQ(suite.children[0].children[0].name, "failure");
  EXPECT_TRUE(suite.children[1].children.empty()) << "recall500 passes";
  EXPECT_TRUE(suite.children[2].children.empty()) << "mpjpe_mm passes";
  EXPECT_EQ(suite.children[3].children.at(0).name, "skipped");
  EXPECT_EQ(suite.children[4].children.at(0).name, "error");
  EXPECT_NE(suite.children[4].children[0].attributes.at("message").find("broken_labels.json"), std::string::npos);
}

// --json: stdout is one JSON document (the table goes to stderr) with every check, skip and
// error, the totals and the exit code; the JUnit file's folder is checked before anything runs;
// an empty name is refused.
TEST_F(CheckCommandTest, JsonIsTheWholeStdoutAndListsSkipsAndErrors) {
  std::ofstream(dir_ / "broken_labels.json") << "{ not json";
  const std::string json = std::string(R"({"evaluations": [)") + kTinyEvaluation +
                           R"(, {"name": "absent data", "dataset": "shelf", "root": "no/such/folder",
                               "simulate": true, "min": {"pcp": 1}},
                              {"name": "broken", "labels": "broken_labels.json", "simulate": true,
                               "min": {"pcp": 1}, "max": {"mpjpe_mm": 100}}]})";
  const CheckRun run = RunCheck(dir_, "thresholds.json", json, "--json");
  EXPECT_EQ(run.result.exit_code, 1) << run.result.err;
  const nlohmann::json result = nlohmann::json::parse(run.result.out);  // throws if the table were there too
  EXPECT_EQ(result["exit_code"], 1);
  EXPECT_EQ(result["totals"], nlohmann::json({{"checks", 1}, {"failed", 0}, {"skipped", 1}, {"errors", 1}}));
  ASSERT_EQ(result["checks"].size(), 4u) << result.dump(1);
  EXPECT_EQ(result["checks"][0]["status"], "pass");
  EXPECT_EQ(result["checks"][0]["metric"], "recall500");
  EXPECT_EQ(result["checks"][1]["status"], "skip");
  EXPECT_EQ(result["checks"][1]["evaluation"], "absent data");
  EXPECT_TRUE(result["checks"][1]["pass"].get<bool>()) << "a skip passes unless --fail-on-skip";
  EXPECT_NE(result["checks"][1]["message"].get<std::string>().find("no/such/folder absent"), std::string::npos);
  EXPECT_EQ(result["checks"][2]["status"], "error");
  EXPECT_EQ(result["checks"][2]["metric"], "pcp");
  EXPECT_EQ(result["checks"][3]["metric"], "mpjpe_mm");
  EXPECT_FALSE(result["checks"][3]["pass"].get<bool>());
  EXPECT_NE(run.result.err.find("1 checks, 0 failed, 1 evaluations skipped"), std::string::npos) << run.result.err;
  const CheckRun failing_skip = RunCheck(dir_, "thresholds.json", json, "--json --fail-on-skip");
  EXPECT_FALSE(nlohmann::json::parse(failing_skip.result.out)["checks"][1]["pass"].get<bool>());

  const CheckRun junit = RunCheck(dir_, "thresholds.json", json, "--junit " + (dir_ / "no" / "such" / "j.xml").string());
  EXPECT_EQ(junit.result.exit_code, 2);
  EXPECT_NE(junit.result.err.find("j.xml: cannot open for writing"), std::string::npos) << junit.result.err;
  EXPECT_EQ(junit.result.out.find("recall500"), std::string::npos) << "nothing ran: " << junit.result.out;

  // The counts of what the metrics leave out (summary.json) are metrics too.
  const CheckRun counts = RunCheck(dir_, "counts.json", R"({"evaluations": [{"name": "counts", "dataset": "synthetic",
      "params": {"frames": 5}, "max": {"missing_pred_joints": 0, "dropped_gt_persons": 0, "unaligned_matches": 0}}]})",
                                   "--json");
  EXPECT_EQ(counts.result.exit_code, 0) << counts.result.err;
  EXPECT_EQ(nlohmann::json::parse(counts.result.out)["totals"]["checks"], 3);

  const CheckRun unnamed = RunCheck(dir_, "unnamed.json", R"({"evaluations": [{"name": "", "dataset": "synthetic",
      "min": {"pcp": 1}}]})");
  EXPECT_EQ(unnamed.result.exit_code, 2);
  EXPECT_NE(unnamed.result.err.find("/evaluations/0/name: empty"), std::string::npos) << unnamed.result.err;
}

// Characters XML 1.0 forbids are written visibly as \xNN (XmlText), no longer dropped: a name
// keeps telling two cases apart.
TEST(JunitXml, EscapesMarkupAndShowsCharactersXmlForbids) {
  const std::string xml = engine::JunitXml("suite & <co>", {{"a\x01 \"b\"", "c 'd' </testcase>", engine::JunitCase::Outcome::kFailure,
                                                          "x < y && \x1f z > w"}});
  const test::XmlElement root = test::XmlReader::Parse(xml);
  EXPECT_EQ(root.attributes.at("name"), "suite & <co>");
  const test::XmlElement& testcase = root.children.at(0).children.at(0);
  EXPECT_EQ(testcase.attributes.at("classname"), "a\\x01 \"b\"");
  EXPECT_EQ(testcase.attributes.at("name"), "c 'd' </testcase>");
  EXPECT_EQ(testcase.children.at(0).attributes.at("message"), "x < y && \\x1f z > w");
}

// A message of several lines (a --strict error lists its warnings) keeps its line breaks in the
// attribute: written literally, a parser turns them into spaces.
TEST(JunitXml, AttributesKeepLineBreaksAndTabs) {
  const std::string xml = engine::JunitXml("s", {{"a\tb", "n", engine::JunitCase::Outcome::kError, "first\nsecond"}});
  const test::XmlElement testcase = test::XmlReader::Parse(xml).children.at(0).children.at(0);
  EXPECT_EQ(testcase.attributes.at("classname"), "a\tb");
  EXPECT_EQ(testcase.children.at(0).attributes.at("message"), "first\nsecond");
  EXPECT_EQ(xml.find("first\n"), std::string::npos) << xml;
}

TEST(XmlReader, RejectsMalformedXml) {
  for (const char* bad : {"<a>", "<a></b>", "<a x=\"<\"/>", "<a x=\"&nbsp;\"/>", "<a x=1/>", "<a/><b/>"}) {
    EXPECT_THROW(test::XmlReader::Parse(bad), std::runtime_error) << bad;
  }
}

}  // namespace
}  // namespace rpt
