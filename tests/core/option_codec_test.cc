// SPDX-License-Identifier: MIT
// The option codec (core/option_codec.h): what each field type accepts and refuses, the problem
// texts, the formatting that reads back, the type and range descriptions, and the Check()
// helpers of core/options_check.h.
#include "core/option_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/closest_name.h"
#include "core/options_check.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

enum class Shade { kLight, kDark };

}  // namespace

template <>
struct EnumNames<Shade> {
  static constexpr std::array<std::pair<Shade, std::string_view>, 2> values = {
      {{Shade::kLight, "light"}, {Shade::kDark, "dark"}}};
};

namespace {

using Names = std::vector<std::string>;

constexpr OptionSpec kUnit{.min = 0, .max = 1};
constexpr OptionSpec kPositive{.min = 0, .min_exclusive = true};
constexpr OptionSpec kCount{.min = 2, .max = 64};

// The problem ParseOption reports for `text` as a T ("" when accepted).
template <class T>
std::string ProblemOf(std::string_view text, const OptionSpec& spec = {}) {
  T value{};
  return ParseOption(text, spec, &value);
}

template <class T>
T Parsed(std::string_view text, const OptionSpec& spec = {}) {
  T value{};
  const std::string problem = ParseOption(text, spec, &value);
  EXPECT_EQ(problem, "") << text;
  return value;
}

TEST(OptionCodec, BooleansTakeOneVocabulary) {
  for (const char* text : {"true", "yes", "on", "1", " true "}) EXPECT_TRUE(Parsed<bool>(text)) << text;
  for (const char* text : {"false", "no", "off", "0", "\toff"}) EXPECT_FALSE(Parsed<bool>(text)) << text;
  for (const char* text : {"maybe", "", "True", "2", "y"}) {
    EXPECT_EQ(ProblemOf<bool>(text), "'" + std::string(text) + "' is not true or false (also yes/no, on/off, 1/0)");
  }
}

TEST(OptionCodec, IntegersAreWholeDecimalNumbersInRange) {
  EXPECT_EQ(Parsed<int>("64", kCount), 64);
  EXPECT_EQ(Parsed<int>("+3", kCount), 3);
  EXPECT_EQ(Parsed<int>(" 2 ", kCount), 2);
  EXPECT_EQ(Parsed<int>("-2147483648"), std::numeric_limits<int>::min());
  for (const char* text : {"65", "1", "3.0", "1e3", "", "0x10", "+-3", "3 4", "nan", "3000000000"}) {
    EXPECT_EQ(ProblemOf<int>(text, kCount), "'" + std::string(text) + "' is not an integer in [2, 64]") << text;
  }
  EXPECT_EQ(ProblemOf<int>("2147483648"), "'2147483648' is not an integer");
  EXPECT_EQ(ProblemOf<int>("0", OptionSpec{.min = 1}), "'0' is not an integer >= 1");
  EXPECT_EQ(Parsed<std::uint64_t>("18446744073709551615"), 18446744073709551615ULL);
  EXPECT_EQ(ProblemOf<std::uint64_t>("-1"), "'-1' is not an integer");
  EXPECT_EQ(ProblemOf<std::uint64_t>("18446744073709551616"), "'18446744073709551616' is not an integer");
}

TEST(OptionCodec, NumbersAreFiniteAndInRange) {
  EXPECT_DOUBLE_EQ(Parsed<double>("0.25", kUnit), 0.25);
  EXPECT_DOUBLE_EQ(Parsed<double>("1e3"), 1000.0);
  EXPECT_DOUBLE_EQ(Parsed<double>(".5"), 0.5);
  EXPECT_DOUBLE_EQ(Parsed<double>("+2"), 2.0);
  EXPECT_DOUBLE_EQ(Parsed<double>("1", kUnit), 1.0);  // inclusive bounds
  EXPECT_DOUBLE_EQ(Parsed<double>("1e-300", kPositive), 1e-300);
  for (const char* text : {"1.5", "-0.1", "nan", "inf", "-inf", "", "x", "1,5", "0.5x"}) {
    EXPECT_EQ(ProblemOf<double>(text, kUnit), "'" + std::string(text) + "' is not a number in [0, 1]") << text;
  }
  EXPECT_EQ(ProblemOf<double>("0", kPositive), "'0' is not a number > 0");
  EXPECT_EQ(ProblemOf<double>("nan"), "'nan' is not a number");
  EXPECT_EQ(ProblemOf<double>("infinity"), "'infinity' is not a number");
  EXPECT_EQ(ProblemOf<double>("4", OptionSpec{.max = 3}), "'4' is not a number <= 3");
  EXPECT_EQ(ProblemOf<double>("0", OptionSpec{.min = 0, .max = 1, .min_exclusive = true}),
            "'0' is not a number in (0, 1]");
}

TEST(OptionCodec, ListsAreJsonOrCommaLists) {
  EXPECT_EQ(Parsed<Names>(" a , b "), (Names{"a", "b"}));
  EXPECT_EQ(Parsed<Names>("a,,b,"), (Names{"a", "b"}));
  EXPECT_EQ(Parsed<Names>(""), Names{});
  EXPECT_EQ(Parsed<Names>("[]"), Names{});
  EXPECT_EQ(Parsed<Names>(" [ \"a\" , \"b c\" ] "), (Names{"a", "b c"}));
  EXPECT_EQ(Parsed<Names>(R"(["x,y", "q\"\\\u00e9\ud83d\ude00"])"), (Names{"x,y", "q\"\\\xc3\xa9\xf0\x9f\x98\x80"}));
  const std::string list_problem = " is not a list of names ([\"a\", \"b\"] or a,b)";
  for (const char* text :
       {"[\"a\",\"b\"", "[1, 2]", "[a, b]", "[\"a\"] x", "[\"a\",]", "[,]", "[\"\\q\"]", "[\"\\ud800\"]"}) {
    EXPECT_EQ(ProblemOf<Names>(text), "'" + std::string(text) + "'" + list_problem) << text;
  }
}

TEST(OptionCodec, VectorsAreThreeNumbers) {
  EXPECT_EQ(Parsed<Eigen::Vector3d>("8,8,3"), Eigen::Vector3d(8, 8, 3));
  EXPECT_EQ(Parsed<Eigen::Vector3d>("[1.5, -2, 1e3]"), Eigen::Vector3d(1.5, -2, 1000));
  EXPECT_EQ(Parsed<Eigen::Vector3d>(" 1 , 2 , 3 "), Eigen::Vector3d(1, 2, 3));
  for (const char* text : {"1,2", "1,2,3,4", "[1, 2]", "1,nan,3", "[\"1\", 2, 3]", "", "[1,2,3"}) {
    EXPECT_EQ(ProblemOf<Eigen::Vector3d>(text), "'" + std::string(text) + "' is not three numbers [x, y, z] (or x,y,z)")
        << text;
  }
}

TEST(OptionCodec, EnumerationsTakeTheirNamesWithADidYouMean) {
  EXPECT_EQ(Parsed<Shade>("dark"), Shade::kDark);
  EXPECT_EQ(Parsed<Shade>(" light "), Shade::kLight);
  EXPECT_EQ(ProblemOf<Shade>("drak"), "'drak' is not one of light, dark (did you mean 'dark'?)");
  EXPECT_EQ(ProblemOf<Shade>("blue"), "'blue' is not one of light, dark");
  EXPECT_EQ(ProblemOf<Shade>(""), "'' is not one of light, dark");
}

TEST(OptionCodec, TextIsTakenAsWrittenWithoutSurroundingBlanks) {
  EXPECT_EQ(Parsed<std::string>(" y z "), "y z");
  EXPECT_EQ(Parsed<std::string>("[1,2"), "[1,2");
  EXPECT_EQ(Parsed<std::string>(""), "");
}

TEST(OptionCodec, RefusedTextsLeaveTheValueAlone) {
  int count = 7;
  EXPECT_NE(ParseOption("x", kCount, &count), "");
  EXPECT_EQ(count, 7);
  Names names = {"keep"};
  EXPECT_NE(ParseOption("[1]", {}, &names), "");
  EXPECT_EQ(names, Names{"keep"});
}

TEST(OptionCodec, NumbersAreFormattedAsJsonWritesThem) {
  EXPECT_EQ(FormatNumber(0.5), "0.5");
  EXPECT_EQ(FormatNumber(25.0), "25.0");
  EXPECT_EQ(FormatNumber(-2.0), "-2.0");
  EXPECT_EQ(FormatNumber(0.0), "0.0");
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(1e9), "1000000000.0");
  EXPECT_EQ(FormatNumber(123456789012345.0), "123456789012345.0");
  EXPECT_EQ(FormatNumber(1e15), "1e+15");
  EXPECT_EQ(FormatNumber(1e16), "1e+16");
  EXPECT_EQ(FormatNumber(1.5e300), "1.5e+300");
  EXPECT_EQ(FormatNumber(0.0001), "0.0001");
  EXPECT_EQ(FormatNumber(0.00001), "1e-05");
  EXPECT_EQ(FormatNumber(-1.25e-7), "-1.25e-07");
  EXPECT_EQ(FormatNumber(std::nan("")), "nan");
  EXPECT_EQ(FormatNumber(-HUGE_VAL), "-inf");
}

TEST(OptionCodec, FormattedValuesReadBack) {
  for (const double value : {0.1, 1.0 / 3.0, 1e-300, 6.02214076e23, -0.0, 12345.678}) {
    EXPECT_EQ(Parsed<double>(FormatOption(value)), value) << FormatOption(value);
  }
  EXPECT_EQ(FormatOption(true), "true");
  EXPECT_EQ(FormatOption(-3), "-3");
  EXPECT_EQ(FormatOption(std::uint64_t{18446744073709551615ULL}), "18446744073709551615");
  EXPECT_EQ(FormatOption(Shade::kDark), "dark");
  EXPECT_EQ(FormatOption(Eigen::Vector3d(8, 8, 3)), "8.0,8.0,3.0");
  EXPECT_EQ(FormatOption(Names{"a", "b"}), "a,b");
  EXPECT_EQ(FormatOption(Names{}), "");
  // Names a comma list cannot hold are written as a JSON list.
  for (const Names& names : {Names{"x,y", "z"}, Names{"", "a"}, Names{" a"}, Names{"[a", "b"}, Names{"q\"\n"}}) {
    EXPECT_EQ(FormatOption(names).front(), '[') << FormatOption(names);
    EXPECT_EQ(Parsed<Names>(FormatOption(names)), names) << FormatOption(names);
  }
}

TEST(OptionCodec, TypesAndRangesAreDescribedInTheWordsOfTheProblems) {
  EXPECT_EQ(OptionTypeText<int>(kCount), "integer in [2, 64]");
  EXPECT_EQ(OptionTypeText<std::uint64_t>({}), "integer");
  EXPECT_EQ(OptionTypeText<double>(kPositive), "number > 0");
  EXPECT_EQ(OptionTypeText<double>(OptionSpec{.min = 0}), "number >= 0");
  EXPECT_EQ(OptionTypeText<double>(OptionSpec{.min = 0, .max = 1e9}), "number in [0, 1000000000]");
  EXPECT_EQ(OptionTypeText<double>(OptionSpec{.min = 0.5, .max = 2.5}), "number in [0.5, 2.5]");
  EXPECT_EQ(OptionTypeText<bool>({}), "true | false");
  EXPECT_EQ(OptionTypeText<std::string>({}), "text");
  EXPECT_EQ(OptionTypeText<Names>({}), "list of names");
  EXPECT_EQ(OptionTypeText<Eigen::Vector3d>({}), "[x, y, z]");
  EXPECT_EQ(OptionTypeText<Shade>({}), "light | dark");
  EXPECT_EQ(OptionRangeText(OptionSpec{.min = 0, .max = 1, .min_exclusive = true}), "(0, 1]");
  EXPECT_EQ(OptionRangeText(OptionSpec{.max = 3}), "<= 3");
  EXPECT_EQ(OptionRangeText({}), "");
  EXPECT_EQ(OptionMessage("--set a.b=x", "a.b", "'x' is not a number"), "--set a.b=x: a.b: 'x' is not a number");
}

TEST(OptionCodec, SplitListTrimsAndDropsEmptyItems) {
  EXPECT_EQ(SplitList(" a , b ,, c,"), (Names{"a", "b", "c"}));
  EXPECT_EQ(SplitList(""), Names{});
  EXPECT_EQ(SplitList(" , "), Names{});
  EXPECT_EQ(SplitList("a"), Names{"a"});
}

TEST(OptionCodec, UnknownNamesGetOneMessage) {
  EXPECT_EQ(UnknownNameProblem("parameter", "cuont", {"count", "seed"}, "test has: count, seed"),
            "unknown parameter 'cuont' (did you mean 'count'?) (test has: count, seed)");
  EXPECT_EQ(UnknownNameProblem("option", "zzz", {"count"}, "sections: a"), "unknown option 'zzz' (sections: a)");
}

// Check(): values set in code are reported in the codec's words, as "section.key: problem".
struct Sample {
  int count = 3;
  double weight = 0.5;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  Shade shade = Shade::kLight;
  std::string Check() const;
};

template <class Visitor, OptionsOf<Sample> Self>
void VisitFields(Visitor& v, Self& o) {
  v("count", o.count, kCount);
  v("weight", o.weight, kUnit);
  v("size", o.size, OptionSpec{});
  v("shade", o.shade, OptionSpec{});
}

std::string Sample::Check() const {
  OptionsChecker checker("sample");
  VisitFields(checker, *this);
  if (count == 4) checker.Require("is unlucky", "count");
  return checker.error();
}

TEST(OptionCodec, CheckReportsTheFirstProblemAsSectionKey) {
  Sample sample;
  EXPECT_EQ(sample.Check(), "");
  EXPECT_NO_THROW(ThrowIfInvalid(sample));
  sample.weight = std::nan("");
  EXPECT_EQ(sample.Check(), "sample.weight: 'nan' is not a number in [0, 1]");
  sample.count = 65;
  EXPECT_EQ(sample.Check(), "sample.count: '65' is not an integer in [2, 64]");
  EXPECT_EQ(test::ConfigErrorOf([&] { ThrowIfInvalid(sample); }), "sample.count: '65' is not an integer in [2, 64]");
  sample = {};
  sample.weight = 2;
  EXPECT_EQ(CheckOptionRanges("sample", sample), "sample.weight: '2.0' is not a number in [0, 1]");
  sample = {};
  sample.size.y() = HUGE_VAL;
  EXPECT_EQ(sample.Check(), "sample.size: '1.0,inf,1.0' is not three numbers [x, y, z] (or x,y,z)");
  sample = {};
  sample.count = 4;
  EXPECT_EQ(sample.Check(), "sample.count: is unlucky");
}

}  // namespace
}  // namespace rpt
