// SPDX-License-Identifier: MIT
#include "cli/results_writer.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace rpt::cli {
namespace {

// Splits one CSV line by RFC 4180 (quoted fields may hold commas; "" is a quote).
std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

TEST(ResultsWriter, CsvFieldQuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(CsvField("shelf"), "shelf");
  EXPECT_EQ(CsvField("a, b"), "\"a, b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\nlines"), "\"two\nlines\"");
}

// Sweep rows are named by people ("bone-length check (rpt addition, off by default)"): a comma in
// the name must not shift the numbers into the wrong columns.
TEST(ResultsWriter, SummaryCsvKeepsColumnsWhenTheRunNameHasCommas) {
  nlohmann::ordered_json summary = {{"pcp", 97.5}, {"mpjpe_mm", 60.25}};
  std::istringstream csv(SummaryCsv({{"bone-length check (rpt addition, off by default)", summary}}));
  std::string header_line, row_line;
  std::getline(csv, header_line);
  std::getline(csv, row_line);
  const std::vector<std::string> header = SplitCsvLine(header_line), row = SplitCsvLine(row_line);
  ASSERT_EQ(row.size(), header.size());
  EXPECT_EQ(row[0], "bone-length check (rpt addition, off by default)");
  int checked = 0;
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "pcp") {
      EXPECT_EQ(row[i], "97.5000");
      ++checked;
    }
    if (header[i] == "mpjpe_mm") {
      EXPECT_EQ(row[i], "60.2500");
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

}  // namespace
}  // namespace rpt::cli
