// SPDX-License-Identifier: MIT
#include "datasets/io/json_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "core/errors.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt::io {
namespace {

using ::testing::HasSubstr;


test::ByteVec Text(const std::string& s) { return test::ByteVec(s.begin(), s.end()); }

TEST(Json, LoadAndFetchTypedValues) {
  test::TempDir dir;
  const auto path = dir.Write("calibration_shelf.json", Text(R"({
  "0": {"R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "T": [[10], [20], [30]], "fx": 1000.5,
        "name": "cam0", "w": 1032, "flat": [1, 2, 3, 4, 5, 6, 7, 8, 9], "ok": true},
  "a/b": {"x~y": 4}
})"));
  const nlohmann::json root = LoadJsonFile(path);
  const std::string src = "calibration_shelf.json";
  EXPECT_EQ(JsonMatrix(root, "/0/R", src, 3, 3), (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(JsonMatrix(root, "/0/T", src, 3, 1), (std::vector<double>{10, 20, 30}));
  EXPECT_EQ(JsonMatrix(root, "/0/flat", src, 3, 3)[5], 6.0);
  EXPECT_DOUBLE_EQ(JsonNumber(root, "/0/fx", src), 1000.5);
  EXPECT_EQ(JsonInt(root, "/0/w", src), 1032);
  EXPECT_EQ(JsonString(root, "/0/name", src), "cam0");
  EXPECT_TRUE(JsonBool(root, "/0/ok", src));
  EXPECT_EQ(JsonNumbers(root, "/0/flat", src, 9).size(), 9u);
  EXPECT_EQ(JsonPointerJoin(JsonPointerJoin("", "a/b"), "x~y"), "/a~1b/x~0y");
  EXPECT_EQ(JsonInt(root, JsonPointerJoin(JsonPointerJoin("", "a/b"), "x~y"), src), 4);
  EXPECT_EQ(JsonPointerJoin("/list", 3), "/list/3");
  EXPECT_EQ(JsonFind(root, "/1/R"), nullptr);
  EXPECT_EQ(JsonFind(root, "not a pointer"), nullptr);
  EXPECT_NE(JsonFind(root, ""), nullptr);
}

TEST(Json, TypedErrorsNameFileAndPointer) {
  const nlohmann::json root = ParseJsonText(R"([{"R": [[1, 0], [0, 1]], "fx": "big", "w": 1.5, "k": [1, "x"]}])", "calibration_shelf.json");
  const std::string src = "calibration_shelf.json";
  EXPECT_THAT(test::InputErrorOf([&] { JsonMatrix(root, "/0/R", src, 3, 3); }),
              HasSubstr("calibration_shelf.json: /0/R: expected 3x3 array of numbers, got 2 rows"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonNumber(root, "/0/fx", src); }), HasSubstr("calibration_shelf.json: /0/fx: expected a number, got string"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonInt(root, "/0/w", src); }), HasSubstr("/0/w: expected an integer, got 1.5"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonNumber(root, "/0/T", src); }), HasSubstr("calibration_shelf.json: /0/T: missing"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonNumbers(root, "/0/k", src); }), HasSubstr("/0/k: expected an array of numbers, found string at index 1"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonNumbers(root, "/0/R/0", src, 3); }), HasSubstr("/0/R/0: expected an array of 3 numbers, got 2 elements"));
  EXPECT_THAT(test::InputErrorOf([&] { JsonString(root, "", src); }), HasSubstr("calibration_shelf.json: /: expected a string, got array"));
}

TEST(Json, ParseErrorsNameLineAndColumn) {
  test::TempDir dir;
  const auto path = dir.Write("broken.json", Text("{\n  \"a\": 1,\n  \"b\": [1, 2,, 3]\n}\n"));
  const std::string msg = test::InputErrorOf([&] { LoadJsonFile(path); });
  EXPECT_THAT(msg, HasSubstr("broken.json:3:14: JSON parse error"));
  EXPECT_THAT(test::InputErrorOf([] { ParseJsonText("", "empty.json"); }), HasSubstr("empty.json:1:1: JSON parse error"));
  EXPECT_THAT(test::InputErrorOf([] { LoadJsonFile("/nonexistent/calibration.json"); }), HasSubstr("/nonexistent/calibration.json: file not found"));
}

// A key given twice in one object is refused at the second (nlohmann kept the last value: a second
// "views": [] emptied a frame unseen); the same key in different objects, or once per level, is fine.
TEST(Json, AKeyTwiceInOneObjectIsRefusedAtTheSecond) {
  EXPECT_THAT(test::InputErrorOf([] {
                ParseJsonText("{\"frames\": [{\"id\": 1, \"views\": [1],\n \"views\": []}]}", "d.json");
              }),
              HasSubstr("d.json:2:2: key 'views' appears twice in this object"));
  EXPECT_THAT(test::InputErrorOf([] { CheckJsonText("{\"K\": 1, \"a\": {\"K\": 2}, \"K\": 3}", "c.json"); }),
              HasSubstr("c.json:1:25: key 'K' appears twice"));
  // Many keys (a set past 32 of them), and the repeat among them.
  std::string many = "{";
  for (int i = 0; i < 100; ++i) many += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
  EXPECT_NO_THROW(ParseJsonText(many + "\"last\": 0}", "many.json"));
  EXPECT_THAT(test::InputErrorOf([&] { ParseJsonText(many + "\"k7\": 0}", "many.json"); }),
              HasSubstr("key 'k7' appears twice"));
  const nlohmann::json fine =
      ParseJsonText(R"([{"id": 1, "a": {"id": 2, "b": {"id": 3}}}, {"id": 4}, {"a": {"id": 5}, "id": 6}])", "fine.json");
  EXPECT_EQ(fine[2]["id"], 6);
}

TEST(JsonFixture, ShelfCalibration) {
  RPT_REQUIRE_SHARED_DATA("shelf/calibration_shelf.json");
  const auto path = test::SharedData("shelf/calibration_shelf.json");
  const nlohmann::json root = LoadJsonFile(path);
  const std::string src = path.string();
  ASSERT_EQ(root.size(), 5u);
  const auto R = JsonMatrix(root, "/0/R", src, 3, 3);
  double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) + R[2] * (R[3] * R[7] - R[4] * R[6]);
  EXPECT_NEAR(det, 1.0, 1e-6);
  EXPECT_EQ(JsonMatrix(root, "/0/T", src, 3, 1).size(), 3u);
  EXPECT_GT(JsonNumber(root, "/0/fx", src), 100.0);
  EXPECT_EQ(JsonMatrix(root, "/0/k", src, 3, 1), (std::vector<double>{0, 0, 0}));
}

}  // namespace
}  // namespace rpt::io

namespace rpt::io {
namespace {

std::string Nested(int depth, const std::string& open, char close) {
  std::string text;
  for (int i = 0; i < depth; ++i) text += open;
  text += "1";
  return text + std::string(static_cast<std::size_t>(depth), close);
}

// Deep nesting stopped the process (exit 139) wherever a value was serialised or destroyed
// recursively: the parse itself stops at kMaxJsonDepth, naming the line and column of the opener.
TEST(JsonDepthLimit, DeeperThanTheLimitIsAnInputErrorAtTheOpener) {
  EXPECT_NO_THROW(ParseJsonText(Nested(kMaxJsonDepth, "[", ']'), "ok.json"));
  EXPECT_NO_THROW(CheckJsonText(Nested(kMaxJsonDepth, "{\"a\":", '}'), "ok.json"));
  EXPECT_THAT(test::InputErrorOf([] { ParseJsonText(Nested(kMaxJsonDepth + 1, "[", ']'), "a.json"); }),
              HasSubstr("a.json:1:257: JSON nested deeper than 256 levels"));
  EXPECT_THAT(test::InputErrorOf([] { ParseJsonText("{\"x\":\n  " + Nested(70000, "{\"a\":", '}') + "}", "b.json"); }),
              HasSubstr("b.json:2:"));
  EXPECT_THAT(test::InputErrorOf([] { CheckJsonText(Nested(100000, "[", ']'), "c.json"); }),
              HasSubstr("c.json:1:257: JSON nested deeper than 256"));
  // Brackets inside strings do not count.
  EXPECT_NO_THROW(ParseJsonText("[\"" + std::string(1000, '[') + "\"]", "d.json"));
  test::TempDir dir;
  const auto path = dir.Write("run.json", Text("{\"a\": " + Nested(50000, "[", ']') + "}"));
  EXPECT_THAT(test::InputErrorOf([&] { LoadOrderedJsonFile(path); }), HasSubstr("run.json:1:"));
  EXPECT_THAT(test::InputErrorOf([&] { LoadJsonFile(path); }), HasSubstr("nested deeper than 256 levels"));
}

// Messages quote at most a short excerpt: of a value (JsonExcerpt) and of the token a parse error
// stopped at (a string token runs to the end of its line, a number as long as its digits).
TEST(JsonExcerpt, ValuesAndTokensAreQuotedShort) {
  EXPECT_EQ(JsonExcerpt(nlohmann::json::parse("[1, 2, {\"a\": 3}]")), "[1,2,{\"a\":3}]") << "as dump() writes it";
  EXPECT_EQ(JsonExcerpt(nlohmann::json("abc")), "\"abc\"");
  nlohmann::json big = nlohmann::json::array();
  for (int i = 0; i < 100000; ++i) big.push_back(i);
  EXPECT_EQ(JsonExcerpt(big, 20), "[0,1,2,3,4,5,6,7,8,9...");
  const nlohmann::json deep = ParseJsonText(Nested(200, "[", ']'), "x");
  EXPECT_EQ(JsonExcerpt(deep, 10), std::string(10, '[') + "...");
  EXPECT_EQ(JsonExcerpt(nlohmann::json(std::string(1000, 'x')), 8), "\"xxxxxxx...");
  // Cut at a character boundary: never half of "é".
  EXPECT_EQ(JsonExcerpt(nlohmann::json("\xc3\xa9\xc3\xa9\xc3\xa9"), 4), "\"\xc3\xa9...");
  const nlohmann::ordered_json ordered = {{"k", std::string(500, 'v')}};
  EXPECT_LE(JsonExcerpt(ordered).size(), kMaxQuotedBytes + 3);

  const std::string long_line = "[\"" + std::string(100000, 's') + "\n\"]";
  const std::string message = test::InputErrorOf([&] { ParseJsonText(long_line, "line.json"); });
  EXPECT_THAT(message, HasSubstr("line.json:1:"));
  EXPECT_LT(message.size(), 300u) << message.substr(0, 300);
  const std::string number = test::InputErrorOf([] { ParseJsonText("[1" + std::string(5000, '0') + "e400]", "n.json"); });
  EXPECT_THAT(number, HasSubstr("number overflow parsing '1000000000"));
  EXPECT_LT(number.size(), 200u) << number.substr(0, 300);
}

// Only regular files are read whole: a FIFO blocked the read forever, a folder is named as such.
TEST(JsonFileType, OnlyRegularFilesAreRead) {
  test::TempDir dir;
  const auto fifo = dir.path() / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(test::InputErrorOf([&] { LoadJsonFile(fifo); }), HasSubstr("fifo.json: not a regular file"));
  EXPECT_THAT(test::InputErrorOf([&] { LoadOrderedJsonFile(fifo); }), HasSubstr("fifo.json: not a regular file"));
  EXPECT_THAT(test::InputErrorOf([&] { LoadJsonFile(dir.path()); }), HasSubstr("is a directory"));
}

}  // namespace
}  // namespace rpt::io
