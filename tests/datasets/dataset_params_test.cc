// SPDX-License-Identifier: MIT
// Typed dataset parameters (datasets/dataset_params.h): parsing, ranges, "did you mean", the
// parameter lists of every reader and their table in docs/datasets.md.
#include "datasets/dataset_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "engine/dataset_registry.h"
#include "tests/error_message.h"

namespace rpt {
using engine::DatasetRegistry;
using engine::DatasetEntry;
namespace {

using ::testing::HasSubstr;

enum class Color { kRed, kGreen };

}  // namespace

template <>
struct EnumNames<Color> {
  static constexpr std::array<std::pair<Color, std::string_view>, 2> values = {
      {{Color::kRed, "red"}, {Color::kGreen, "green"}}};
};

namespace {

struct TestParams {
  int count = 3;
  std::uint64_t seed = 1;
  double rate = 25;
  double weight = 0.5;
  bool flag = true;
  std::string name = "x";
  ParamList items = {"a", "b"};
  Color color = Color::kRed;
};

template <class Visitor, OptionsOf<TestParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("count", o.count, OptionSpec{.help = "a count", .min = 2, .max = 64});
  v("seed", o.seed, OptionSpec{.help = "a seed"});
  v("rate", o.rate, OptionSpec{.help = "a rate", .min = 0, .min_exclusive = true});
  v("weight", o.weight, OptionSpec{.help = "a weight", .min = 0});
  v("flag", o.flag, OptionSpec{.help = "a flag"});
  v("name", o.name, OptionSpec{.help = "a name"});
  v("items", o.items, OptionSpec{.help = "some items"});
  v("color", o.color, OptionSpec{.help = "a color"});
}

DatasetRequest Request(std::map<std::string, std::string> params) {
  DatasetRequest request;
  request.params = std::move(params);
  return request;
}

TestParams Parse(std::map<std::string, std::string> params) {
  return ParseDatasetParams<TestParams>("test", Request(std::move(params)));
}

std::string ErrorOf(std::map<std::string, std::string> params) {
  return test::ErrorMessage<ConfigError>([&] { Parse(params); });
}

TEST(DatasetParams, DefaultsComeFromTheStruct) {
  const TestParams p = Parse({});
  EXPECT_EQ(p.count, 3);
  EXPECT_EQ(p.items, (ParamList{"a", "b"}));
  EXPECT_EQ(p.color, Color::kRed);
}

TEST(DatasetParams, ParsesEveryType) {
  const TestParams p = Parse({{"count", "64"},
                              {"seed", "18446744073709551615"},
                              {"rate", "0.5"},
                              {"weight", "0"},
                              {"flag", "false"},
                              {"name", "y z"},
                              {"items", "c, d,,e"},
                              {"color", "green"}});
  EXPECT_EQ(p.count, 64);
  EXPECT_EQ(p.seed, 18446744073709551615ULL);
  EXPECT_DOUBLE_EQ(p.rate, 0.5);
  EXPECT_DOUBLE_EQ(p.weight, 0);
  EXPECT_FALSE(p.flag);
  EXPECT_EQ(p.name, "y z");
  EXPECT_EQ(p.items, (ParamList{"c", "d", "e"}));
  EXPECT_EQ(p.color, Color::kGreen);
}

// "<where>: <dataset>.<key>: '<text>' is not ..." (the codec's problems, core/option_codec.h).
TEST(DatasetParams, BadValuesNameTheParamAndTheRange) {
  EXPECT_EQ(ErrorOf({{"count", "65"}}), "--param count=65: test.count: '65' is not an integer in [2, 64]");
  EXPECT_EQ(ErrorOf({{"count", "3.5"}}), "--param count=3.5: test.count: '3.5' is not an integer in [2, 64]");
  EXPECT_THAT(ErrorOf({{"count", "3000000000"}}), HasSubstr("is not an integer in [2, 64]"));
  EXPECT_EQ(ErrorOf({{"seed", "-1"}}), "--param seed=-1: test.seed: '-1' is not an integer");
  EXPECT_EQ(ErrorOf({{"rate", "0"}}), "--param rate=0: test.rate: '0' is not a number > 0");
  EXPECT_EQ(ErrorOf({{"rate", "inf"}}), "--param rate=inf: test.rate: 'inf' is not a number > 0");
  EXPECT_EQ(ErrorOf({{"weight", "-0.1"}}), "--param weight=-0.1: test.weight: '-0.1' is not a number >= 0");
  EXPECT_EQ(ErrorOf({{"flag", "maybe"}}),
            "--param flag=maybe: test.flag: 'maybe' is not true or false (also yes/no, on/off, 1/0)");
  EXPECT_EQ(ErrorOf({{"color", "blue"}}), "--param color=blue: test.color: 'blue' is not one of red, green");
  EXPECT_EQ(ErrorOf({{"color", "gren"}}),
            "--param color=gren: test.color: 'gren' is not one of red, green (did you mean 'green'?)");
  EXPECT_EQ(ErrorOf({{"items", "[\"a\""}}),
            "--param items=[\"a\": test.items: '[\"a\"' is not a list of names ([\"a\", \"b\"] or a,b)");
}

TEST(DatasetParams, UnknownKeysListTheValidOnesAndSuggestTheNearest) {
  EXPECT_EQ(ErrorOf({{"cuont", "3"}}),
            "--param cuont=3: unknown parameter 'cuont' (did you mean 'count'?) (test has: count, seed, rate, weight, "
            "flag, name, items, color)");
  EXPECT_THAT(ErrorOf({{"zzzzzz", "1"}}), ::testing::Not(HasSubstr("did you mean")));
}

// Booleans, lists and blanks follow the codec's rules, like --set.
TEST(DatasetParams, ValuesFollowTheCodecsRules) {
  EXPECT_FALSE(Parse({{"flag", "no"}}).flag);
  EXPECT_FALSE(Parse({{"flag", "off"}}).flag);
  EXPECT_TRUE(Parse({{"flag", " yes "}}).flag);
  EXPECT_EQ(Parse({{"items", "[\"c\", \"d,e\"]"}}).items, (ParamList{"c", "d,e"}));
  EXPECT_EQ(Parse({{"items", ""}}).items, ParamList{});
  EXPECT_EQ(Parse({{"count", " 5 "}}).count, 5);
  EXPECT_DOUBLE_EQ(Parse({{"rate", "1e3"}}).rate, 1000.0);
}

TEST(DatasetParams, DescriptionCarriesDefaultsAndTypes) {
  const std::vector<DatasetParam> params = DescribeDatasetParams<TestParams>();
  ASSERT_EQ(params.size(), 8u);
  EXPECT_EQ(params[0].name, "count");
  EXPECT_EQ(params[0].default_value, "3");
  EXPECT_EQ(params[0].type, "integer in [2, 64]");
  EXPECT_EQ(params[1].type, "integer");
  EXPECT_EQ(params[2].type, "number > 0");
  EXPECT_EQ(params[3].type, "number >= 0");
  EXPECT_EQ(params[4].default_value, "true");
  EXPECT_EQ(params[6].default_value, "a,b");
  EXPECT_EQ(params[2].default_value, "25.0");
  EXPECT_EQ(params[4].type, "true | false");
  EXPECT_EQ(params[5].type, "text");
  EXPECT_EQ(params[6].type, "list of names");
  EXPECT_EQ(params[7].type, "red | green");
}

// Every reader's listed defaults are values its own parser accepts, and they parse back to the
// same text (one source of truth: the struct initialisers).
TEST(DatasetParams, EveryReaderListsParsableDefaults) {
  for (const DatasetEntry& entry : DatasetRegistry()) {
    ASSERT_FALSE(entry.info.params.empty()) << entry.info.name;
    for (const DatasetParam& p : entry.info.params) {
      EXPECT_FALSE(p.help.empty()) << entry.info.name << " " << p.name;
      EXPECT_FALSE(p.type.empty()) << entry.info.name << " " << p.name;
    }
  }
  // The synthetic reader takes its listed defaults back (the others need files on disk).
  std::map<std::string, std::string> given;
  for (const DatasetParam& p : SyntheticInfo().params) given[p.name] = p.default_value;
  given["frames"] = "2";
  DatasetRequest request = Request(given);
  EXPECT_EQ(MaterializeAll(OpenSynthetic(request)).front().frames.size(), 2u);
}

// `--param frames` of a generated scene is a count, of a dataset on disk frame indices: a range
// given to the synthetic reader is refused saying so, whatever its form.
TEST(DatasetParams, SyntheticFramesAreACountNotIndices) {
  for (const std::string frames : {"0-12", "0,5", "0-30:2"}) {
    EXPECT_THAT(test::ErrorMessage<ConfigError>([&] { MaterializeAll(OpenSynthetic(Request({{"frames", frames}}))); }),
                HasSubstr("--param frames=" + frames + ": synthetic.frames is the number of frames to generate "
                          "(frames=N: frames 0 to N-1)"));
  }
  EXPECT_EQ(MaterializeAll(OpenSynthetic(Request({{"frames", "13"}}))).front().frames.size(), 13u);
}

// `rpt demo --seed` takes any uint64; so does the synthetic reader (it used to stop at 2^31 - 1).
TEST(DatasetParams, SyntheticSeedTakesTheFullRange) {
  const DatasetRequest request = Request({{"frames", "1"}, {"seed", "3000000000"}});
  EXPECT_EQ(ParseDatasetParams<SyntheticParams>("synthetic", request).seed, 3000000000ULL);
  EXPECT_EQ(MaterializeAll(OpenSynthetic(request)).front().frames.size(), 1u);
  EXPECT_THAT(test::ErrorMessage<ConfigError>([] {
                MaterializeAll(OpenSynthetic(Request({{"noise", "noisy"}})));
              }),
              HasSubstr("synthetic.noise: 'noisy' is not one of perfect, clean, realistic, hard, none"));
  EXPECT_THAT(test::ErrorMessage<ConfigError>([] {
                MaterializeAll(OpenSynthetic(Request({{"camras", "3"}})));
              }),
              HasSubstr("did you mean 'cameras'?"));
}

}  // namespace
}  // namespace rpt
