// SPDX-License-Identifier: MIT
// The dataset registry (engine/dataset_registry.h): every reader is listed with parameters its own
// parser accepts, docs/datasets.md shows the tables it generates, and opening a dataset gives the
// frames that reading it whole gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "engine/dataset_registry.h"

namespace rpt::engine {
namespace {

TEST(DatasetRegistry, EveryReaderIsListedOnce) {
  std::map<std::string, int> names;
  for (const DatasetEntry& entry : DatasetRegistry()) ++names[entry.info.name];
  for (const char* name : {"shelf", "shelf-4da", "campus", "panoptic", "human36m", "h3wb", "egohumans", "mvor",
                           "generic", "synthetic"}) {
    EXPECT_EQ(names[name], 1) << name;
  }
  EXPECT_EQ(names.size(), 10u);
}

// docs/datasets.md shows the tables DatasetParamsMarkdown() generates from the readers' visits.
TEST(DatasetRegistry, DocsTablesMatchTheReaders) {
  std::ifstream file(std::filesystem::path(RPT_SOURCE_DIR) / "docs" / "datasets.md");
  ASSERT_TRUE(file.good());
  std::stringstream text;
  text << file.rdbuf();
  const std::string docs = text.str();
  const std::string begin = "<!-- dataset-params:begin -->\n";
  const std::string end = "<!-- dataset-params:end -->";
  const size_t a = docs.find(begin);
  const size_t b = docs.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(docs.substr(a + begin.size(), b - a - begin.size()), DatasetParamsMarkdown())
      << "regenerate the tables in docs/datasets.md (rpt datasets --markdown)";
}

TEST(DatasetRegistry, AnUnknownDatasetIsAConfigErrorListingTheKnownOnes) {
  DatasetRequest request;
  request.dataset = "shelve";
  try {
    OpenDataset(request);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown dataset 'shelve'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("shelf-4da"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rpt::engine
