// SPDX-License-Identifier: MIT
// Numbers out of range and values out of order in input files (issue 10, finding 5): JSON number
// overflows, integers beyond int64 or int, timestamps that do not increase, duplicate body ids,
// wrong-typed fields are errors naming file and place; implausible cameras are counted warnings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "datasets/io/json_file.h"
#include "datasets/readers/coco_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/voxelpose_calibration.h"
#include "tests/datasets/readers_generic_test_util.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using test::InputErrorOf;
using test::WriteText;

TEST(InputRanges, JsonNumberOverflowIsAParseErrorWithLineAndColumn) {
  // nlohmann reports 1e400 as out_of_range.406, which escaped as an internal error (exit 1).
  EXPECT_THAT(InputErrorOf([] { io::ParseJsonText("[1,\n 1e400]", "big.json"); }),
              HasSubstr("big.json:2:6: JSON parse error: number overflow parsing '1e400'"));
  EXPECT_THAT(InputErrorOf([] { io::ParseJsonText("{\"T\": -1e400}", "big.json"); }),
              HasSubstr("big.json:1:12: JSON parse error: number overflow parsing '-1e400'"));
  test::TempDir dir;
  const auto path = WriteText(dir, "labels.json", "[{\"id\": 1e400}]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(path)); }),
              HasSubstr("labels.json:1:13: JSON parse error: number overflow"));
  // Ordinary parse errors keep their message.
  EXPECT_THAT(InputErrorOf([] { io::ParseJsonText("[1,]", "x.json"); }), HasSubstr("x.json:1:4: JSON parse error: syntax error"));
}

TEST(InputRanges, JsonIntRefusesValuesOutsideInt64) {
  const nlohmann::json root = io::ParseJsonText(
      R"({"max": 9223372036854775807, "min": -9223372036854775808, "over": 9223372036854775813,
          "float_ok": 4.0, "two63": 9223372036854775808.0, "huge": 1e30, "frac": 2.5})",
      "ids.json");
  EXPECT_EQ(io::JsonInt(root, "/max", "ids.json"), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(io::JsonInt(root, "/min", "ids.json"), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(io::JsonInt(root, "/float_ok", "ids.json"), 4);
  EXPECT_THAT(InputErrorOf([&] { io::JsonInt(root, "/over", "ids.json"); }),
              HasSubstr("ids.json: /over: integer 9223372036854775813 is outside the 64-bit signed range"));
  EXPECT_THAT(InputErrorOf([&] { io::JsonInt(root, "/two63", "ids.json"); }), HasSubstr("ids.json: /two63: integer"));
  EXPECT_THAT(InputErrorOf([&] { io::JsonInt(root, "/huge", "ids.json"); }), HasSubstr("ids.json: /huge: integer 1e+30 is outside"));
  EXPECT_THAT(InputErrorOf([&] { io::JsonInt(root, "/frac", "ids.json"); }), HasSubstr("ids.json: /frac: expected an integer, got 2.5"));
  EXPECT_THAT(InputErrorOf([&] { io::JsonIntIn(root, "/float_ok", "ids.json", 0, 3); }),
              HasSubstr("ids.json: /float_ok: 4 is not an integer in [0, 3]"));
}

TEST(InputRanges, CocoImageIdBeyondInt64IsRefusedNotNegative) {
  test::TempDir dir;
  const auto results = WriteText(dir, "results.json",
                                 R"([{"image_id": 9223372036854775813, "category_id": 1, "score": 0.9, "keypoints": [1, 2, 1]}])");
  const std::string error = InputErrorOf([&] { ReadCocoDetections(results); });
  EXPECT_THAT(error, HasSubstr("results.json: /0/image_id: expected an integer image id in the 64-bit signed range, got 9223372036854775813"));
  EXPECT_THAT(error, Not(HasSubstr("-9223372036854775803")));
}

// AlphaPose writes the image's file name as its id: named as a name, with where to go ("7" as a
// string of digits stays an id).
TEST(InputRanges, CocoImageIdThatIsAFileNameSaysWhatToWrite) {
  test::TempDir dir;
  const auto results = WriteText(dir, "alphapose.json",
                                 R"([{"image_id": "000001.jpg", "category_id": 1, "score": 0.9, "keypoints": [1, 2, 1]}])");
  const std::string error = InputErrorOf([&] { ReadCocoDetections(results); });
  EXPECT_THAT(error, HasSubstr("alphapose.json: /0/image_id: image id \"000001.jpg\" is a name, not a number"));
  EXPECT_THAT(error, HasSubstr("generic detections JSON"));
}

// One generic label of scene S with a camera at `center` (metres) and distortion `dc`, and extra members.
std::string Label(const std::string& id, const std::string& extra, const std::string& center = "0, 0, -3",
                  const std::string& dc = "0.1, 0, 0, 0, 0") {
  return R"({"id": ")" + id + R"(", "scene": "S", "joints": ["nose"], "bodies3D": [[[0, 0, 1, 1]], [[1, 0, 1, 1]]],
   "cameras": [{"name": "c", "K": [[900, 0, 500], [0, 900, 400], [0, 0, 1]], "DC": [)" + dc + R"(],
                "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "T": [)" + center + R"(], "width": 1000, "height": 800}])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

TEST(InputRanges, GenericLabelTimestampsMustIncrease) {
  test::TempDir dir;
  const auto ok = WriteText(dir, "ok.json", "[" + Label("a", R"("timestamp": 1.0)") + "," + Label("b", R"("timestamp": 1.04)") + "]");
  EXPECT_EQ(MaterializeAll(OpenLabels(ok))[0].frames.size(), 2u);
  const auto decreasing = WriteText(dir, "dec.json", "[" + Label("a", R"("timestamp": 1.0)") + "," + Label("b", R"("timestamp": 0.5)") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(decreasing)); }),
              HasSubstr("dec.json: /1/timestamp: timestamp 0.5 does not increase (the previous label of sequence 'S', "
                        "'a', has 1.0)"));
  const auto repeated = WriteText(dir, "rep.json", "[" + Label("a", R"("timestamp": 2)") + "," + Label("b", R"("timestamp": 2)") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(repeated)); }),
              HasSubstr("rep.json: /1/timestamp: timestamp 2.0 does not increase"));
}

TEST(InputRanges, GenericLabelBodyIdsAreUniqueIntsPerFrame) {
  test::TempDir dir;
  const auto ok = WriteText(dir, "ok.json", "[" + Label("a", R"("bodyids": [7, -1])") + "]");
  EXPECT_EQ(MaterializeAll(OpenLabels(ok))[0].frames[0].gt.track_ids, (std::vector<int>{7, -1}));
  const auto duplicate = WriteText(dir, "dup.json", "[" + Label("a", R"("bodyids": [7, 7])") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(duplicate)); }),
              HasSubstr("dup.json: /0/bodyids/1: body id 7 is also the id of person 0"));
  const auto huge = WriteText(dir, "huge.json", "[" + Label("a", R"("bodyids": [4294967296, 1])") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(huge)); }),
              HasSubstr("huge.json: /0/bodyids/0: 4294967296 is not an integer in [-1, 2147483647]"));
}

TEST(InputRanges, GenericLabelSplitsMustBeAListOfNames) {
  test::TempDir dir;
  LabelsOptions options;
  options.split = "test";
  const auto string = WriteText(dir, "s.json", "[" + Label("a", R"("splits": "test")") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(string, options)); }),
              HasSubstr("s.json: /0/splits: expected a list of split names (e.g. [\"test\"]), got string"));
  const auto number = WriteText(dir, "n.json", "[" + Label("a", R"("splits": ["test", 3])") + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(number, options)); }),
              HasSubstr("n.json: /0/splits/1: expected a split name, got number"));
  const auto list = WriteText(dir, "l.json", "[" + Label("a", R"("splits": ["train", "test"])") + "]");
  EXPECT_EQ(MaterializeAll(OpenLabels(list, options))[0].frames.size(), 1u);
}

TEST(InputRanges, ImplausibleCamerasAreCountedWarnings) {
  test::TempDir dir;
  LabelsOptions timed;  // times known: the warnings are the cameras' only
  timed.fps = 25;
  const auto plausible = WriteText(dir, "near.json", "[" + Label("a", "", "0, 900, -3") + "]");
  EXPECT_TRUE(MaterializeAll(OpenLabels(plausible, timed))[0].warnings.empty());
  const auto far = WriteText(dir, "far.json", "[" + Label("a", "", "0, 0, 1e300") + "]");
  const InputWarnings far_warnings = MaterializeAll(OpenLabels(far, timed))[0].warnings;
  ASSERT_EQ(far_warnings.items().size(), 1u);
  EXPECT_EQ(far_warnings.items()[0].Line(), far.string() + ": 1 cameras more than 1 km from the origin (check the units of T) (max |T| in m = 1e+300)");
  const auto km = WriteText(dir, "km.json", "[" + Label("a", "", "0, 1500, 0") + "]");
  ASSERT_EQ(MaterializeAll(OpenLabels(km, timed))[0].warnings.items().size(), 1u);
  const auto distorted = WriteText(dir, "dist.json", "[" + Label("a", "", "0, 0, -3", "1e10, 0, 0, 0, 0") + "]");
  const InputWarnings dist_warnings = MaterializeAll(OpenLabels(distorted, timed))[0].warnings;
  ASSERT_EQ(dist_warnings.items().size(), 1u);
  EXPECT_EQ(dist_warnings.items()[0].Line(), distorted.string() + ": 1 cameras with a distortion coefficient beyond +-100 (max |coefficient| = 1e+10)");
}

std::string VoxelPoseCamera(const std::string& t_mm, const std::string& intrinsics) {
  return R"({"R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "T": [[)" + t_mm + R"(]], )" + intrinsics +
         R"(, "k": [[0], [0], [0]], "p": [[0], [0]]})";
}

TEST(InputRanges, VoxelPoseCalibrationFarCameraWarnsAndMissingCxNamesThePlace) {
  test::TempDir dir;
  const std::string intrinsics = R"("fx": 1000, "fy": 1000, "cx": 500, "cy": 400)";
  const auto far = WriteText(dir, "far.json", "{\"0\": " + VoxelPoseCamera("0], [0], [2e6", intrinsics) + "}");  // 2 km in mm
  InputWarnings warnings;
  ASSERT_EQ(ReadVoxelPoseCalibration(far, 1000, 800, &warnings).size(), 1u);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_THAT(warnings.items()[0].Line(), HasSubstr("1 cameras more than 1 km from the origin"));
  // Debug builds asserted in Eigen's comma initialiser when a value in its middle was missing.
  const auto no_cx = WriteText(dir, "no_cx.json", "{\"0\": " + VoxelPoseCamera("0], [0], [0", R"("fx": 1000, "fy": 1000, "cy": 400)") + "}");
  EXPECT_THAT(InputErrorOf([&] { ReadVoxelPoseCalibration(no_cx, 1000, 800); }), HasSubstr("no_cx.json: /0/cx: missing"));
}

}  // namespace
}  // namespace rpt
