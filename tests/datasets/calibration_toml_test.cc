// SPDX-License-Identifier: MIT
// Pose2Sim / anipose camera groups (datasets/calibration/camera_group_toml.h): the hand-built
// camera as both tools write it, units, file order, fisheye, round trips and errors with line.
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

// Pose2Sim's Calib.toml: 4 distortion coefficients, sizes as floats, a metadata table.
const std::string kPose2Sim = R"([cam_01]
name = "cam_01"
size = [ 1920.0, 1080.0]
matrix = [ [ 1000.0, 0.0, 960.0], [ 0.0, 1000.0, 540.0], [ 0.0, 0.0, 1.0]]
distortions = [ 0.0, 0.0, 0.0, 0.0]
rotation = [ 1.5707963267948966, 0.0, 0.0]
translation = [ 0.0, 1.5, 4.0]
fisheye = false

[metadata]
adjusted = false
error = 0.0
)";

// anipose's CameraGroup.dump: cam_0, 5 coefficients, integer sizes, millimetres.
const std::string kAnipose = R"([cam_0]
name = "A"
size = [ 1920, 1080,]
matrix = [ [ 1000.0, 0.0, 960.0,], [ 0.0, 1000.0, 540.0,], [ 0.0, 0.0, 1.0,],]
distortions = [ 0.0, 0.0, 0.0, 0.0, 0.0,]
rotation = [ 1.5707963267948966, 0.0, 0.0,]
translation = [ 0.0, 1500.0, 4000.0,]

[cam_1]
name = "B"
size = [ 1920, 1080,]
matrix = [ [ 1000.0, 0.0, 960.0,], [ 0.0, 1000.0, 540.0,], [ 0.0, 0.0, 1.0,],]
distortions = [ 0.0, 0.0, 0.0, 0.0, 0.0,]
rotation = [ 0.0, 0.0, 0.0,]
translation = [ 2000.0, 0.0, 0.0,]

[metadata]
)";

TEST(CalibrationToml, Pose2SimFileIsWorldToCameraWithARodriguesVector) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "Calib.toml", kPose2Sim);
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kToml);
  InputWarnings warnings;
  const Calibration calibration = ReadCalibration(path, {}, &warnings);
  ASSERT_EQ(calibration.cameras.size(), 1u);
  test::ExpectHandBuiltCamera(calibration.cameras[0]);
  EXPECT_EQ(calibration.cameras[0].name, "cam_01");
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(calibration.description.rotation, "Rodrigues vector (axis * angle, radians)");
  EXPECT_TRUE(calibration.description.units_assumed);
  // The same rotation as a 3x3 matrix (row by row) is said to be one; in degrees it is refused.
  std::string matrix = kPose2Sim;
  const std::string rotation = "rotation = [ 1.5707963267948966, 0.0, 0.0]";
  matrix.replace(matrix.find(rotation), rotation.size(), "rotation = [ [1, 0, 0], [0, 0, -1], [0, 1, 0]]");
  const Calibration as_matrix = ReadCalibration(WriteCalibrationText(dir.path() / "matrix.toml", matrix));
  test::ExpectHandBuiltCamera(as_matrix.cameras[0]);
  EXPECT_EQ(as_matrix.description.rotation, "3x3 matrix (9 numbers, row by row)");
  std::string degrees = kPose2Sim;
  degrees.replace(degrees.find(rotation), rotation.size(), "rotation = [ 90.0, 0.0, 0.0]");
  const auto degrees_path = WriteCalibrationText(dir.path() / "degrees.toml", degrees);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(degrees_path); }),
              HasSubstr("degrees.toml:6: [cam_01].rotation: a rotation vector of length 90 (its angle in radians) "
                        "turns more than a full turn"));
}

TEST(CalibrationToml, AniposeMillimetresAreReadWithTheUnitsOptionAndWarnedWithout) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "calibration.toml", kAnipose);
  const Calibration mm = ReadCalibration(path, {.units = LengthUnit::kMillimetres});
  ASSERT_EQ(mm.cameras.size(), 2u);
  test::ExpectHandBuiltCamera(mm.cameras[0]);
  EXPECT_EQ(mm.cameras[0].name, "A");
  EXPECT_NEAR((mm.cameras[1].Center() - Eigen::Vector3d(-2, 0, 0)).norm(), 0, 1e-12);
  InputWarnings warnings;
  ReadCalibration(path, {}, &warnings);  // metres: centres 4.7 km apart
  std::vector<std::string> lines;
  for (const InputWarning& w : warnings.items()) lines.push_back(w.Line());
  EXPECT_THAT(
      lines,
      testing::ElementsAre(
          path.string() + ": 2 cameras more than 1 km from the origin (check the units of T) (max |T| in m = 4272)",
          HasSubstr(path.string() + ": 1 camera rigs spanning more than 100 m (millimetres read as metres? "
                                    "check the units) (span in m = 4716.99")));
}

TEST(CalibrationToml, CamerasComeInFileOrderAndFisheyeIsRead) {
  test::TempDir dir;
  std::string text;
  for (int c : {2, 10, 1}) {
    text += "[cam_" + std::to_string(c) +
            "]\nsize = [ 1920.0, 1080.0]\nmatrix = [ [ 1000.0, 0.0, 960.0], [ 0.0, 1000.0, 540.0], [ 0.0, 0.0, 1.0]]\n"
            "distortions = [ 0.1, -0.02, 0.003, -0.0004]\nrotation = [ 0.0, 0.0, 0.0]\ntranslation = [ " +
            std::to_string(c) + ".0, 0.0, 3.0]\nfisheye = " + (c == 10 ? "true" : "false") + "\n\n";
  }
  const Calibration calibration = ReadCalibration(WriteCalibrationText(dir.path() / "c.toml", text));
  ASSERT_EQ(calibration.cameras.size(), 3u);
  EXPECT_EQ(calibration.cameras[0].name, "cam_2");  // no name: the table's key
  EXPECT_EQ(calibration.cameras[1].name, "cam_10");
  EXPECT_EQ(calibration.cameras[2].name, "cam_1");
  EXPECT_EQ(calibration.cameras[0].model, DistortionModel::kOpenCV);
  EXPECT_DOUBLE_EQ(calibration.cameras[0].dist[3], -0.0004);
  EXPECT_EQ(calibration.cameras[1].model, DistortionModel::kFisheye);
  EXPECT_DOUBLE_EQ(calibration.cameras[1].dist[3], -0.0004);
  // A misspelt key changed the lens without a word (fish_eye = true: radial-tangential): said.
  InputWarnings none;
  ReadCalibration(WriteCalibrationText(dir.path() / "c2.toml", text), {}, &none);
  EXPECT_TRUE(none.empty()) << none.items()[0].Line();
  std::string misspelt = text;
  misspelt.replace(misspelt.find("fisheye = true"), 14, "fish_eye = true");
  const auto path = WriteCalibrationText(dir.path() / "m.toml", misspelt);
  InputWarnings warnings;
  const Calibration read = ReadCalibration(path, {}, &warnings);
  EXPECT_EQ(read.cameras[1].model, DistortionModel::kOpenCV);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].Line(),
            path.string() + ": 1 keys in camera tables rpt does not read, ignored (the first: 'fish_eye' in [cam_10] "
                            "(did you mean 'fisheye'?))");
}

TEST(CalibrationToml, WriterRoundTripsEveryLensModelThroughOurJson) {
  test::TempDir dir;
  const std::vector<Camera> rig = test::MakeRig(/*with_fisheye=*/true);
  WriteCalibration(dir.path() / "rig.toml", rig);
  const Calibration back = ReadCalibration(dir.path() / "rig.toml");
  test::ExpectSameProjections(rig, back.cameras);
  WriteCalibration(dir.path() / "rig.json", back.cameras);
  WriteCalibration(dir.path() / "again.toml", ReadCalibration(dir.path() / "rig.json").cameras,
                   {.units = LengthUnit::kMillimetres});
  test::ExpectSameProjections(rig,
                              ReadCalibration(dir.path() / "again.toml", {.units = LengthUnit::kMillimetres}).cameras);
  Camera quoted = rig[0];
  quoted.name = "cam \"a\"\\1";
  WriteCalibration(dir.path() / "quoted.toml", {quoted});
  EXPECT_EQ(ReadCalibration(dir.path() / "quoted.toml").cameras[0].name, quoted.name);
}

TEST(CalibrationToml, MalformedFilesNameTheFileLineAndKey) {
  test::TempDir dir;
  auto read = [&](const std::string& name, const std::string& text) {
    const auto path = WriteCalibrationText(dir.path() / name, text);
    return test::InputErrorOf([&] { ReadCalibration(path); });
  };
  EXPECT_THAT(read("syntax.toml", "[cam_1]\nsize = [1920, 1080\nmatrix = 3\n"), HasSubstr("syntax.toml:3:"));
  std::string no_matrix = kPose2Sim;
  no_matrix.erase(no_matrix.find("matrix"), no_matrix.find("distortions") - no_matrix.find("matrix"));
  EXPECT_THAT(read("no_matrix.toml", no_matrix), HasSubstr("no_matrix.toml:1: [cam_01]: matrix missing"));
  std::string short_t = kPose2Sim;
  short_t.replace(short_t.find("[ 0.0, 1.5, 4.0]"), 16, "[ 0.0, 1.5]");
  EXPECT_THAT(read("short_t.toml", short_t),
              HasSubstr("short_t.toml:7: [cam_01].translation: expected 3 numbers, got 2"));
  std::string text_size = kPose2Sim;
  text_size.replace(text_size.find("[ 1920.0, 1080.0]"), 17, "[ \"1920\", 1080.0]");
  EXPECT_THAT(read("text_size.toml", text_size),
              HasSubstr("text_size.toml:3: [cam_01].size: expected numbers (or rows of numbers), found a string"));
  std::string fisheye = kPose2Sim;
  fisheye.replace(fisheye.find("fisheye = false"), 15, "fisheye = true");
  fisheye.replace(fisheye.find("[ 0.0, 0.0, 0.0, 0.0]"), 21, "[ 0.1, 0.0, 0.0]");
  EXPECT_THAT(read("fisheye.toml", fisheye),
              HasSubstr("fisheye.toml:5: [cam_01].distortions: the fisheye model has 4 coefficients"));
  EXPECT_THAT(read("empty.toml", "[metadata]\nerror = 0.0\n"), HasSubstr("empty.toml: no camera table"));
}

}  // namespace
}  // namespace rpt
