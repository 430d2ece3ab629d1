// SPDX-License-Identifier: MIT
#include "datasets/io/json_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
