// SPDX-License-Identifier: MIT
// rpt cameras show / convert end to end on cameras the test writes: a conversion through the
// command gives the same cameras (projections to 1e-9 px), show prints every camera's centre, and
// bad files and option values exit 2 naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "datasets/calibration/calibration.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

std::vector<Camera> SceneCameras() {
  SyntheticParams params;
  params.frames = 1;
  params.distortion = SyntheticLens::kOpenCV;
  return OpenSyntheticSequence(params)->header().cameras;
}

double MaxProjectionDifferencePx(const std::vector<Camera>& a, const std::vector<Camera>& b) {
  double worst = 0;
  for (size_t c = 0; c < a.size(); ++c) {
    for (const Eigen::Vector3d& X : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1.5, -2, 0.2), Eigen::Vector3d(-3, 2.5, 1.8)}) {
      Eigen::Vector2d pa, pb;
      EXPECT_EQ(a[c].Project(X, &pa), b[c].Project(X, &pb));
      worst = std::max(worst, (pa - pb).norm());
    }
  }
  return worst;
}

TEST(CamerasCommand, ConvertsThroughEveryWrittenFormatAndShowsTheCentres) {
  const fs::path dir = test::TempDir("cameras_command");
  const std::vector<Camera> cameras = SceneCameras();
  WriteCalibration(dir / "cameras.json", cameras);
  // A folder that does not exist yet is created, as --out creates its folder.
  for (const std::string out : {"cameras.toml", "cameras.yml", "cameras.xml", "easymocap/new/intri.yml"}) {
    const test::CommandResult convert =
        test::RunRpt("cameras convert " + (dir / "cameras.json").string() + " " + (dir / out).string());
    ASSERT_EQ(convert.exit_code, 0) << out << ": " << convert.err;
    EXPECT_NE(convert.out.find("5 cameras"), std::string::npos) << convert.out;
    const Calibration back = ReadCalibration(dir / out);
    ASSERT_EQ(back.cameras.size(), cameras.size()) << out;
    EXPECT_LT(MaxProjectionDifferencePx(cameras, back.cameras), 1e-9) << out;
  }
  const test::CommandResult show = test::RunRpt("cameras show " + (dir / "cameras.toml").string());
  ASSERT_EQ(show.exit_code, 0) << show.err;
  EXPECT_NE(show.out.find("format: toml"), std::string::npos) << show.out;
  for (const Camera& c : cameras) {
    char centre[64];
    std::snprintf(centre, sizeof(centre), "%8.3f %8.3f %8.3f", c.Center().x(), c.Center().y(), c.Center().z());
    EXPECT_NE(show.out.find(c.name), std::string::npos) << show.out;
    EXPECT_NE(show.out.find(centre), std::string::npos) << centre << "\n" << show.out;
  }
  fs::remove_all(dir);
}

TEST(CamerasCommand, UnitsOptionScalesTheTranslations) {
  const fs::path dir = test::TempDir("cameras_units");
  const std::vector<Camera> cameras = SceneCameras();
  WriteCalibration(dir / "cameras.toml", cameras);  // metres
  const test::CommandResult convert = test::RunRpt("cameras convert " + (dir / "cameras.toml").string() + " " +
                                                   (dir / "cm.json").string() + " --units cm");
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const Calibration back = ReadCalibration(dir / "cm.json");
  ASSERT_EQ(back.cameras.size(), cameras.size());
  EXPECT_NEAR((back.cameras[0].Center() - 0.01 * cameras[0].Center()).norm(), 0, 1e-9) << "read as centimetres";
  fs::remove_all(dir);
}

TEST(CamerasCommand, BadFilesAndValuesExit2NamingThem) {
  const fs::path dir = test::TempDir("cameras_bad");
  WriteCalibration(dir / "cameras.json", SceneCameras());
  const test::CommandResult missing = test::RunRpt("cameras show " + (dir / "nothing.yml").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("nothing.yml"), std::string::npos) << missing.err;

  const test::CommandResult units = test::RunRpt("cameras show " + (dir / "cameras.json").string() + " --units inch");
  EXPECT_EQ(units.exit_code, 2);
  EXPECT_NE(units.err.find("--units"), std::string::npos) << units.err;
  EXPECT_NE(units.err.find("'inch'"), std::string::npos) << units.err;

  const test::CommandResult format = test::RunRpt("cameras convert " + (dir / "cameras.json").string() + " " +
                                                  (dir / "out.bin").string());
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_NE(format.err.find("out.bin"), std::string::npos) << format.err;
  EXPECT_FALSE(fs::exists(dir / "out.bin"));

  // A write that fails leaves no folders it created behind (EasyMocap cannot hold a fisheye lens).
  std::vector<Camera> fisheye = SceneCameras();
  fisheye[0].model = DistortionModel::kFisheye;
  fisheye[0].dist = {0.1, 0, 0, 0, 0};
  WriteCalibration(dir / "fisheye.json", fisheye);
  const test::CommandResult refused = test::RunRpt("cameras convert " + (dir / "fisheye.json").string() + " " +
                                                   (dir / "new" / "sub" / "intri.yml").string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("EasyMocap has no fisheye model (write toml or json, which keep it; rpt writes OpenCV "
                             "files in this layout only)"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir / "new")) << "an empty folder was left behind";
  EXPECT_EQ(test::RunRpt("cameras convert " + (dir / "cameras.json").string() + " " +
                         (dir / "new" / "sub" / "intri.yml").string())
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(dir / "new" / "sub" / "intri.yml"));

  // A format rpt only reads is not offered for writing: the help and the error list the written ones.
  const test::CommandResult read_only = test::RunRpt("cameras convert " + (dir / "cameras.json").string() + " " +
                                                     (dir / "cameras.txt").string() + " --out-format colmap");
  EXPECT_EQ(read_only.exit_code, 2);
  EXPECT_NE(read_only.err.find("--out-format: 'colmap' is not one of auto, json, opencv, easymocap, toml"),
            std::string::npos)
      << read_only.err;
  const test::CommandResult help = test::RunRpt("cameras convert --help");
  EXPECT_NE(help.out.find("[auto | json | opencv | easymocap | toml, default auto]"), std::string::npos) << help.out;

  fs::path broken = dir / "broken.toml";
  std::ofstream(broken) << "[cam_1]\nname = \"a\"\nmatrix = [[1, 0], [0, 1]]\n";
  const test::CommandResult bad = test::RunRpt("cameras show " + broken.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("broken.toml"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt
