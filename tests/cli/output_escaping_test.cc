// SPDX-License-Identifier: MIT
// One escaping function per sink (engine/outputs/text_escaping.h, core/printable_text.h), each fed
// every string of tests/hostile_strings.h, alone and through the writers that use it: TRC fields, the tables
// (summary.csv, summary.md, sweep.csv, sweep.md), JUnit XML, sweep.html and the report's data block.
#include "engine/outputs/text_escaping.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/printable_text.h"
#include "core/utf8.h"
#include "datasets/io/json_output.h"
#include "engine/outputs/junit_xml.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/sweep_html.h"
#include "engine/report/report_html.h"
#include "tests/cli/cli_test_util.h"
#include "tests/cli/xml_check.h"
#include "tests/hostile_strings.h"

namespace rpt::engine {
namespace {

using Json = nlohmann::ordered_json;
using test::HostileStrings;
namespace fs = std::filesystem;

// What a terminal must never receive raw: C0 controls (but newline and tab when
// `line_breaks_allowed`), DEL, C1 controls, bidirectional overrides, noncharacters, invalid UTF-8.
void ExpectTerminalSafe(const std::string& text, bool line_breaks_allowed, const std::string& from) {
  EXPECT_TRUE(IsValidUtf8(text)) << from;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<std::uint8_t>(text[i]);
    if (line_breaks_allowed && (c == '\n' || c == '\t')) continue;
    EXPECT_FALSE(c < 0x20 || c == 0x7f) << "byte " << int(c) << " at " << i << " from " << PrintableText(from);
    if (c == 0xc2 && i + 1 < text.size()) {
      EXPECT_GE(static_cast<std::uint8_t>(text[i + 1]), 0xa0) << PrintableText(from);
    }
    if (c == 0xe2 && i + 2 < text.size() && static_cast<std::uint8_t>(text[i + 1]) == 0x80) {
      const auto last = static_cast<std::uint8_t>(text[i + 2]);
      EXPECT_FALSE(last >= 0xaa && last <= 0xae) << "bidirectional override from " << PrintableText(from);
    }
    if (c == 0xef && i + 2 < text.size() && static_cast<std::uint8_t>(text[i + 1]) == 0xbf) {
      EXPECT_LT(static_cast<std::uint8_t>(text[i + 2]), 0xbe) << "noncharacter from " << PrintableText(from);
    }
  }
}

TEST(OutputEscaping, TerminalTextKeepsNothingATerminalActsOn) {
  EXPECT_EQ(PrintableText("\x1b[31mred", LineBreaks::kEscape), "\\x1b[31mred");
  EXPECT_EQ(PrintableText("\xc2\x9b"
                          "31m",
                          LineBreaks::kEscape),
            "\\xc2\\x9b31m");
  EXPECT_EQ(PrintableText("l\xe2\x80\xaer"), "l\\xe2\\x80\\xaer");
  EXPECT_EQ(PrintableText("a\nb\tc", LineBreaks::kEscape), "a\\x0ab\\x09c");
  EXPECT_EQ(PrintableText("a\nb\tc"), "a\nb\tc");
  EXPECT_EQ(PrintableText("\xef\xbf\xbf"), "\\xef\\xbf\\xbf");
  EXPECT_EQ(PrintableText("\xc2\xa0\xe2\x80\x94"), "\xc2\xa0\xe2\x80\x94") << "no-break space and dash stay";
  for (const std::string& s : HostileStrings()) {
    ExpectTerminalSafe(PrintableText(s, LineBreaks::kEscape), false, s);
    ExpectTerminalSafe(PrintableText(s), true, s);
  }
  EXPECT_EQ(PrintableText("Z\xc3\xbcrich \xe2\x9c\x93 \xf0\x9f\x98\x80"),
            "Z\xc3\xbcrich \xe2\x9c\x93 \xf0\x9f\x98\x80");
}

// A name quoted into a one-line message (errors and warnings of the readers): one line, safe.
TEST(OutputEscaping, QuotedNamesAreOneTerminalSafeLine) {
  for (const std::string& s : HostileStrings()) {
    const std::string quoted = QuoteName(s);
    ASSERT_GE(quoted.size(), 2u);
    EXPECT_EQ(quoted.front(), '\'');
    EXPECT_EQ(quoted.back(), '\'');
    ExpectTerminalSafe(quoted, false, s);
  }
}

// Names listed in a message ("(cameras: a, b)"): one line, safe, each name as PrintableText.
TEST(OutputEscaping, ListedNamesAreOneTerminalSafeLine) {
  const std::vector<std::string> hostile = HostileStrings();
  ExpectTerminalSafe(JoinNames(hostile), false, "the hostile names joined");
  EXPECT_EQ(JoinNames({"cam0", "cam4\nresults in x\t"}), "cam0, cam4\\x0aresults in x\\x09");
  // End to end: a calibration camera named with a line break, listed in triangulate's error.
  const fs::path dir = test::TempDir("listed_names");
  ASSERT_EQ(test::RunRpt("convert --dataset synthetic --param frames=1 --labels-out " + (dir / "labels.json").string() +
                         " --detections-out " + (dir / "detections.json").string())
                .exit_code,
            0);
  std::string labels = test::ReadAll(dir / "labels.json");
  const size_t at = labels.find("\"cam4\"");
  ASSERT_NE(at, std::string::npos);
  labels.replace(at, 6, "\"cam4\\nresults in x\"");
  std::ofstream(dir / "labels.json") << labels;
  const test::CommandResult r = test::RunRpt("triangulate --cameras " + (dir / "labels.json").string() + " --detections " +
                                             (dir / "detections.json").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("(cameras: cam0, cam1, cam2, cam3, cam4\\x0aresults in x)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\nresults in x"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(OutputEscaping, HtmlTextHasNoMarkup) {
  EXPECT_EQ(HtmlText("<!--<script>"), "&lt;!--&lt;script&gt;");
  EXPECT_EQ(HtmlText("a & 'b' \"c\"\n"), "a &amp; &apos;b&apos; &quot;c&quot;\\x0a");
  for (const std::string& s : HostileStrings()) {
    const std::string html = HtmlText(s);
    EXPECT_EQ(html.find_first_of("<>\"'"), std::string::npos) << html;
    for (size_t at = html.find('&'); at != std::string::npos; at = html.find('&', at + 1)) {
      const std::string entity = html.substr(at, html.find(';', at) - at + 1);
      EXPECT_TRUE(entity == "&amp;" || entity == "&lt;" || entity == "&gt;" || entity == "&quot;" || entity == "&apos;")
          << entity;
    }
    ExpectTerminalSafe(html, false, s);
    // As text of an element and as an attribute value, read back by a strict XML reader.
    const test::XmlElement e =
        test::XmlReader::Parse("<p title=\"" + html + "\">" + html + "</p>", test::Markup::kDocument);
    EXPECT_EQ(e.text, PrintableText(s, LineBreaks::kEscape));
    EXPECT_EQ(e.attributes.at("title"), PrintableText(s, LineBreaks::kEscape));
  }
}

TEST(OutputEscaping, ScriptJsonCannotEndOrChangeTheScriptElement) {
  EXPECT_EQ(ScriptJson("[\"</script><!--<script>&\"]"),
            "[\"\\u003c/script\\u003e\\u003c!--\\u003cscript\\u003e\\u0026\"]");
  EXPECT_EQ(ScriptJson("\"\xe2\x80\xa8\xe2\x80\xa9\""), "\"\\u2028\\u2029\"");
  Json data = Json::object();
  for (const std::string& s : HostileStrings()) {
    data["values"].push_back(s);
    data[s] = {{"camera", s}};
  }
  int replaced = 0;
  const std::string text = io::DumpJson(data, -1, &replaced);
  EXPECT_GT(replaced, 0) << "the set holds invalid UTF-8";
  const std::string script = ScriptJson(text);
  EXPECT_EQ(script.find_first_of("<>&"), std::string::npos);
  // The value is unchanged, but for the right-to-left override, which becomes visible text.
  std::string shown = text;
  for (size_t at; (at = shown.find("\xe2\x80\xae")) != std::string::npos;) shown.replace(at, 3, "\\\\xe2\\\\x80\\\\xae");
  EXPECT_EQ(Json::parse(script), Json::parse(shown));
  EXPECT_EQ(ScriptJson("[\"a\xe2\x81\xa6" "b\xe2\x81\xa9\"]"), R"(["a\\xe2\\x81\\xa6b\\xe2\\x81\\xa9"])");
}

TEST(OutputEscaping, TrcFieldsAreOneFieldOfOneLine) {
  EXPECT_EQ(TrcField("extra_a\tb\nc"), "extra_a\\x09b\\x0ac");
  EXPECT_EQ(TrcField("shoulder_left"), "shoulder_left");
  for (const std::string& s : HostileStrings()) {
    const std::string field = TrcField(s);
    EXPECT_EQ(field.find_first_of("\t\n\r"), std::string::npos) << PrintableText(s);
    ExpectTerminalSafe(field, false, s);
  }
}

TEST(OutputEscaping, CsvFieldsAreOneLineNeverAFormulaAndReadBack) {
  EXPECT_EQ(CsvField("shelf"), "shelf");
  EXPECT_EQ(CsvField("a, b"), "\"a, b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\nlines"), "two\\x0alines");
  EXPECT_EQ(CsvField("=1+2"), "'=1+2");
  EXPECT_EQ(CsvField("-3"), "'-3");
  EXPECT_EQ(CsvField("@SUM(A1),x"), "\"'@SUM(A1),x\"");
  EXPECT_EQ(CsvField("'quoted"), "''quoted");
  EXPECT_EQ(SplitCsvLine("a,\"b,\"\"c\"\"\",'=d,''e,'f"), (std::vector<std::string>{"a", "b,\"c\"", "=d", "'e", "'f"}));
  EXPECT_THROW(SplitCsvLine("\"open"), std::invalid_argument);
  std::string line;
  std::vector<std::string> expected;
  for (const std::string& s : HostileStrings()) {
    const std::string field = CsvField(s);
    EXPECT_EQ(field.find_first_of("\r\n"), std::string::npos) << field;
    const size_t first = field.rfind('"', 0) == 0 ? 1 : 0;
    if (field.size() > first) {
      EXPECT_EQ(std::string("=+-@").find(field[first]), std::string::npos) << field;
    }
    EXPECT_EQ(SplitCsvLine(field), std::vector<std::string>{PrintableText(s, LineBreaks::kEscape)}) << field;
    line += (line.empty() && expected.empty() ? "" : ",") + field;
    expected.push_back(PrintableText(s, LineBreaks::kEscape));
  }
  EXPECT_EQ(SplitCsvLine(line), expected);
}

// The cells of a Markdown table row: split at '|' not escaped by a backslash.
std::vector<std::string> MarkdownCells(const std::string& row) {
  std::vector<std::string> cells(1);
  for (size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size()) {
      cells.back() += row.substr(i, 2);
      ++i;
    } else if (row[i] == '|') {
      cells.emplace_back();
    } else {
      cells.back() += row[i];
    }
  }
  return cells;
}

TEST(OutputEscaping, MarkdownTextAndCodeSpansHoldAnyName) {
  EXPECT_EQ(MarkdownText("a|b `c` <i>"), "a\\|b \\`c\\` \\<i\\>");
  EXPECT_EQ(MarkdownText("x_y\n"), "x\\_y\\\\x0a");
  EXPECT_EQ(MarkdownCode("rpt eval --out a`b"), "``rpt eval --out a`b``");
  EXPECT_EQ(MarkdownCode("`"), "`` ` ``");
  EXPECT_EQ(MarkdownCode("plain"), "`plain`");
  EXPECT_EQ(MarkdownCode(""), "` `");
  for (const std::string& s : HostileStrings()) {
    const std::string text = MarkdownText(s);
    ExpectTerminalSafe(text, false, s);
    EXPECT_EQ(MarkdownCells("| " + text + " |").size(), 3u) << text;
    for (size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\\') {
        ++i;
        continue;
      }
      EXPECT_EQ(std::string("`*_[]<>|~&!$").find(text[i]), std::string::npos) << "unescaped in " << text;
    }
    const std::string code = MarkdownCode(s);
    ExpectTerminalSafe(code, false, s);
    const size_t fence = code.find_first_not_of('`');
    ASSERT_NE(fence, std::string::npos) << code;
    const std::string inside = code.substr(fence, code.size() - 2 * fence);
    EXPECT_EQ(code.substr(code.size() - fence), std::string(fence, '`'));
    EXPECT_EQ(inside.find(std::string(fence, '`')), std::string::npos) << "the fence ends inside: " << code;
  }
}

// The code point of each character of valid UTF-8 `text`.
std::vector<std::uint32_t> CodePoints(const std::string& text) {
  std::vector<std::uint32_t> out;
  for (size_t i = 0; i < text.size();) {
    const size_t length = Utf8SequenceLength(text, i);
    if (length == 0) return {0};
    std::uint32_t code = static_cast<std::uint8_t>(text[i]) & (length == 1 ? 0x7f : 0xff >> (length + 1));
    for (size_t k = 1; k < length; ++k) code = (code << 6) | (static_cast<std::uint8_t>(text[i + k]) & 0x3f);
    out.push_back(code);
    i += length;
  }
  return out;
}

// XML 1.0: #x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF].
bool IsXmlChar(std::uint32_t c) {
  return c == 0x9 || c == 0xa || c == 0xd || (c >= 0x20 && c <= 0xd7ff) || (c >= 0xe000 && c <= 0xfffd) ||
         (c >= 0x10000 && c <= 0x10ffff);
}

TEST(OutputEscaping, JunitXmlIsWellFormedForEveryName) {
  EXPECT_EQ(XmlText("a\xff<b"), "a\xef\xbf\xbd&lt;b");
  EXPECT_EQ(XmlText("x\xef\xbf\xbey\x01"), "x\\xef\\xbf\\xbey\\x01");
  std::vector<JunitCase> cases;
  for (const std::string& s : HostileStrings()) cases.push_back({s, s, JunitCase::Outcome::kFailure, s});
  const std::string xml = JunitXml(HostileStrings()[0], cases);
  for (const std::uint32_t c : CodePoints(xml)) EXPECT_TRUE(IsXmlChar(c)) << "U+" << std::hex << c;
  const test::XmlElement root = test::XmlReader::Parse(xml);
  const test::XmlElement& suite = root.children.at(0);
  ASSERT_EQ(suite.children.size(), HostileStrings().size());
  for (size_t i = 0; i < HostileStrings().size(); ++i) {
    EXPECT_EQ(suite.children[i].attributes.at("name"), PrintableText(io::ValidUtf8(HostileStrings()[i])));
  }
}

TEST(OutputEscaping, SummaryTablesKeepOneRowAndColumnsPerLabel) {
  std::vector<std::pair<std::string, Json>> rows;
  for (const std::string& s : HostileStrings()) rows.emplace_back(s, Json{{"pcp", 90.0}, {"frames", 3}});
  std::istringstream csv(SummaryCsv(rows));
  std::string line;
  std::getline(csv, line);
  const size_t columns = SplitCsvLine(line).size();
  for (const std::string& s : HostileStrings()) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> fields = SplitCsvLine(line);
    ASSERT_EQ(fields.size(), columns) << line;
    EXPECT_EQ(fields[0], PrintableText(s, LineBreaks::kEscape));
  }
  EXPECT_FALSE(std::getline(csv, line)) << "one line per row";

  std::istringstream md(SummaryMarkdown(rows));
  std::getline(md, line);
  const size_t cells = MarkdownCells(line).size();
  std::getline(md, line);  // |---|
  for (size_t i = 0; i < HostileStrings().size(); ++i) {
    ASSERT_TRUE(std::getline(md, line));
    EXPECT_EQ(MarkdownCells(line).size(), cells) << line;
    ExpectTerminalSafe(line, false, HostileStrings()[i]);
  }
}

TEST(OutputEscaping, SweepHtmlIsWellFormedAndCutsLabelsAtCharacters) {
  Json sweep;
  sweep["base"] = Json::object();
  sweep["run"] = {{"command", "rpt sweep --list " + HostileStrings()[0]}};
  for (const std::string& s : HostileStrings()) {
    sweep["rows"].push_back({{"name", s}, {"set", {{s, s}}}, {"default", false}, {"summary", {{"pcp", 1.0}}}});
  }
  const std::string long_name(47, 'a');
  for (const std::string& tail : {std::string("\xc3\xbc\xc3\xbc\xc3\xbc"), std::string("\xf0\x9f\x98\x80 end")}) {
    sweep["rows"].push_back(
        {{"name", long_name + tail}, {"set", Json::object()}, {"default", false}, {"summary", {{"pcp", 2.0}}}});
  }
  sweep["rows"][0]["default"] = true;
  const std::string html = SweepHtml(sweep);
  EXPECT_TRUE(IsValidUtf8(html));
  ExpectTerminalSafe(html, true, "sweep.html");
  const test::XmlElement page = test::XmlReader::Parse(html, test::Markup::kDocument);
  EXPECT_NE(html.find(HtmlText(HostileStrings()[0])), std::string::npos);
  EXPECT_NE(html.find(">" + long_name + "...</text>"), std::string::npos) << "47 characters, then ...";
  (void)page;
}

TEST(OutputEscaping, ReportDataBlockHoldsAnyNameAndParsesBack) {
  Json data;
  data["title"] = HostileStrings()[0];
  for (const std::string& s : HostileStrings()) data["names"].push_back(s);
  std::string page;
  try {
    page = ReportHtml(data);
  } catch (const std::exception& e) {
    GTEST_SKIP() << "JavaScript libraries absent: " << e.what();
  }
  const std::string open = "<script type=\"application/json\" id=\"rpt-data\">";
  const size_t begin = page.find(open) + open.size();
  const size_t end = page.find("</script>", begin);
  ASSERT_NE(end, std::string::npos);
  const std::string block = page.substr(begin, end - begin);
  EXPECT_EQ(block.find_first_of("<>&"), std::string::npos);
  const Json back = Json::parse(block);
  for (size_t i = 0; i < HostileStrings().size(); ++i) {
    // Every name as it was, but a right-to-left override shown as text (it reversed what followed it).
    std::string expected = Json::parse(io::DumpJson(Json(HostileStrings()[i]))).get<std::string>();
    if (const size_t rlo = expected.find("\xe2\x80\xae"); rlo != std::string::npos) {
      expected.replace(rlo, 3, "\\xe2\\x80\\xae");
    }
    EXPECT_EQ(back["names"][i], expected);
  }
}

}  // namespace
}  // namespace rpt::engine
