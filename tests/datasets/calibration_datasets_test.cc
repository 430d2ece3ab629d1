// SPDX-License-Identifier: MIT
// The calibrations read by the dataset readers and COLMAP's text model, through ReadCalibration:
// the hand-built camera in each file format, the real calibrations of ../shared/data (Shelf and
// Campus VoxelPose JSON, Panoptic, 4D-Association Shelf, Human3.6M) round-tripped through our
// JSON and every writer with projections equal to 1e-9 px, and errors with file and place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/errors.h"
#include "datasets/calibration/calibration.h"
#include "datasets/readers/human36m.h"
#include "tests/datasets/calibration_test_util.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

using test::WriteCalibrationText;
using ::testing::HasSubstr;

TEST(CalibrationDatasets, VoxelPoseFileHoldsTheCentreInMillimetres) {
  test::TempDir dir;
  const auto path = WriteCalibrationText(dir.path() / "calibration_x.json", R"({"0": {
    "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4000], [1500]], "fx": 1000, "fy": 1000, "cx": 960, "cy": 540,
    "k": [[0], [0], [0]], "p": [[0], [0]]}})");
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kVoxelPose);
  const Calibration given = ReadCalibration(path, {.image_width = 1920, .image_height = 1080});
  test::ExpectHandBuiltCamera(given.cameras[0]);
  EXPECT_EQ(given.description.units, LengthUnit::kMillimetres);
  EXPECT_THAT(given.description.extrinsics, HasSubstr("camera centre T"));
  // Without the option, the size is twice the principal point (here the same), counted.
  InputWarnings warnings;
  test::ExpectHandBuiltCamera(ReadCalibration(path, {}, &warnings).cameras[0]);
  ASSERT_EQ(warnings.items().size(), 1u);
  EXPECT_EQ(warnings.items()[0].Line(), path.string() + ": 1 image sizes missing, taken as twice the principal point");
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadCalibration(path, {.units = LengthUnit::kMetres}); }),
              HasSubstr("units: voxelpose files are in millimetres"));
}

TEST(CalibrationDatasets, PanopticFileIsConvertedToZUpMetres) {
  test::TempDir dir;
  // R = I, t = (0, 0, 400) cm in Panoptic's world (y down): the Panoptic point (50, -50, 100) cm
  // is at (0.1, -0.1) normalised, so pixel (1060, 440); in rpt's world it is (0.5, 1, 0.5) m.
  const auto path =
      WriteCalibrationText(dir.path() / "calibration_seq.json", R"({"calibDataSource": "test", "cameras": [
    {"name": "00_00", "type": "hd", "resolution": [1920, 1080], "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]],
     "distCoef": [0, 0, 0, 0, 0], "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [[0], [0], [400]]},
    {"name": "01_01", "type": "vga", "resolution": [640, 480], "K": [[700, 0, 320], [0, 700, 240], [0, 0, 1]],
     "distCoef": [0, 0, 0, 0, 0], "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [[100], [0], [400]]}]})");
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kPanoptic);
  const Calibration calibration = ReadCalibration(path);
  ASSERT_EQ(calibration.cameras.size(), 2u);  // every camera, in file order
  EXPECT_EQ(calibration.cameras[1].name, "01_01");
  Eigen::Vector2d uv;
  ASSERT_TRUE(calibration.cameras[0].Project(Eigen::Vector3d(0.5, 1.0, 0.5), &uv));
  EXPECT_NEAR(uv.x(), 1060, 1e-9);
  EXPECT_NEAR(uv.y(), 440, 1e-9);
  EXPECT_EQ(calibration.description.units, LengthUnit::kCentimetres);
  EXPECT_THAT(calibration.description.notes, testing::Contains(HasSubstr("(x, y, z) -> (x, z, -y)")));
  // rpt's own JSON with a stray 't' is taken for Panoptic: the error says so (it named a missing
  // 'resolution' only); with the format given the reader's error stays as it is.
  const auto ours = WriteCalibrationText(dir.path() / "ours.json", R"({"cameras": [{"name": "a", "width": 1920,
    "height": 1080, "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    "T": [[0], [0], [0]], "t": [[0], [0], [0]]}]})");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(ours); }),
              HasSubstr("/cameras/0/resolution: missing (the file was read as a CMU Panoptic calibration"));
  CalibrationReadOptions panoptic;
  panoptic.format = CalibrationFormat::kPanoptic;
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(ours, panoptic); }),
              testing::Not(HasSubstr("was read as")));
}

TEST(CalibrationDatasets, FourDaFileIsWorldToCameraInMetres) {
  test::TempDir dir;
  const auto path =
      WriteCalibrationText(dir.path() / "calibration.json", R"({"0": {"K": [1000, 0, 960, 0, 1000, 540, 0, 0, 1],
    "imgSize": [1920, 1080], "RT": [1, 0, 0, 0, 0, 0, -1, 1.5, 0, 1, 0, 4]},
    "1": {"K": [1000, 0, 960, 0, 1000, 540, 0, 0, 1], "imgSize": [1920, 1080], "R": [1.5707963267948966, 0, 0], "T": [0, 1.5, 4]}})");
  EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kFourDa);
  const Calibration calibration = ReadCalibration(path);
  ASSERT_EQ(calibration.cameras.size(), 2u);
  test::ExpectHandBuiltCamera(calibration.cameras[0]);
  test::ExpectHandBuiltCamera(calibration.cameras[1]);
}

const std::string kColmapCameras =
    "# Camera list\n1 PINHOLE 1920 1080 1000 1000 960 540\n2 OPENCV 1920 1080 1000 1001 950 530 0.1 -0.01 0.001 "
    "0.002\n";
const std::string kColmapImages =
    "# Image list\n1 0.70710678118654757 0.70710678118654757 0 0 0 1.5 4 1 cam01/00001.jpg\n\n"
    "2 1 0 0 0 0.5 0 3 2 cam02/00001.jpg\n100 200 -1\n";

TEST(CalibrationDatasets, ColmapImagesAreCamerasWorldToCameraQuaternions) {
  test::TempDir dir;
  WriteCalibrationText(dir.path() / "sparse/cameras.txt", kColmapCameras);
  const auto images = WriteCalibrationText(dir.path() / "sparse/images.txt", kColmapImages);
  for (const auto& path : {images, dir.path() / "sparse/cameras.txt", dir.path() / "sparse"}) {
    EXPECT_EQ(DetectCalibrationFormat(path), CalibrationFormat::kColmap);
    const Calibration calibration = ReadCalibration(path);
    ASSERT_EQ(calibration.cameras.size(), 2u);
    test::ExpectHandBuiltCamera(calibration.cameras[0]);
    EXPECT_EQ(calibration.cameras[0].name, "cam01/00001");
    EXPECT_EQ(calibration.cameras[1].model, DistortionModel::kOpenCV);
    EXPECT_EQ(calibration.description.rotation, "unit quaternion QW QX QY QZ");
  }
  const Calibration calibration = ReadCalibration(images);
  WriteCalibration(dir.path() / "colmap.json", calibration.cameras);
  test::ExpectSameProjections(calibration.cameras, ReadCalibration(dir.path() / "colmap.json").cameras);
  WriteCalibrationText(images, kColmapImages + "3 1 0 0 0 0 0 3 7 cam03/00001.jpg\n\n");
  EXPECT_THAT(test::InputErrorOf([&] { ReadCalibration(images); }),
              HasSubstr(images.string() + ":6: CAMERA_ID 7 is not in"));
}

// Reads a real calibration, then checks that it round-trips through our JSON and through each
// writer that can hold it with projections equal to 1e-9 px.
void ExpectRoundTrips(const std::vector<Camera>& cameras, const std::vector<std::string>& outputs) {
  test::TempDir dir;
  WriteCalibration(dir.path() / "cameras.json", cameras);
  const std::vector<Camera> json = ReadCalibration(dir.path() / "cameras.json").cameras;
  test::ExpectSameProjections(cameras, json);
  for (const std::string& output : outputs) {
    SCOPED_TRACE(output);
    std::filesystem::create_directories((dir.path() / output).parent_path());
    WriteCalibration(dir.path() / output, json);
    const std::vector<Camera> back = ReadCalibration(dir.path() / output).cameras;
    test::ExpectSameProjections(cameras, back);
    WriteCalibration(dir.path() / "again.json", back);
    test::ExpectSameProjections(cameras, ReadCalibration(dir.path() / "again.json").cameras);
  }
}

const std::vector<std::string> kEveryWriter = {"cameras.toml", "cameras.yml", "cameras.xml", "easymocap/intri.yml"};

TEST(CalibrationDatasets, RealShelfAndCampusRoundTrip) {
  RPT_REQUIRE_SHARED_DATA("shelf/calibration_shelf.json");
  RPT_REQUIRE_SHARED_DATA("campus/calibration_campus.json");
  InputWarnings warnings;
  const Calibration shelf = ReadCalibration(test::SharedData("shelf/calibration_shelf.json"),
                                            {.image_width = 1032, .image_height = 776}, &warnings);
  ASSERT_EQ(shelf.cameras.size(), 5u);
  EXPECT_EQ(shelf.description.format, CalibrationFormat::kVoxelPose);
  for (const InputWarning& w : warnings.items()) EXPECT_THAT(w.what, HasSubstr("re-orthonormalised")) << w.Line();
  ExpectRoundTrips(shelf.cameras, kEveryWriter);
  const Calibration campus =
      ReadCalibration(test::SharedData("campus/calibration_campus.json"), {.image_width = 360, .image_height = 288});
  ASSERT_EQ(campus.cameras.size(), 3u);
  ExpectRoundTrips(campus.cameras, kEveryWriter);
}

TEST(CalibrationDatasets, RealPanopticRoundTrips) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1/calibration_160906_band1.json");
  InputWarnings warnings;
  const Calibration panoptic =
      ReadCalibration(test::SharedData("panoptic/160906_band1/calibration_160906_band1.json"), {}, &warnings);
  EXPECT_GT(panoptic.cameras.size(), 500u);  // 480 VGA, 31 HD and the Kinects
  for (const InputWarning& w : warnings.items()) EXPECT_THAT(w.what, HasSubstr("re-orthonormalised")) << w.Line();
  ExpectRoundTrips(panoptic.cameras, {"cameras.toml", "easymocap/intri.yml"});
}

TEST(CalibrationDatasets, RealFourDaShelfRoundTrips) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association/calibration.json");
  InputWarnings warnings;
  const Calibration shelf = ReadCalibration(test::SharedData("shelf/4d_association/calibration.json"), {}, &warnings);
  ASSERT_EQ(shelf.cameras.size(), 5u);
  EXPECT_EQ(shelf.description.format, CalibrationFormat::kFourDa);
  for (const InputWarning& w : warnings.items()) EXPECT_THAT(w.what, HasSubstr("re-orthonormalised")) << w.Line();
  ExpectRoundTrips(shelf.cameras, kEveryWriter);
}

TEST(CalibrationDatasets, RealHuman36mCamerasRoundTrip) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  // The Human3.6M lens model: only our JSON holds it; the others refuse it, naming the camera.
  const std::vector<Camera> h36m = ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S1");
  ASSERT_EQ(h36m.size(), 4u);
  ExpectRoundTrips(h36m, {});
  test::TempDir dir;
  EXPECT_THAT(test::InputErrorOf([&] { WriteCalibration(dir.path() / "h36m.toml", h36m); }),
              HasSubstr("camera '54138969': the Human3.6M lens model has no OpenCV equivalent"));
  // Read with OpenCV's lens model, they go through every writer.
  ExpectRoundTrips(ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S1", DistortionModel::kOpenCV),
                   kEveryWriter);
}

}  // namespace
}  // namespace rpt
