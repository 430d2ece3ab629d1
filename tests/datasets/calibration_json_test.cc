// SPDX-License-Identifier: MIT
// Our cameras JSON (datasets/calibration/cameras_json.h) through ReadCalibration /
// WriteCalibration: the hand-built camera, every lens model round-tripped, labels files, the
// description, format detection and errors with file and place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/errors.h"
#include "datasets/calibration/calibration.h"
#include "tests/datasets/calibration_test_util.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using test::WriteCalibrationText;
using ::testing::HasSubstr;

const std::string kHandBuiltCamera = R"({"name": "cam0", "width": 1920, "height": 1080,
   "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "DC": [0, 0, 0, 0, 0],
   "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0.0], [-4.0], [1.5]]})";
const std::string kHandBuiltJson = "{\"cameras\": [\n  " + kHandBuiltCamera + "]}";

// A pickle (Human3.6M's cameras.pkl) is named as such, with where it is read, instead of "set the
// format", which no format could follow; an unknown extension still says which names are known.
TEST(CalibrationFormat, APickleSaysWhereItIsReadAnUnknownNameWhatIsKnown) {
  test::TempDir dir;
  const auto pickle = WriteCalibrationText(dir.path() / "cameras.pkl", "\x80\x04");
  EXPECT_THAT(test::InputErrorOf([&] { DetectCalibrationFormat(pickle); }),
              ::testing::HasSubstr("cameras.pkl: a Python pickle, which is no calibration format rpt reads as a file "
                                   "(Human3.6M's cameras.pkl is read with its dataset: --dataset human36m"));
  const auto other = WriteCalibrationText(dir.path() / "cameras.bin", "x");
  EXPECT_THAT(test::InputErrorOf([&] { DetectCalibrationFormat(other); }),
              ::testing::HasSubstr("cameras.bin: cannot tell the calibration format from the name"));
}

TEST(CalibrationJson, HandBuiltCameraProjectsTheKnownPointToTheKnownPixel) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "cameras.json", kHandBuiltJson);
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kJson);
  InputWarnings warnings;
  const Calibration calibration = ReadCalibration(path, {}, &warnings);
  ASSERT_EQ(calibration.cameras.size(), 1u);
  test::ExpectHandBuiltCamera(calibration.cameras[0]);
  EXPECT_EQ(calibration.cameras[0].name, "cam0");
  EXPECT_TRUE(warnings.empty());
  const CalibrationDescription& d = calibration.description;
  EXPECT_EQ(d.format, CalibrationFormat::kJson);
  EXPECT_EQ(d.units, LengthUnit::kMetres);
  EXPECT_FALSE(d.units_assumed);
  EXPECT_THAT(d.extrinsics, HasSubstr("camera centre T: x_cam = R (X - T)"));
  const std::vector<std::string> lines = d.Lines();
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines[0], "format: json, rpt cameras JSON (the camera schema of the generic labels)");
  EXPECT_EQ(lines[1], "files: " + path.string());
  EXPECT_EQ(lines[4], "units: metres");
}

TEST(CalibrationJson, EveryLensModelRoundTripsExactly) {
  test::TempDir dir;
  std::vector<Camera> rig = test::MakeRig(/*with_fisheye=*/true);
  rig.push_back(test::LookingAtRoomCentre("h36m", {0.1, -4.2, 1.8}));
  rig.back().model = DistortionModel::kH36M;
  rig.back().dist = {-0.2, 0.24, -0.0016, -0.0007, -0.0028};
  WriteCalibration(dir.path() / "rig.json", rig);
  InputWarnings warnings;
  const Calibration back = ReadCalibration(dir.path() / "rig.json", {}, &warnings);
  test::ExpectSameProjections(rig, back.cameras);
  EXPECT_EQ(back.cameras[3].model, DistortionModel::kFisheye);
  EXPECT_EQ(back.cameras[4].model, DistortionModel::kH36M);
  EXPECT_TRUE(warnings.empty());  // every key the writer writes is one the reader reads
}

// A key the reader does not know changed the camera without a word ("model": "fisheye" read as a
// pinhole lens, "dist" as no distortion): such keys are counted as unused input (--strict refuses
// them), the first named with the key it may mean, another tool's name for it or a typo.
TEST(CalibrationJson, KeysTheReaderDoesNotKnowAreCountedTheFirstWithTheKeyItMayMean) {
  test::TempDir dir;
  std::string other_tool = kHandBuiltCamera;
  other_tool.replace(other_tool.find("\"DC\""), 4, "\"dist\"");
  const std::string second = R"({"name": "cam1", "model": "fisheye", "note": "bumped", "width": 1920, "height": 1080,
   "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[1], [-4], [1.5]]})";
  const auto path = WriteCalibrationText(dir.path() / "cameras.json", "{\"cameras\": [" + other_tool + ", " + second + "]}");
  InputWarnings warnings;
  const Calibration read = ReadCalibration(path, {}, &warnings);
  EXPECT_EQ(read.cameras[1].model, DistortionModel::kNone);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].Line(), path.string() +
                                            ": 3 keys in camera objects rpt does not read, ignored (the first: 'dist' "
                                            "in /cameras/0 (did you mean 'DC'?))");
  const auto typo = WriteCalibrationText(dir.path() / "typo.json",
                                         "{\"cameras\": [" + std::string(R"({"name": "c", "tyep": "fisheye",)") +
                                             kHandBuiltCamera.substr(kHandBuiltCamera.find("\"width\"")) + "]}");
  InputWarnings typo_warnings;
  ReadCalibration(typo, {}, &typo_warnings);
  ASSERT_EQ(typo_warnings.items().size(), 1u);
  EXPECT_THAT(typo_warnings.items()[0].Line(), HasSubstr("1 keys in camera objects rpt does not read, ignored (the "
                                                         "first: 'tyep' in /cameras/0 (did you mean 'type'?))"));
}

TEST(CalibrationJson, ALabelsFileGivesTheCamerasOfItsFirstLabel) {
  test::TempDir dir;
  const auto path =
      WriteCalibrationText(dir.path() / "labels.json", R"([{"id": "f0", "joints": ["nose"], "cameras": [)" +
                                                           kHandBuiltCamera + "]}, {\"id\": \"f1\"}]");
  const Calibration calibration = ReadCalibration(path);
  ASSERT_EQ(calibration.cameras.size(), 1u);
  test::ExpectHandBuiltCamera(calibration.cameras[0]);
  EXPECT_THAT(calibration.description.notes, testing::Contains(HasSubstr("labels file")));
}

TEST(CalibrationJson, MalformedFilesNameTheFileAndThePlace) {
  test::TempDir dir;
  const auto syntax = WriteCalibrationText(dir.path() / "syntax.json", "{\"cameras\": [\n  {\"name\": \"a\",, }]}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(syntax, {.format = CalibrationFormat::kJson}); }),
              HasSubstr(syntax.string() + ":2:"));
  std::string no_k = kHandBuiltJson;  // "K" -> "k"
  no_k.replace(no_k.find("\"K\""), 3, "\"k\"");
  const auto missing = WriteCalibrationText(dir.path() / "missing.json", no_k);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(missing); }),
              HasSubstr(missing.string() + ": /cameras/0/K: missing"));
  const std::string twice = "{\"cameras\": [" + kHandBuiltCamera + ", " + kHandBuiltCamera + "]}";
  const auto duplicate = WriteCalibrationText(dir.path() / "twice.json", twice);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(duplicate); }),
              HasSubstr(duplicate.string() + ": /cameras/1/name: camera name 'cam0' appears twice"));
  const auto unknown = WriteCalibrationText(dir.path() / "unknown.json", R"({"a": {"b": 1}})");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(unknown); }),
              HasSubstr(unknown.string() + ": cannot tell which calibration JSON"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(dir.path() / "absent.json"); }),
              HasSubstr((dir.path() / "absent.json").string() + ": file not found"));
}

TEST(CalibrationJson, OptionsThatDoNotApplyAreConfigErrors) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "cameras.json", kHandBuiltJson);
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadCalibration(path, {.units = LengthUnit::kMillimetres}); }),
              HasSubstr("units: json files are in metres"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                WriteCalibration(dir.path() / "out.json", test::MakeRig(true), {.units = LengthUnit::kMillimetres});
              }),
              HasSubstr("always in metres"));
  EXPECT_THAT(test::ConfigErrorOf([&] { WriteCalibration(dir.path() / "out.txt", test::MakeRig(true)); }),
              HasSubstr("cannot tell the format to write"));
}

TEST(CalibrationJson, CamerasAFormatCannotHoldAreRefusedNamingTheCamera) {
  test::TempDir dir;
  std::vector<Camera> rig = test::MakeRig(true);
  rig[1].name = rig[0].name;
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "out.json", rig); }),
              HasSubstr("camera name 'cam_a' appears twice"));
  rig = test::MakeRig(true);
  rig[2].R(0, 0) = 2;
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "out.json", rig); }),
              HasSubstr("out.json: cannot write camera 'cam_c' (lens opencv): R is not orthonormal"));
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "out.json", {}); }),
              HasSubstr("no cameras to write"));
}

}  // namespace
}  // namespace rpt
