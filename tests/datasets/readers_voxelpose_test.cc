// SPDX-License-Identifier: MIT
// VoxelPose camera json and 2D detection cache: files written by the tests, plus the real
// Shelf/Campus fixtures when shared/data is present.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/joints.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/voxelpose_calibration.h"
#include "datasets/readers/voxelpose_detections.h"
#include "tests/datasets/io_test_util.h"
#include "tests/datasets/tolerance_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;


std::filesystem::path WriteText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

std::string Num(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

std::string Matrix3Json(const Eigen::Matrix3d& m) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    s += std::string(r ? "," : "") + "[" + Num(m(r, 0)) + "," + Num(m(r, 1)) + "," + Num(m(r, 2)) + "]";
  }
  return s + "]";
}

// One camera object of a VoxelPose calibration json. `extra` is appended verbatim.
std::string VoxelPoseCamera(const Eigen::Matrix3d& R, const Eigen::Vector3d& center_mm, const std::string& k_p,
                            bool with_R = true) {
  std::string s = "{";
  if (with_R) s += "\"R\": " + Matrix3Json(R) + ", ";
  s += "\"T\": [[" + Num(center_mm.x()) + "], [" + Num(center_mm.y()) + "], [" + Num(center_mm.z()) + "]], ";
  s += "\"fx\": 1000.5, \"fy\": 1001.5, \"cx\": 500.25, \"cy\": 380.75";
  if (!k_p.empty()) s += ", " + k_p;
  return s + "}";
}

// World -> camera rotation of a camera at `center` looking at `target` (x right, y down, z up world).
Eigen::Matrix3d LookAt(const Eigen::Vector3d& center, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d(0, 0, 1)).normalized();
  Eigen::Matrix3d R;
  R << x.transpose(), z.cross(x).transpose(), z.transpose();
  return R;
}

Eigen::Matrix3d SomeRotation(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

// VoxelPose's own projection (lib/utils/cameras_cpu.py project_point_radial), written out.
Eigen::Vector2d VoxelPoseProject(const Eigen::Matrix3d& R, const Eigen::Vector3d& T_mm, double fx, double fy, double cx,
                                 double cy, const Eigen::Vector3d& k, const Eigen::Vector2d& p,
                                 const Eigen::Vector3d& X_mm) {
  const Eigen::Vector3d x = R * (X_mm - T_mm);
  const Eigen::Vector2d y = x.head<2>() / x.z();
  const double r2 = y.squaredNorm();
  const double radial = 1 + k[0] * r2 + k[1] * r2 * r2 + k[2] * r2 * r2 * r2;
  const double tan = p[0] * y[1] + p[1] * y[0];
  const Eigen::Vector2d yd = y * (radial + 2 * tan) + Eigen::Vector2d(p[1], p[0]) * r2;
  return Eigen::Vector2d(fx * yd.x() + cx, fy * yd.y() + cy);
}

// ---------------------------------------------------------------------------------------
// Calibration json written here

TEST(VoxelPoseCalibration, DistortionCentreConventionAndNumericOrder) {
  test::TempDir dir;
  const Eigen::Vector3d T0(1200.0, -2100.0, 1500.0);
  const Eigen::Matrix3d R0 = LookAt(T0 / 1000.0, Eigen::Vector3d(0, 0, 1));
  const std::string distortion = "\"k\": [[0.11], [-0.05], [0.013]], \"p\": [[0.0012], [-0.0021]]";
  const std::string text = "{\"10\": " + VoxelPoseCamera(SomeRotation(2.0), Eigen::Vector3d(0, 0, 3000), "") +
                           ", \"0\": " + VoxelPoseCamera(R0, T0, distortion) + ", \"2\": " +
                           VoxelPoseCamera(SomeRotation(1.0), Eigen::Vector3d(10, 20, 2000),
                                           "\"k\": [[0.0], [0.0], [0.0]], \"p\": [[0.0], [0.0]]") +
                           "}";
  const auto path = WriteText(dir.path() / "calibration.json", text);
  const std::vector<Camera> cameras = ReadVoxelPoseCalibration(path, 1032, 776);
  ASSERT_EQ(cameras.size(), 3u);
  EXPECT_EQ(cameras[0].name, "0");
  EXPECT_EQ(cameras[1].name, "2");
  EXPECT_EQ(cameras[2].name, "10");
  for (const Camera& camera : cameras) {
    EXPECT_EQ(camera.width, 1032);
    EXPECT_EQ(camera.height, 776);
    EXPECT_EQ(camera.Validate(), "");
  }
  const Camera& c0 = cameras[0];
  EXPECT_EQ(c0.model, DistortionModel::kOpenCV);
  EXPECT_EQ(c0.dist, (std::array<double, 5>{0.11, -0.05, 0.0012, -0.0021, 0.013}));
  EXPECT_EQ(cameras[1].model, DistortionModel::kNone);  // all-zero k, p
  EXPECT_EQ(cameras[2].model, DistortionModel::kNone);  // k, p absent
  EXPECT_TRUE(c0.Center().isApprox(T0 / 1000.0, 1e-12));
  EXPECT_TRUE(c0.R.isApprox(R0, 1e-12));
  EXPECT_DOUBLE_EQ(c0.K(0, 0), 1000.5);
  EXPECT_DOUBLE_EQ(c0.K(1, 2), 380.75);

  // The converted camera projects like VoxelPose's own formula (mm world, centre T).
  for (const Eigen::Vector3d& X_m :
       {Eigen::Vector3d(0.5, 0.2, 1.0), Eigen::Vector3d(-0.3, 1.1, 0.1), Eigen::Vector3d(0, 0, 1.8)}) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(c0.Project(X_m, &uv));
    const Eigen::Vector2d expected =
        VoxelPoseProject(R0, T0, 1000.5, 1001.5, 500.25, 380.75, Eigen::Vector3d(0.11, -0.05, 0.013),
                         Eigen::Vector2d(0.0012, -0.0021), X_m * 1000.0);
    EXPECT_NEAR((uv - expected).norm(), 0.0, 1e-8) << X_m.transpose();
  }
}

TEST(VoxelPoseCalibration, RoundedRotationIsReorthonormalisedAndCounted) {
  test::TempDir dir;
  const Eigen::Matrix3d rounded = test::RoundedRotation(SomeRotation(0.4));  // 6 significant digits
  ASSERT_GT(test::OrthonormalityError(rounded), 1e-7);
  const auto path = WriteText(dir.path() / "c.json", "{\"0\": " + VoxelPoseCamera(rounded, Eigen::Vector3d(0, 0, 0), "") +
                                                         ", \"1\": " + VoxelPoseCamera(rounded, Eigen::Vector3d(1, 0, 0), "") + "}");
  InputWarnings warnings;
  const std::vector<Camera> cameras = ReadVoxelPoseCalibration(path, 1032, 776, &warnings);
  ASSERT_EQ(cameras.size(), 2u);
  for (const Camera& camera : cameras) {
    EXPECT_EQ(camera.Validate(), "");
    EXPECT_LT(test::OrthonormalityError(camera.R), 1e-12);
    EXPECT_LT((camera.R - rounded).cwiseAbs().maxCoeff(), 1e-5);
  }
  test::ExpectOneWarning(warnings, path.string(), test::kRotationsFixed, 2);
  EXPECT_NO_THROW(ReadVoxelPoseCalibration(path, 1032, 776)) << "no sink: corrected all the same";
}

TEST(VoxelPoseCalibration, RotationBeyondTheToleranceNamesFileAndCamera) {
  test::TempDir dir;
  const auto path = WriteText(dir.path() / "c.json",
                              "{\"0\": " + VoxelPoseCamera(SomeRotation(0.4), Eigen::Vector3d(0, 0, 0), "") + ", \"1\": " +
                                  VoxelPoseCamera(test::WrongRotation(SomeRotation(0.4)), Eigen::Vector3d(0, 0, 0), "") + "}");
  InputWarnings warnings;
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(path, 1032, 776, &warnings); }),
              HasSubstr(path.string() + ": /1/R: R is not a rotation (max |R^T R - I| = 0.010025"));
}

TEST(VoxelPoseCalibration, MalformedFilesNameFileAndPlace) {
  test::TempDir dir;
  const auto missing = dir.path() / "calibration_shelf.json";
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(missing, 1032, 776); }),
              HasSubstr(missing.string() + ": file not found"));

  const std::string good = VoxelPoseCamera(SomeRotation(0.1), Eigen::Vector3d(1, 2, 3), "");
  const auto no_r = WriteText(
      dir.path() / "no_r.json",
      "{\"0\": " + good + ", \"1\": " + VoxelPoseCamera(SomeRotation(0.2), Eigen::Vector3d(1, 2, 3), "", false) + "}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(no_r, 1032, 776); }),
              HasSubstr(no_r.string() + ": /1/R: missing"));

  const auto scaled =
      WriteText(dir.path() / "scaled.json",
                "{\"0\": " + VoxelPoseCamera(1.1 * SomeRotation(0.3), Eigen::Vector3d(1, 2, 3), "") + "}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(scaled, 1032, 776); }),
              HasSubstr(scaled.string() + ": /0/R: R is not a rotation (max |R^T R - I| = 0.21"));

  Eigen::Matrix3d mirror = SomeRotation(0.3);
  mirror.row(2) *= -1;
  const auto reflection =
      WriteText(dir.path() / "mirror.json", "{\"0\": " + VoxelPoseCamera(mirror, Eigen::Vector3d(1, 2, 3), "") + "}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(reflection, 1032, 776); }),
              HasSubstr(reflection.string() + ": /0/R: R is a reflection"));

  const auto short_k = WriteText(
      dir.path() / "k.json",
      "{\"0\": " + VoxelPoseCamera(SomeRotation(0.3), Eigen::Vector3d(1, 2, 3), "\"k\": [[0.1], [0.2]]") + "}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(short_k, 1032, 776); }), HasSubstr(short_k.string() + ": /0/k"));

  const auto no_fx = WriteText(dir.path() / "fx.json",
                               "{\"0\": {\"R\": " + Matrix3Json(SomeRotation(0.3)) + ", \"T\": [[0],[0],[0]]}}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(no_fx, 1032, 776); }),
              HasSubstr(no_fx.string() + ": /0/fx: missing"));

  // A missing cx is read after fx and 0 were given to K's comma initialiser: the throw must not
  // happen inside it (Debug builds abort on an unfinished comma initialiser, issue 10 finding 6).
  for (const char* key : {"cx", "fy", "cy"}) {
    nlohmann::json camera = nlohmann::json::parse(good);
    camera.erase(key);
    const auto path = WriteText(dir.path() / (std::string(key) + ".json"), "{\"0\": " + camera.dump() + "}");
    EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(path, 1032, 776); }),
                HasSubstr(path.string() + ": /0/" + key + ": missing"));
  }

  const auto array = WriteText(dir.path() / "array.json", "[1, 2]");
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseCalibration(array, 1032, 776); }),
              HasSubstr("expected an object keyed by camera id"));
}

TEST(VoxelPoseCalibration, ShelfAndCampusFixtures) {
  RPT_REQUIRE_SHARED_DATA("shelf/calibration_shelf.json");
  RPT_REQUIRE_SHARED_DATA("campus/calibration_campus.json");
  InputWarnings shelf_warnings;
  const std::vector<Camera> shelf =
      ReadVoxelPoseCalibration(test::SharedData("shelf/calibration_shelf.json"), 1032, 776, &shelf_warnings);
  ASSERT_EQ(shelf.size(), 5u);
  // Its rotations have 6 decimals (max |R^T R - I| ~1.1e-6): all five are corrected and counted.
  test::ExpectOneWarning(shelf_warnings, test::SharedData("shelf/calibration_shelf.json").string(),
                         test::kRotationsFixed, 5);
  for (size_t c = 0; c < shelf.size(); ++c) {
    EXPECT_EQ(shelf[c].name, std::to_string(c));
    EXPECT_EQ(shelf[c].model, DistortionModel::kNone);
    EXPECT_EQ(shelf[c].Validate(), "");
  }
  // calibration_shelf.json camera 0: T = (-1586.45, -2109.47, 1104.21) mm.
  EXPECT_TRUE(shelf[0].Center().isApprox(Eigen::Vector3d(-1.5864496077989998, -2.10946905869, 1.104209800652), 1e-6));
  // The 4D-Association file stores t = -R T / 1000 for the same camera: (-0.5943, 0.9720, 2.6245) m.
  EXPECT_NEAR(shelf[0].t.x(), -0.5943, 1e-4);
  EXPECT_NEAR(shelf[0].t.y(), 0.9720, 1e-4);
  EXPECT_NEAR(shelf[0].t.z(), 2.6245, 1e-4);

  InputWarnings campus_warnings;
  const std::vector<Camera> campus =
      ReadVoxelPoseCalibration(test::SharedData("campus/calibration_campus.json"), 360, 288, &campus_warnings);
  ASSERT_EQ(campus.size(), 3u);
  EXPECT_TRUE(campus_warnings.empty()) << "exact to round-off: nothing to report";
  EXPECT_EQ(campus[2].name, "2");
}

// ---------------------------------------------------------------------------------------
// Detection cache written here

// A rows x 3 float64 array (x = base + j, y = 2 * base + j, score).
test::ByteVec PredBytes(double base, double score, std::int64_t rows) {
  std::vector<double> values;
  for (int j = 0; j < rows; ++j) {
    values.push_back(base + j);
    values.push_back(2 * base + j);
    values.push_back(j == 0 ? score : 0.5);
  }
  return test::RawOf(values);
}

// defaultdict(None, {key: [{"pred": array}, ...]}) like VoxelPose's cache (protocol 3).
struct CacheEntry {
  std::string key;
  std::vector<double> bases;  // one detection per base
  double score = 0.9;
  std::vector<std::int64_t> shape = {17, 3};
};

test::ByteVec CachePickle(const std::vector<CacheEntry>& entries) {
  test::PickleWriter w;
  w.Proto(3).Global("collections", "defaultdict").None().Tuple1().Reduce().Mark();
  for (const CacheEntry& entry : entries) {
    w.Str(entry.key).EmptyList();
    if (!entry.bases.empty()) {
      w.Mark();
      for (double base : entry.bases) {
        w.EmptyDict()
            .Str("pred")
            .Array(entry.shape, "f8", "<", false, PredBytes(base, entry.score, entry.shape[0]))
            .SetItem();
      }
      w.Appends();
    }
  }
  w.SetItems().Stop();
  return w.bytes;
}

// The cache read for cameras "0" and "1" of a sequence whose frame ids are "shelf_<frame>".
const VoxelPoseDetectionsOptions kTwoCameras = {{"0", "1"}, "shelf"};

TEST(VoxelPoseDetections, KeysMapToFramesAndCameras) {
  test::TempDir dir;
  const auto path = dir.Write("pred.pkl", CachePickle({
                                              {"0_5", {100, 200}, 1.25},  // above 1: clamped, counted
                                              {"1_5", {}},                // nothing detected
                                              {"3_5", {10}},              // camera not asked for
                                              {"0_7", {10}},
                                              {"1_300", {50}, 0.4},
                                          }));
  const Detections detections = ReadVoxelPoseDetections(path, kTwoCameras);
  EXPECT_EQ(detections.joints, CocoBodyJoints());
  ASSERT_EQ(detections.frames.size(), 3u);  // every frame of the file, ascending

  const FrameDetections& f5 = detections.frames[0];
  EXPECT_EQ(f5.frame_id, "shelf_000005");
  EXPECT_EQ(f5.cameras, (std::vector<std::string>{"0", "1"}));
  ASSERT_EQ(f5.views.size(), 2u);
  ASSERT_EQ(f5.views[0].num_persons(), 2);
  EXPECT_EQ(f5.views[1].num_persons(), 0);
  EXPECT_EQ(f5.views[0].Person(1)(0, 3), 203.0);  // x of joint 3 of the second detection
  EXPECT_EQ(f5.views[0].Person(1)(1, 3), 403.0);
  EXPECT_EQ(f5.views[0].Person(0)(2, 0), 1.0);
  EXPECT_EQ(f5.views[0].Person(0)(2, 1), 0.5);

  EXPECT_EQ(detections.frames[1].frame_id, "shelf_000007");
  EXPECT_EQ(detections.frames[1].cameras, (std::vector<std::string>{"0"}));
  const FrameDetections& f300 = detections.frames[2];
  EXPECT_EQ(f300.frame_id, "shelf_000300");
  EXPECT_EQ(f300.cameras, (std::vector<std::string>{"1"}));
  EXPECT_DOUBLE_EQ(f300.views[0].Person(0)(2, 0), 0.4);
  // Two detections of key 0_5 with score 1.25; the key of camera 3 (not asked for) is counted as
  // unused input.
  ASSERT_EQ(detections.warnings.items().size(), 2u);
  EXPECT_EQ(detections.warnings.items()[0].Line(),
            path.string() + ": 1 keys of cameras not in the calibration ignored (cameras '3')");
  EXPECT_EQ(detections.warnings.items()[0].kind, InputWarningKind::kUnused);
  EXPECT_EQ(detections.warnings.items()[1].Line(), path.string() + ": 2 scores above 1 clamped to 1 (largest = 1.25)");
}

// A pickle stores an object once however often it is referenced: every key's value here is one
// list of 1000 references to one detection (a file of a few KB). What the keys decode to is
// charged to the file's inflate budget before any is read (it took 630 MB for a 9 KB file); the
// same detections written out one by one are read.
TEST(VoxelPoseDetections, SharedReferencesDecodeWithinTheInflateBudget) {
  test::TempDir dir;
  const auto bomb = [](int keys, int references) {
    test::PickleWriter w;
    w.Proto(3).EmptyDict().Mark();
    for (int k = 0; k < keys; ++k) {
      w.Str("0_" + std::to_string(k));
      if (k > 0) {
        w.Get(1);
        continue;
      }
      w.EmptyList().Put(1).Mark();
      for (int r = 0; r < references; ++r) {
        if (r == 0) {
          w.EmptyDict().Str("pred").Array({17, 3}, "f8", "<", false, PredBytes(100, 0.9, 17)).SetItem().Put(2);
        } else {
          w.Get(2);
        }
      }
      w.Appends();
    }
    w.SetItems().Stop();
    return w.bytes;
  };
  const auto path = dir.Write("bomb.pkl", bomb(500, 1000));
  EXPECT_LT(std::filesystem::file_size(path), 20000u);
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(path, kTwoCameras); }),
              HasSubstr(path.string() + ": its 500000 detections (objects the file stores once may be referenced "
                        "many times): decompressing 194.5 MB would take the data decompressed from " + path.string()));
  const Detections few = ReadVoxelPoseDetections(dir.Write("few.pkl", bomb(3, 20)), kTwoCameras);
  ASSERT_EQ(few.frames.size(), 3u);
  EXPECT_EQ(few.frames[2].views[0].num_persons(), 20);
}

// Without camera names every camera of the keys is read (sorted); without a frame-id prefix the
// keys cannot become frame ids.
TEST(VoxelPoseDetections, CamerasDefaultToTheFileAndThePrefixIsRequired) {
  test::TempDir dir;
  const auto path = dir.Write("pred.pkl", CachePickle({{"1_5", {100}}, {"0_6", {7}}, {"3_5", {10}}}));
  const Detections detections = ReadVoxelPoseDetections(path, {{}, "campus"});
  ASSERT_EQ(detections.frames.size(), 2u);
  EXPECT_EQ(detections.frames[0].frame_id, "campus_000005");
  EXPECT_EQ(detections.frames[0].cameras, (std::vector<std::string>{"1", "3"}));
  EXPECT_EQ(detections.frames[1].cameras, (std::vector<std::string>{"0"}));
  EXPECT_TRUE(detections.warnings.empty());
  EXPECT_THAT(
      test::ConfigErrorOf([&] {
        ReadVoxelPoseDetections(path, {{"0"}, ""});
      }),
      HasSubstr("pred.pkl: a VoxelPose cache is keyed \"{camera}_{frame}\": reading it needs the frame-id prefix"));
}

// The file is parsed once; a frame's views are converted when asked for, so a bad value in a frame
// that is never asked for is never seen.
TEST(VoxelPoseDetections, FileConvertsOneFrameWhenAskedFor) {
  test::TempDir dir;
  CacheEntry bad{"1_9", {1}};
  bad.score = std::nan("");
  const auto path = dir.Write("pred.pkl", CachePickle({{"0_5", {100}, 1.2}, {"1_5", {3}}, bad}));
  const VoxelPoseDetectionsFile file(path, {"0", "1", "2"});
  EXPECT_EQ(file.frames(), (std::vector<long>{5, 9}));
  EXPECT_TRUE(file.HasFrame(9));
  EXPECT_FALSE(file.HasFrame(6));
  InputWarnings warnings;
  std::vector<Poses2D> views;
  file.ReadFrame(5, &views, &warnings);
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[0].num_persons(), 1);
  EXPECT_EQ(views[1].num_persons(), 1);
  EXPECT_EQ(views[2].num_persons(), 0);
  EXPECT_EQ(views[2].num_joints, 17);
  EXPECT_EQ(views[0].Person(0)(2, 0), 1.0);
  test::ExpectOneWarning(warnings, path.string(), test::kScoresClamped, 1);
  file.ReadFrame(6, &views, &warnings);  // no key: every view empty
  for (const Poses2D& view : views) EXPECT_EQ(view.num_persons(), 0);
  EXPECT_THAT(test::InputErrorOf([&] { file.ReadFrame(9, &views, &warnings); }),
              HasSubstr(path.string() + ": key '1_9'[0].pred: contains NaN or infinity"));
}

// ReadDetectionsFile reads a .pkl (the one dispatch on what a detections path is).
TEST(VoxelPoseDetections, DetectionsFileReadsThePickle) {
  test::TempDir dir;
  const auto path = dir.Write("pred.pkl", CachePickle({{"0_5", {100}}, {"1_300", {50}, 0.4}}));
  DetectionsFileOptions options;
  options.voxelpose = kTwoCameras;
  const Detections detections = ReadDetectionsFile(path, options);
  ASSERT_EQ(detections.frames.size(), 2u);
  EXPECT_EQ(detections.frames[1].frame_id, "shelf_000300");
  EXPECT_DOUBLE_EQ(detections.frames[1].views[0].Person(0)(2, 0), 0.4);
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadDetectionsFile(path); }), HasSubstr("frame-id prefix"));
}

TEST(VoxelPoseDetections, ScoresSlightlyAboveOneAreClampedAndCounted) {
  test::TempDir dir;
  const auto path = dir.Write("pred.pkl", CachePickle({{"0_5", {100}, 1.008}, {"1_5", {100}, 1.018}, {"0_6", {7}, 1.0}}));
  const Detections detections = ReadVoxelPoseDetections(path, kTwoCameras);
  ASSERT_EQ(detections.frames.size(), 2u);
  EXPECT_EQ(detections.frames[0].views[0].Person(0)(2, 0), 1.0);
  EXPECT_EQ(detections.frames[0].views[1].Person(0)(2, 0), 1.0);
  EXPECT_EQ(detections.frames[1].views[0].Person(0)(2, 0), 1.0);
  test::ExpectOneWarning(detections.warnings, path.string(), test::kScoresClamped, 2);
  EXPECT_DOUBLE_EQ(detections.warnings.items()[0].worst, 1.018);
}

TEST(VoxelPoseDetections, NegativeLargeOrNanScoresNameFileAndKey) {
  test::TempDir dir;
  for (const double score : {1.6, -0.1}) {
    const auto path = dir.Write("bad.pkl", CachePickle({{"0_5", {100}, 0.9}, {"1_6", {100}, score}}));
    EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(path, kTwoCameras); }),
                HasSubstr(path.string() + ": key '1_6'[0].pred: row 0: score " + (score > 0 ? "1.6" : "-0.1") +
                          " outside [0, 1]"));
  }
  const auto nan = dir.Write("nan.pkl", CachePickle({{"1_6", {100}, std::nan("")}}));
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(nan, kTwoCameras); }),
              HasSubstr(nan.string() + ": key '1_6'[0].pred: contains NaN or infinity"));
}

TEST(VoxelPoseDetections, MalformedCacheNamesFileAndKey) {
  test::TempDir dir;
  const auto bad_key = dir.Write("key.pkl", CachePickle({{"camera0", {1}}}));
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(bad_key, kTwoCameras); }),
              HasSubstr(bad_key.string() + ": top level: key 'camera0' is not of the form"));

  CacheEntry wrong_shape{"0_5", {1}};
  wrong_shape.shape = {16, 3};
  wrong_shape.score = 0.5;
  const auto shape = dir.Write("shape.pkl", CachePickle({wrong_shape}));
  const std::string message = test::InputErrorOf([&] { ReadVoxelPoseDetections(shape, kTwoCameras); });
  EXPECT_THAT(message, HasSubstr(shape.string()));
  EXPECT_THAT(message, HasSubstr("0_5"));
  EXPECT_THAT(message, HasSubstr("pred"));

  CacheEntry nan{"1_6", {1}};
  nan.score = std::nan("");
  const auto nan_path = dir.Write("nan.pkl", CachePickle({nan}));
  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(nan_path, kTwoCameras); }),
              HasSubstr("contains NaN or infinity"));

  EXPECT_THAT(test::InputErrorOf([&] { ReadVoxelPoseDetections(dir.path() / "absent.pkl", kTwoCameras); }),
              HasSubstr("absent.pkl: file not found"));
}

TEST(VoxelPoseDetections, ShelfFixtureKeys) {
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  const Detections detections = ReadVoxelPoseDetections(test::SharedData("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl"),
                                                        {{"0", "1", "2", "3", "4"}, "shelf"});
  ASSERT_EQ(detections.frames.size(), 3u);
  EXPECT_EQ(detections.frames[2].frame_id, "shelf_000002");
  for (const FrameDetections& frame : detections.frames) {
    ASSERT_EQ(frame.views.size(), 5u);
    for (const Poses2D& view : frame.views) {
      EXPECT_GE(view.num_persons(), 3);
      EXPECT_LE(view.num_persons(), 5);
    }
  }
  const Poses2D& view = detections.frames[0].views[2];  // key "2_0"
  EXPECT_NEAR(view.Person(0)(0, 0), 278.49, 0.01);
  EXPECT_NEAR(view.Person(0)(1, 0), 70.81, 0.01);
  EXPECT_NEAR(view.Person(0)(2, 0), 0.40, 0.01);
}

}  // namespace
}  // namespace rpt
