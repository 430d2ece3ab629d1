// SPDX-License-Identifier: MIT
// The dataset registry (engine/dataset_registry.h): every reader is listed with parameters its own
// parser accepts, docs/datasets.md shows the tables it generates, and opening a dataset gives the
// frames that reading it whole gives.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "datasets/frame_source.h"
#include "datasets/readers/synthetic_dataset.h"
#include "engine/dataset_registry.h"

namespace rpt::engine {
namespace {

TEST(DatasetRegistry, EveryReaderIsListedWithDescribedParameters) {
  std::map<std::string, int> names;
  for (const DatasetEntry& entry : DatasetRegistry()) {
    ++names[entry.info.name];
    ASSERT_FALSE(entry.info.params.empty()) << entry.info.name;
    for (const DatasetParam& p : entry.info.params) {
      EXPECT_FALSE(p.help.empty()) << entry.info.name << " " << p.name;
      EXPECT_FALSE(p.type.empty()) << entry.info.name << " " << p.name;
    }
  }
  for (const char* name : {"shelf", "shelf-4da", "campus", "panoptic", "human36m", "h3wb", "egohumans", "mvor",
                           "generic", "synthetic"}) {
    EXPECT_EQ(names[name], 1) << name;
  }
  EXPECT_EQ(names.size(), 10u);
}

// The synthetic reader takes its listed defaults back (the others need files on disk).
TEST(DatasetRegistry, TheSyntheticReaderTakesItsListedDefaults) {
  DatasetRequest request;
  request.dataset = "synthetic";
  for (const DatasetParam& p : SyntheticInfo().params) request.params[p.name] = p.default_value;
  request.params["frames"] = "2";
  EXPECT_EQ(ReadDataset(request).front().frames.size(), 2u);
}

// docs/datasets.md shows the tables DatasetParamsMarkdown() generates from the readers' visits.
TEST(DatasetRegistry, DocsTablesMatchTheReaders) {
  std::ifstream file(std::string(RPT_SOURCE_DIR) + "/docs/datasets.md");
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

TEST(DatasetRegistry, OpeningGivesTheFramesThatReadingWholeGives) {
  DatasetRequest request;
  request.dataset = "synthetic";
  request.params = {{"frames", "40"}, {"people", "2"}, {"cameras", "3"}, {"seed", "5"}};
  const std::vector<Sequence> read = ReadDataset(request);
  std::vector<std::unique_ptr<FrameSource>> sources = OpenDataset(request);
  ASSERT_EQ(read.size(), 1u);
  ASSERT_EQ(sources.size(), 1u);
  const Sequence streamed = Materialize(*sources[0]);
  EXPECT_EQ(streamed.name, read[0].name);
  ASSERT_EQ(streamed.frames.size(), read[0].frames.size());
  for (size_t f = 0; f < streamed.frames.size(); ++f) {
    EXPECT_EQ(streamed.frames[f].id, read[0].frames[f].id);
    EXPECT_EQ(streamed.frames[f].gt.data, read[0].frames[f].gt.data);
    ASSERT_EQ(streamed.frames[f].views.size(), read[0].frames[f].views.size());
    for (size_t v = 0; v < streamed.frames[f].views.size(); ++v) {
      EXPECT_EQ(streamed.frames[f].views[v].data, read[0].frames[f].views[v].data);
    }
  }
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
