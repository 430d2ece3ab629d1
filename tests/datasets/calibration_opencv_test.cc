// SPDX-License-Identifier: MIT
// OpenCV cv::FileStorage calibrations (datasets/calibration/opencv_yml.h, easymocap_yml.h):
// single files as calibrateCamera / stereoCalibrate / ROS write them, EasyMocap's intri.yml +
// extri.yml, the writers, round trips through our JSON, units and errors with file and place.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/calibration/calibration.h"
#include "datasets/calibration/file_storage.h"
#include "tests/datasets/calibration_test_util.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using test::WriteCalibrationText;
using ::testing::HasSubstr;

std::string Matrix(const std::string& key, int rows, int cols, const std::string& data) {
  return key + ": !!opencv-matrix\n   rows: " + std::to_string(rows) + "\n   cols: " + std::to_string(cols) +
         "\n   dt: d\n   data: [ " + data + " ]\n";
}

const std::string kK = "1000., 0., 960., 0., 1000., 540., 0., 0., 1.";
const std::string kR = "1., 0., 0., 0., 0., -1., 0., 1., 0.";
const std::string kRvec = "1.5707963267948966, 0., 0.";  // Rx(90 deg) as a Rodrigues vector

// The hand-built camera (tests/datasets/calibration_test_util.h) as cv::calibrateCamera users
// save it.
const std::string kCalibrateCameraYml = "%YAML:1.0\n---\nimage_width: 1920\nimage_height: 1080\n" +
                                        Matrix("camera_matrix", 3, 3, kK) +
                                        Matrix("distortion_coefficients", 1, 5, "0., 0., 0., 0., 0.") +
                                        Matrix("R", 3, 3, kR) + Matrix("T", 3, 1, "0., 1.5, 4.");

TEST(CalibrationOpenCV, CalibrateCameraFileIsWorldToCameraWithAMatrix) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "cam0.yml", kCalibrateCameraYml);
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kOpenCV);
  InputWarnings warnings;
  const Calibration calibration = ReadCalibration(path, {}, &warnings);
  ASSERT_EQ(calibration.cameras.size(), 1u);
  test::ExpectHandBuiltCamera(calibration.cameras[0]);
  EXPECT_EQ(calibration.cameras[0].name, "cam0");  // the file's stem
  EXPECT_EQ(calibration.cameras[0].model, DistortionModel::kNone);
  EXPECT_TRUE(warnings.empty());
  const CalibrationDescription& d = calibration.description;
  EXPECT_EQ(d.format, CalibrationFormat::kOpenCV);
  EXPECT_EQ(d.extrinsics, "world to camera: x_cam = R X + T");
  EXPECT_EQ(d.rotation, "R (3x3 matrix)");
  EXPECT_TRUE(d.units_assumed);
  EXPECT_THAT(d.Lines(), testing::Contains(HasSubstr("units: metres (assumed")));
}

TEST(CalibrationOpenCV, RodriguesVectorsMillimetresAndXml) {
  test::TempDir dir;
  const auto yml = WriteCalibrationText(
      dir.path() / "mm.yml", "%YAML:1.0\n---\nimage_width: 1920\nimage_height: 1080\n" + Matrix("K", 3, 3, kK) +
                                 Matrix("rvec", 3, 1, kRvec) + Matrix("tvec", 3, 1, "0., 1500., 4000."));
  const Calibration mm = ReadCalibration(yml, {.units = LengthUnit::kMillimetres});
  test::ExpectHandBuiltCamera(mm.cameras[0]);
  EXPECT_EQ(mm.description.rotation, "rvec (Rodrigues vector)");
  EXPECT_EQ(mm.description.units, LengthUnit::kMillimetres);
  EXPECT_FALSE(mm.description.units_assumed);
  EXPECT_THAT(mm.description.Lines(), testing::Contains("units: millimetres, converted to metres"));
  // Read as metres (the default), the camera is 4 km away: warned, not refused.
  InputWarnings warnings;
  ReadCalibration(yml, {}, &warnings);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_THAT(warnings.items()[0].Line(), HasSubstr("1 cameras more than 1 km from the origin (check the units of T)"));

  const auto xml = WriteCalibrationText(dir.path() / "cam.xml", R"(<?xml version="1.0"?>
<opencv_storage>
<image_width>1920</image_width><image_height>1080</image_height>
<cameraMatrix type_id="opencv-matrix"><rows>3</rows><cols>3</cols><dt>d</dt><data>1000 0 960 0 1000 540 0 0 1</data></cameraMatrix>
<distCoeffs type_id="opencv-matrix"><rows>1</rows><cols>4</cols><dt>d</dt><data>0 0 0 0</data></distCoeffs>
<R type_id="opencv-matrix"><rows>3</rows><cols>1</cols><dt>d</dt><data>1.5707963267948966 0 0</data></R>
<T type_id="opencv-matrix"><rows>3</rows><cols>1</cols><dt>d</dt><data>0 1.5 4</data></T>
</opencv_storage>
)");
  test::ExpectHandBuiltCamera(ReadCalibration(xml).cameras[0]);
  // The same written by cv::FileStorage as JSON: told from the other JSON calibrations by its
  // "opencv-matrix" tags.
  const auto json = WriteCalibrationText(dir.path() / "cam.json", R"({
    "image_width": 1920, "image_height": 1080,
    "cameraMatrix": {"type_id": "opencv-matrix", "rows": 3, "cols": 3, "dt": "d", "data": [1000, 0, 960, 0, 1000, 540, 0, 0, 1]},
    "distCoeffs": {"type_id": "opencv-matrix", "rows": 1, "cols": 4, "dt": "d", "data": [0, 0, 0, 0]},
    "R": {"type_id": "opencv-matrix", "rows": 3, "cols": 1, "dt": "d", "data": [1.5707963267948966, 0, 0]},
    "T": {"type_id": "opencv-matrix", "rows": 3, "cols": 1, "dt": "d", "data": [0, 1.5, 4]}
})");
  EXPECT_EQ(DetectCalibrationFormat(json), CalibrationFormat::kOpenCV);
  test::ExpectHandBuiltCamera(ReadCalibration(json).cameras[0]);
}

TEST(CalibrationOpenCV, RosCameraInfoWithoutHeaderIsTheWorldOrigin) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "left.yaml", R"(image_width: 1280
image_height: 720
camera_name: narrow_stereo
camera_matrix:
  rows: 3
  cols: 3
  data: [1000, 0, 640, 0, 1000, 360, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.1, 0.01, 0.001, 0.002, 0.0]
)");
  const Calibration calibration = ReadCalibration(path);
  ASSERT_EQ(calibration.cameras.size(), 1u);
  const Camera& camera = calibration.cameras[0];
  EXPECT_EQ(camera.name, "narrow_stereo");
  EXPECT_EQ(camera.width, 1280);
  EXPECT_EQ(camera.model, DistortionModel::kOpenCV);
  EXPECT_DOUBLE_EQ(camera.dist[3], 0.002);
  EXPECT_TRUE(camera.R.isIdentity());
  EXPECT_TRUE(camera.t.isZero());
  EXPECT_THAT(calibration.description.extrinsics, HasSubstr("the camera is the world origin"));
  // The lens model's name decides the lens, whatever its case; a name rpt does not know is an error
  // (kannala_brandt, a typo: read as radial-tangential, a fisheye lens was up to 17.6 px off).
  std::stringstream read;
  read << std::ifstream(path).rdbuf();
  const std::string text = read.str();
  int written = 0;
  const auto with_model = [&](const std::string& model) {
    std::string edited = text;
    edited.replace(edited.find("plumb_bob"), 9, model);
    edited.replace(edited.find("cols: 5"), 7, "cols: 4");  // a fisheye lens has 4 coefficients
    edited.replace(edited.find(", 0.0]"), 6, "]");
    return WriteCalibrationText(dir.path() / ("model" + std::to_string(written++) + ".yaml"), edited);
  };
  EXPECT_EQ(ReadCalibration(with_model("Kannala_Brandt")).cameras[0].model, DistortionModel::kFisheye);
  EXPECT_EQ(ReadCalibration(with_model("EQUIDISTANT")).cameras[0].model, DistortionModel::kFisheye);
  EXPECT_EQ(ReadCalibration(with_model("radtan")).cameras[0].model, DistortionModel::kOpenCV);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(with_model("plumb_bobb")); }),
              HasSubstr("distortion_model: 'plumb_bobb' is not a lens model rpt reads"));
  // A pose under names rpt does not read would leave the camera at the world origin, silently.
  const auto renamed = WriteCalibrationText(
      dir.path() / "renamed.yaml",
      text + "rotation_matrix:\n  rows: 3\n  cols: 3\n  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n"
             "translation_vector:\n  rows: 3\n  cols: 1\n  data: [0.5, 0, 3]\n");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(renamed); }),
              HasSubstr(": no pose rpt reads (R, rvec or rotation with T, tvec, t or translation), but "
                        "'rotation_matrix', 'translation_vector': rename them"));
  // A parse error is reported at the file's own line (the added %YAML header is not counted).
  const auto bad =
      WriteCalibrationText(dir.path() / "bad.yaml", "image_width: 1280\ncamera_matrix:\n  rows: 3\n   data: [1, 2\n");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(bad); }), HasSubstr(bad.string() + ":4: "));
}

// Found by the fuzzer (calibration_easymocap): OpenCV 4.6's YAML parser loops forever on this
// text (an indented sequence, then a line with an unterminated quote). The parse runs in a child
// process first; past its limit the file is refused.
TEST(CalibrationOpenCV, AFileThatLoopsOpenCVsParserIsRefusedAfterTheLimit) {
  test::TempDir dir;
  const auto looping = WriteCalibrationText(dir.path() / "looping.yml", "   - a\n\"\nK");
  EXPECT_EQ(test::InputErrorOf([&] { file_storage::ReadFile(looping, std::chrono::milliseconds(300)); }),
            looping.string() + ": OpenCV's FileStorage parser did not finish within 300 ms: the file is damaged; rpt "
                               "did not read it");
  // A damaged file the parser does finish is still reported with OpenCV's error and its line.
  const auto bad = WriteCalibrationText(dir.path() / "bad.yml", "   - a\n\"\n");
  EXPECT_THAT(test::InputErrorOf([&] { file_storage::ReadFile(bad, std::chrono::milliseconds(300)); }),
              HasSubstr(bad.string()));
}

TEST(CalibrationOpenCV, StereoFilesGiveTwoCamerasTheFirstAtTheOrigin) {
  test::TempDir dir;
  // camera 2 = the hand-built camera seen from camera 1 at the world origin.
  const std::string intrinsics = "%YAML:1.0\n" + Matrix("M1", 3, 3, kK) + Matrix("D1", 1, 5, "0, 0, 0, 0, 0") +
                                 Matrix("M2", 3, 3, kK) + Matrix("D2", 1, 5, "0, 0, 0, 0, 0");
  const std::string extrinsics = "%YAML:1.0\n" + Matrix("R", 3, 3, kR) + Matrix("T", 3, 1, "0, 1.5, 4");
  const Calibration one =
      ReadCalibration(WriteCalibrationText(dir.path() / "one/stereo.yml", intrinsics + extrinsics.substr(10)),
                      {.image_width = 1920, .image_height = 1080});
  ASSERT_EQ(one.cameras.size(), 2u);
  EXPECT_EQ(one.cameras[0].name, "1");
  EXPECT_TRUE(one.cameras[0].R.isIdentity());
  test::ExpectHandBuiltCamera(one.cameras[1]);
  EXPECT_THAT(one.description.extrinsics, HasSubstr("camera 2 from camera 1"));
  // The stereo_calib sample's two files: either one names the pair.
  WriteCalibrationText(dir.path() / "pair/intrinsics.yml", intrinsics);
  const auto path = WriteCalibrationText(dir.path() / "pair/extrinsics.yml", extrinsics);
  InputWarnings warnings;
  const Calibration pair = ReadCalibration(path, {}, &warnings);
  test::ExpectHandBuiltCamera(pair.cameras[1]);
  EXPECT_EQ(pair.description.files.size(), 2u);
  // No image size in the files: twice the principal point, counted.
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].Line(), path.string() + ": 2 image sizes missing, taken as twice the principal point");
}

// EasyMocap's files as its write_intri / write_extri save them (cv2.FileStorage).
const std::string kIntri = "%YAML:1.0\n---\nnames:\n   - \"01\"\n" + Matrix("K_01", 3, 3, kK) +
                           Matrix("dist_01", 1, 5, "0., 0., 0., 0., 0.") + "H_01: 1080\nW_01: 1920\n";
const std::string kExtri = "%YAML:1.0\n---\nnames:\n   - \"01\"\n" + Matrix("R_01", 3, 1, kRvec) +
                           Matrix("Rot_01", 3, 3, kR) + Matrix("T_01", 3, 1, "0., 1.5, 4.");

TEST(CalibrationEasyMocap, IntriAndExtriGiveTheHandBuiltCamera) {
  test::TempDir dir;
  const auto intri = WriteCalibrationText(dir.path() / "intri.yml", kIntri);
  WriteCalibrationText(dir.path() / "extri.yml", kExtri);
  for (const auto& path : {intri, dir.path() / "extri.yml", dir.path()}) {
    EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kEasyMocap) << path;
    const Calibration calibration = ReadCalibration(path);
    ASSERT_EQ(calibration.cameras.size(), 1u);
    test::ExpectHandBuiltCamera(calibration.cameras[0]);
    EXPECT_EQ(calibration.cameras[0].name, "01");
    EXPECT_EQ(calibration.description.rotation, "R_ (Rodrigues vector)");
    EXPECT_EQ(calibration.description.files, (std::vector<std::filesystem::path>{intri, dir.path() / "extri.yml"}));
  }
  // Millimetres read as metres: the count names extri.yml, the file of T (it named intri.yml).
  std::string far = kExtri;
  far.replace(far.find("0., 1.5, 4."), 11, "0., 1500., 4000.");
  WriteCalibrationText(dir.path() / "extri.yml", far);
  InputWarnings warnings;
  ReadCalibration(intri, CalibrationReadOptions{}, &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_EQ(warnings.items()[0].Line(), (dir.path() / "extri.yml").string() +
                                            ": 1 cameras more than 1 km from the origin (check the units of T) (max "
                                            "|T| in m = 4272)");
  WriteCalibrationText(dir.path() / "extri.yml", kExtri);
  // The keys of both files in one file: the EasyMocap layout too.
  const auto both = WriteCalibrationText(dir.path() / "both.yml", kIntri + kExtri.substr(kExtri.find("R_01")));
  EXPECT_EQ(DetectCalibrationFormat(both), CalibrationFormat::kEasyMocap);
  test::ExpectHandBuiltCamera(ReadCalibration(both).cameras[0]);
}

TEST(CalibrationEasyMocap, MissingAndContradictoryKeysNameTheFileAndKey) {
  test::TempDir dir;
  WriteCalibrationText(dir.path() / "intri.yml", kIntri);
  std::string extri = kExtri;
  extri.replace(extri.find("0., 1.5, 4."), 11, "0., 1.5");
  const auto extri_path = WriteCalibrationText(dir.path() / "extri.yml", extri);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(extri_path); }),
              HasSubstr(extri_path.string() + ": T_01: expected 3x1 numbers, got 2"));
  extri = kExtri;
  extri.replace(extri.find("1.5707963267948966"), 18, "1.5707");
  WriteCalibrationText(extri_path, extri);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(extri_path); }),
              HasSubstr(extri_path.string() + ": Rot_01 differs from R_01 by up to"));
  WriteCalibrationText(extri_path, "%YAML:1.0\nnames: [\"01\"]\n");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(extri_path); }),
              HasSubstr(extri_path.string() + ": R_01: missing (camera '01' of names)"));
  std::filesystem::remove(extri_path);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(dir.path() / "intri.yml"); }),
              HasSubstr(extri_path.string() + ": file not found"));
}

TEST(CalibrationOpenCV, WritersRoundTripThroughOurJson) {
  test::TempDir dir;
  const std::vector<Camera> rig = test::MakeRig(/*with_fisheye=*/false);
  // Several cameras in one OpenCV file: the EasyMocap keys.
  for (const std::string name : {"rig.yml", "rig.xml", "easymocap/intri.yml"}) {
    std::filesystem::create_directories(dir.path() / "easymocap");
    WriteCalibration(dir.path() / name, rig);
    const Calibration back = ReadCalibration(dir.path() / name);
    EXPECT_EQ(back.description.format, CalibrationFormat::kEasyMocap) << name;
    test::ExpectSameProjections(rig, back.cameras);
    // Written with format opencv, read back with format opencv (not only auto).
    test::ExpectSameProjections(rig, ReadCalibration(dir.path() / name, {.format = CalibrationFormat::kOpenCV}).cameras);
    WriteCalibration(dir.path() / "via.json", back.cameras);
    test::ExpectSameProjections(rig, ReadCalibration(dir.path() / "via.json").cameras);
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "easymocap/extri.yml"));
  // One camera: calibrateCamera's keys; fisheye cameras too (fisheye_model: 1), in millimetres.
  const Camera fisheye = test::MakeRig(/*with_fisheye=*/true)[3];
  for (const std::string name : {"fisheye.yml", "fisheye.xml"}) {
    WriteCalibration(dir.path() / name, {fisheye}, {.units = LengthUnit::kMillimetres});
    const Calibration back = ReadCalibration(dir.path() / name, {.units = LengthUnit::kMillimetres});
    EXPECT_EQ(back.description.format, CalibrationFormat::kOpenCV);
    EXPECT_EQ(back.cameras[0].model, DistortionModel::kFisheye);
    test::ExpectSameProjections({fisheye}, back.cameras);
  }
  // A skew is written, but OpenCV's projectPoints ignores it: counted for opencv, easymocap and
  // toml, not for our JSON (a tester measured 4.6 px with skew 7.5).
  std::vector<Camera> skewed = rig;
  for (Camera& camera : skewed) camera.K(0, 1) = 0;
  skewed[1].K(0, 1) = 7.5;
  for (const std::string name : {"skew.yml", "skew.toml", "skew.json"}) {
    InputWarnings warnings;
    WriteCalibration(dir.path() / name, skewed, {}, &warnings);
    long counted = 0;
    for (const InputWarning& w : warnings.items()) {
      if (w.what.find("with a skew (K[0][1]) written") == std::string::npos) continue;
      counted += w.count;
      EXPECT_EQ(w.worst, 7.5);
    }
    EXPECT_EQ(counted, name == "skew.json" ? 0 : 1) << name;
  }
}

TEST(CalibrationOpenCV, CamerasTheLayoutCannotHoldAreRefused) {
  test::TempDir dir;
  std::vector<Camera> rig = test::MakeRig(/*with_fisheye=*/true);
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "intri.yml", rig); }),
              HasSubstr("cannot write camera 'cam_d' in the EasyMocap layout: EasyMocap has no fisheye model"));
  rig = test::MakeRig(false);
  rig[1].name = "cam/b";
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "rig.yml", rig); }),
              HasSubstr("cannot write camera 'cam/b' in the EasyMocap layout"));
  Camera h36m = test::MakeRig(false)[1];
  h36m.model = DistortionModel::kH36M;
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "h36m.yml", {h36m}); }),
              HasSubstr("the Human3.6M lens model has no OpenCV equivalent"));
  EXPECT_THAT(test::ConfigErrorOf(
                  [&] { WriteCalibration(dir.path() / "x.yml", rig, {.format = CalibrationWriteFormat::kEasyMocap}); }),
              HasSubstr("give intri.yml"));
  // A control character in a name: OpenCV's reader cut "cam\x01x" to "cam"; refused, nothing written.
  for (const std::string& name : {std::string("cam\x01x"), std::string("cam\tb")}) {
    for (const std::string file : {"one.yml", "one.xml"}) {
      Camera named = test::MakeRig(false)[0];
      named.name = name;
      EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / file, {named}); }),
                  HasSubstr("cannot write camera_name " + QuoteName(name) +
                            ": OpenCV's files cannot hold control characters"));
      EXPECT_FALSE(std::filesystem::exists(dir.path() / file)) << file;
    }
  }
}

TEST(CalibrationOpenCV, MalformedFilesNameTheFileAndTheNode) {
  test::TempDir dir;
  auto read = [&](const std::string& name, const std::string& text) {
    const auto path = WriteCalibrationText(dir.path() / name, text);
    return test::InputErrorOf([&] { ReadCalibration(path); });
  };
  EXPECT_THAT(read("no_k.yml", "%YAML:1.0\nimage_width: 10\n"), HasSubstr("no_k.yml: no camera matrix"));
  EXPECT_THAT(read("short_k.yml", "%YAML:1.0\n" + Matrix("K", 2, 3, "1, 0, 2, 0, 1, 3")),
              HasSubstr("short_k.yml: K: expected 3x3 numbers, got 6"));
  EXPECT_THAT(read("text_k.yml", "%YAML:1.0\nK: hello\n"),
              HasSubstr("text_k.yml: K: expected numbers (a matrix or a list), got a string"));
  EXPECT_THAT(
      read("rational.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) + Matrix("D", 1, 8, "0.1, 0, 0, 0, 0, 0.5, 0, 0")),
      HasSubstr("rational.yml: D: coefficients past k3"));
  EXPECT_THAT(read("only_r.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) + Matrix("R", 3, 3, kR)),
              HasSubstr("only_r.yml: R without a translation"));
  EXPECT_THAT(
      read("reflection.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) + Matrix("R", 3, 3, "1, 0, 0, 0, 1, 0, 0, 0, -1") +
                                 Matrix("T", 3, 1, "0, 0, 1")),
      HasSubstr("reflection.yml: R: R is a reflection"));
  EXPECT_THAT(read("size.yml", "%YAML:1.0\nimage_width: -5\n" + Matrix("K", 3, 3, kK)),
              HasSubstr("size.yml: image_width: expected an integer in [1, 1000000]"));
  EXPECT_THAT(read("syntax.yml", "%YAML:1.0\n---\nK: [1, 2,\n  3\nT: {\n"), HasSubstr("syntax.yml:"));
  EXPECT_THAT(read("binary.yml", std::string("%YAML:1.0\nK: \0", 14)), HasSubstr("binary.yml: not a text file"));
  EXPECT_THAT(read("list.yml", "%YAML:1.0\n- 1\n- 2\n"), HasSubstr("list.yml"));
  // The message lists every key the reader accepts (intrinsic_matrix too).
  EXPECT_THAT(read("no_k2.yml", "%YAML:1.0\nimage_width: 10\n"),
              HasSubstr("expected one of camera_matrix, K, M, cameraMatrix, intrinsic_matrix)"));
  // Rx(90 deg) written in degrees: an angle of 90 "radians" is more than a full turn.
  EXPECT_THAT(read("degrees.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) + Matrix("rvec", 3, 1, "90., 0., 0.") +
                                      Matrix("tvec", 3, 1, "0., 1.5, 4.")),
              HasSubstr("degrees.yml: rvec: a rotation vector of length 90 (its angle in radians) turns more than a "
                        "full turn (2 pi = 6.283): angles in degrees?"));
  // Just under a full turn is a rotation (no tool writes it, but it is one); just over is refused.
  EXPECT_NO_THROW(ReadCalibration(WriteCalibrationText(dir.path() / "turn.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) +
                                                         Matrix("rvec", 3, 1, "6.28, 0., 0.") +
                                                         Matrix("tvec", 3, 1, "0., 1.5, 4."))));
  EXPECT_THAT(read("over.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, kK) + Matrix("rvec", 3, 1, "0., 6.29, 0.") +
                                   Matrix("tvec", 3, 1, "0., 1.5, 4.")),
              HasSubstr("over.yml: rvec: a rotation vector of length 6.29"));
  EXPECT_THAT(read("negative_f.yml", "%YAML:1.0\n" + Matrix("K", 3, 3, "-1000., 0., 960., 0., 1000., 540., 0., 0., 1.")),
              HasSubstr("focal lengths must be positive (fx = -1000, fy = 1000)"));
}

TEST(CalibrationOpenCV, AFolderOfOneFilePerCameraIsTheRigInFileNameOrder) {
  test::TempDir dir;
  const auto folder = dir.path() / "calib";
  std::filesystem::create_directories(folder);
  WriteCalibrationText(folder / "b_side.yml", kCalibrateCameraYml);
  WriteCalibrationText(folder / "a_front.YAML",
                       "%YAML:1.0\n---\nimage_width: 1920\nimage_height: 1080\n" + Matrix("K", 3, 3, kK) +
                           Matrix("rvec", 3, 1, kRvec) + Matrix("tvec", 3, 1, "0., 1.5, 4."));
  WriteCalibrationText(folder / "notes.txt", "not a calibration");
  EXPECT_EQ(DetectCalibrationFormat(folder), CalibrationFormat::kOpenCV);
  const Calibration calibration = ReadCalibration(folder);
  ASSERT_EQ(calibration.cameras.size(), 2u);
  EXPECT_EQ(calibration.cameras[0].name, "a_front");
  EXPECT_EQ(calibration.cameras[1].name, "b_side");
  for (const Camera& camera : calibration.cameras) test::ExpectHandBuiltCamera(camera);
  EXPECT_EQ(calibration.description.files,
            (std::vector<std::filesystem::path>{folder / "a_front.YAML", folder / "b_side.yml"}));
  // Millimetres read as metres in every file: counted once for the folder (it said "1 cameras ..."
  // once per file), with the farthest camera.
  const auto far = dir.path() / "far";
  std::filesystem::create_directories(far);
  for (const std::string name : {"a", "b"}) {
    WriteCalibrationText(far / (name + ".yml"),
                         "%YAML:1.0\n---\nimage_width: 1920\nimage_height: 1080\n" + Matrix("K", 3, 3, kK) +
                             Matrix("rvec", 3, 1, kRvec) +
                             Matrix("tvec", 3, 1, name == "a" ? "0., 1500., 4000." : "0., 3000., 4000."));
  }
  InputWarnings far_warnings;
  ReadCalibration(far, CalibrationReadOptions{}, &far_warnings);
  ASSERT_FALSE(far_warnings.empty());
  EXPECT_EQ(far_warnings.items()[0].Line(),
            far.string() + ": 2 cameras more than 1 km from the origin (check the units of T) (max |T| in m = 5000)");
  // A folder with no OpenCV file names the three layouts it looked for.
  const auto empty = dir.path() / "empty";
  std::filesystem::create_directories(empty);
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(empty); }),
              HasSubstr("nor OpenCV files, one per camera (*.yml, *.yaml, *.xml)"));
  // Two files naming the same camera: both files named (it named the folder only).
  WriteCalibrationText(folder / "c_copy.yml", "%YAML:1.0\n---\ncamera_name: a_front\n" +
                                                  kCalibrateCameraYml.substr(std::string("%YAML:1.0\n---\n").size()));
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(folder); }),
              HasSubstr((folder / "c_copy.yml").string() + ": camera name 'a_front' appears twice (also in " +
                        (folder / "a_front.YAML").string() + ")"));
}

}  // namespace
}  // namespace rpt
