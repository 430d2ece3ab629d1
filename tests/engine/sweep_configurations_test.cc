// SPDX-License-Identifier: MIT
#include "engine/sweep_configurations.h"

#include <gtest/gtest.h>

#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt::engine {
namespace {

using Overrides = std::vector<std::pair<std::string, std::string>>;

std::filesystem::path WriteList(const test::TempDir& dir, const std::string& text) {
  return dir.Write("list.json", test::ByteVec(text.begin(), text.end()));
}

TEST(SweepConfigurations, ListItemsKeepTheirOrderNamesAndValueTexts) {
  test::TempDir dir;
  const std::vector<SweepConfiguration> list = ReadSweepList(
      WriteList(dir, R"([{"name": "no prefilter", "set": {"prefilter.enabled": false}},
                         {"set": {"filter.min_match_score": 0.9, "triangulate.core_joints": ["nose", "hip_left"]}},
                         {"name": "default"}])")
          .string());
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].name, "no prefilter");
  EXPECT_EQ(list[0].overrides, (Overrides{{"prefilter.enabled", "false"}}));
  EXPECT_EQ(list[1].name, "configuration 2");  // unnamed: its place, counted from 1
  EXPECT_EQ(list[1].overrides,
            (Overrides{{"filter.min_match_score", "0.9"}, {"triangulate.core_joints", R"(["nose","hip_left"])"}}));
  EXPECT_EQ(list[2].name, "default");
  EXPECT_TRUE(list[2].overrides.empty());
  // The object form reads the same list under /configurations.
  const std::vector<SweepConfiguration> wrapped =
      ReadSweepList(WriteList(dir, R"({"configurations": [{"name": "a", "set": {"merge.top_k": 0}}]})").string());
  ASSERT_EQ(wrapped.size(), 1u);
  EXPECT_EQ(wrapped[0].name, "a");
  EXPECT_EQ(wrapped[0].overrides, (Overrides{{"merge.top_k", "0"}}));
}

TEST(SweepConfigurations, WrongTypesAreInputErrorsNamingTheFileAndPointer) {
  test::TempDir dir;
  const auto error_of = [&](const std::string& text) {
    const std::string path = WriteList(dir, text).string();
    return test::InputErrorOf([&] { ReadSweepList(path); });
  };
  EXPECT_NE(error_of(R"({"configurations": 3})").find("list.json: /configurations: expected a list"),
            std::string::npos);
  EXPECT_NE(error_of(R"("text")").find("list.json: /: expected a list"), std::string::npos);
  EXPECT_NE(error_of(R"([{"name": "a"}, 7])").find("list.json: /1: expected {\"name\", \"set\"}, got number"),
            std::string::npos);
  EXPECT_NE(error_of(R"([{"name": 5}])").find("list.json: /0/name"), std::string::npos);
  EXPECT_NE(error_of(R"([{"set": [1]}])").find("list.json: /0/set: expected an object"), std::string::npos);
  EXPECT_NE(error_of(std::string(300, '[')).find("deeper than 256"), std::string::npos);
}

TEST(SweepConfigurations, GridIsEveryCombinationFirstAxisOutermost) {
  const std::vector<SweepConfiguration> grid = ExpandSweepGrid({"a.x=1,2", "b.y=p,q,r"});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[0].name, "a.x=1 b.y=p");
  EXPECT_EQ(grid[1].name, "a.x=1 b.y=q");
  EXPECT_EQ(grid[3].name, "a.x=2 b.y=p");
  EXPECT_EQ(grid[5].overrides, (Overrides{{"a.x", "2"}, {"b.y", "r"}}));
  const std::vector<SweepConfiguration> none = ExpandSweepGrid({});
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].name, "default");
  EXPECT_NE(test::ConfigErrorOf([] { ExpandSweepGrid({"a.x"}); }).find("--grid a.x: expected key=value1"),
            std::string::npos);
  EXPECT_NE(test::ConfigErrorOf([] { ExpandSweepGrid({"a.x="}); }).find("--grid a.x=: no values"), std::string::npos);
}

TEST(SweepConfigurations, GridValuesMayBeListsAndStringsHoldingCommas) {
  const std::vector<SweepConfiguration> lists =
      ExpandSweepGrid({R"(t.core=[], ["hip_left","hip_right"] ,[8,8,3])", R"(n.name="a,b",c)"});
  ASSERT_EQ(lists.size(), 6u);
  EXPECT_EQ(lists[0].overrides, (Overrides{{"t.core", "[]"}, {"n.name", R"("a,b")"}}));
  EXPECT_EQ(lists[2].overrides, (Overrides{{"t.core", R"(["hip_left","hip_right"])"}, {"n.name", R"("a,b")"}}));
  EXPECT_EQ(lists[5].overrides, (Overrides{{"t.core", "[8,8,3]"}, {"n.name", "c"}}));
  EXPECT_EQ(ExpandSweepGrid({R"(s.x="a\",b",c)"})[0].overrides, (Overrides{{"s.x", R"("a\",b")"}}));
}

}  // namespace
}  // namespace rpt::engine
