// SPDX-License-Identifier: MIT
// Shelf / Campus readers: the mmpose subsets in shared/data (3 frames, renumbered 0-2) and
// small actorsGT.mat + calibration files written by the tests.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/joints.h"
#include "datasets/io/mat.h"
#include "datasets/readers/shelf_campus.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
using engine::ReadDataset;
namespace {

using ::testing::HasSubstr;
namespace m = test::mat;


DatasetRequest Request(const std::string& dataset, const std::filesystem::path& root,
                       std::map<std::string, std::string> params) {
  DatasetRequest request;
  request.dataset = dataset;
  request.root = root;
  request.params = std::move(params);
  return request;
}

Eigen::Vector3d Joint(const Poses3D& gt, int person, int joint) { return gt.Person(person).col(joint).head<3>(); }

int PersonWithTrack(const Poses3D& gt, int track) {
  for (int p = 0; p < gt.num_persons(); ++p) {
    if (gt.track_ids[p] == track) return p;
  }
  return -1;
}

// ---------------------------------------------------------------------------------------
// Real fixtures (mmpose subsets; skipped when shared/data is absent)

TEST(ShelfReader, FixtureCamerasAndGroundTruth) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const std::vector<Sequence> sequences = ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "0-2"}}));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& shelf = sequences[0];
  EXPECT_EQ(shelf.name, "shelf");
  ASSERT_EQ(shelf.cameras.size(), 5u);
  // calibration_shelf.json stores R with 6 decimals: one warning line for its 5 corrected rotations.
  ASSERT_EQ(shelf.warnings.items().size(), 1u);
  EXPECT_EQ(shelf.warnings.items()[0].Line().rfind(test::SharedData("shelf/calibration_shelf.json").string() +
                                                       ": 5 rotations re-orthonormalised (max |R^T R - I| = 1.0",
                                                   0),
            0u)
      << shelf.warnings.items()[0].Line();
  for (size_t c = 0; c < 5; ++c) {
    EXPECT_EQ(shelf.cameras[c].name, std::to_string(c));
    EXPECT_EQ(shelf.cameras[c].width, 1032);
    EXPECT_EQ(shelf.cameras[c].height, 776);
  }
  EXPECT_EQ(shelf.gt_joints, ShelfCampusJoints());
  for (const std::string& joint : EvaluationJoints13()) EXPECT_GE(FindJoint(shelf.gt_joints, joint), 0) << joint;
  EXPECT_TRUE(shelf.frames[0].views.empty());  // detections=none
  EXPECT_TRUE(shelf.room.size_m.isApprox(Eigen::Vector3d(8, 8, 2)));

  ASSERT_EQ(shelf.frames.size(), 3u);
  EXPECT_EQ(shelf.frames[0].id, "shelf_000000");
  EXPECT_EQ(shelf.frames[2].id, "shelf_000002");
  EXPECT_DOUBLE_EQ(shelf.frames[2].timestamp_s, 2.0 / 25.0);
  for (const SequenceFrame& frame : shelf.frames) {
    // Actors 1 and 3 are not annotated in the subset.
    EXPECT_EQ(PersonWithTrack(frame.gt, 1), -1);
    EXPECT_EQ(PersonWithTrack(frame.gt, 3), -1);
    EXPECT_GE(PersonWithTrack(frame.gt, 0), 0);
  }
  const Poses3D& gt = shelf.frames[0].gt;
  const int actor0 = PersonWithTrack(gt, 0);
  EXPECT_NEAR(Joint(gt, actor0, 0).x(), -0.1430438, 1e-7);
  EXPECT_NEAR(Joint(gt, actor0, 0).y(), -0.0922845, 1e-7);
  EXPECT_NEAR(Joint(gt, actor0, 0).z(), -0.0411864, 1e-7);
  EXPECT_EQ(gt.Person(actor0).row(3), Eigen::RowVectorXd::Ones(15));
  const int nose = FindJoint(shelf.gt_joints, "nose");
  EXPECT_TRUE(Joint(gt, actor0, nose).isApprox(0.5 * (Joint(gt, actor0, 12) + Joint(gt, actor0, 13)), 1e-12));
  // z is up: the head is above the ankles.
  EXPECT_GT(Joint(gt, actor0, 13).z(), Joint(gt, actor0, 0).z() + 1.0);
}

TEST(ShelfReader, ProjectionReproducesActor2D) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const Sequence shelf = ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "0-2"}}))[0];
  const io::MatFile mat = io::ReadMat(test::SharedData("shelf/actorsGT.mat"));
  const io::MatValue& views = mat.Get("actor2D").Cell(0).Cell(0);  // actor 0, frame 0
  const Poses3D& gt = shelf.frames[0].gt;
  const int actor0 = PersonWithTrack(gt, 0);

  const std::vector<double> stored = views.Cell(0).RowMajor(14, 2);  // camera 0
  Eigen::Vector2d bottom, top;
  ASSERT_TRUE(shelf.cameras[0].Project(Joint(gt, actor0, 12), &bottom));
  ASSERT_TRUE(shelf.cameras[0].Project(Joint(gt, actor0, 13), &top));
  EXPECT_NEAR(bottom.x(), 250.44, 0.01);
  EXPECT_NEAR(bottom.y(), 163.83, 0.01);
  EXPECT_NEAR(top.x(), 278.04, 0.01);
  EXPECT_NEAR(top.y(), 89.22, 0.01);
  EXPECT_NEAR((bottom - Eigen::Vector2d(stored[24], stored[25])).norm(), 0.0, 0.1);
  EXPECT_NEAR((top - Eigen::Vector2d(stored[26], stored[27])).norm(), 0.0, 0.1);

  // Every joint in every camera where actor2D has it.
  for (size_t c = 0; c < shelf.cameras.size(); ++c) {
    if (views.Cell(c).IsEmpty()) continue;
    const std::vector<double> rows = views.Cell(c).RowMajor(14, 2);
    for (int j = 0; j < 14; ++j) {
      Eigen::Vector2d uv;
      ASSERT_TRUE(shelf.cameras[c].Project(Joint(gt, actor0, j), &uv));
      EXPECT_NEAR((uv - Eigen::Vector2d(rows[2 * j], rows[2 * j + 1])).norm(), 0.0, 0.1)
          << "camera " << c << " joint " << j;
    }
  }
}

TEST(ShelfReader, VoxelPoseDetectionsAttach) {
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  const Sequence shelf =
      ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "0-2"}, {"detections", "voxelpose"}}))[0];
  EXPECT_EQ(shelf.detection_joints, CocoBodyJoints());
  for (const SequenceFrame& frame : shelf.frames) {
    ASSERT_EQ(frame.views.size(), 5u);
    for (const Poses2D& view : frame.views) EXPECT_GE(view.num_persons(), 3);
  }
  const Poses2D& view = shelf.frames[0].views[2];  // key "2_0"
  EXPECT_NEAR(view.Person(0)(0, 0), 278.49, 0.01);
  EXPECT_NEAR(view.Person(0)(1, 0), 70.81, 0.01);
  EXPECT_NEAR(view.Person(0)(2, 0), 0.40, 0.01);
  // Its detections are of the original frames 0-2, its ground truth of frames 300-302: said.
  const auto warned = [](const Sequence& sequence) {
    for (const InputWarning& w : sequence.warnings.items()) {
      if (w.Line().find("frames of mmpose's 3-frame test subset: its ground truth is Shelf frames 300-302") !=
          std::string::npos) {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(warned(shelf));
  EXPECT_FALSE(warned(ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "0-2"}}))[0]));
}

TEST(ShelfReader, DefaultFramesExceedTheFixture) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const std::string message = test::InputErrorOf([] { ReadDataset(Request("shelf", test::SharedData("shelf"), {})); });
  EXPECT_THAT(message, HasSubstr("actorsGT.mat: frame 600 requested but actor3D has 3 frames (0-2)"));
}

TEST(ShelfReader, ActorsAndNoseProxyParams) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const Sequence only0 = ReadDataset(
      Request("shelf", test::SharedData("shelf"), {{"frames", "1"}, {"actors", "0"}, {"nose_proxy", "top"}}))[0];
  ASSERT_EQ(only0.frames.size(), 1u);
  EXPECT_EQ(only0.frames[0].id, "shelf_000001");
  ASSERT_EQ(only0.frames[0].gt.track_ids, (std::vector<int>{0}));
  EXPECT_EQ(Joint(only0.frames[0].gt, 0, 14), Joint(only0.frames[0].gt, 0, 13));
  const Sequence bottom =
      ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "1"}, {"nose_proxy", "bottom"}}))[0];
  const int actor0 = PersonWithTrack(bottom.frames[0].gt, 0);
  EXPECT_EQ(Joint(bottom.frames[0].gt, actor0, 14), Joint(bottom.frames[0].gt, actor0, 12));
  EXPECT_THAT(test::InputErrorOf([] {
                ReadDataset(Request("shelf", test::SharedData("shelf"), {{"frames", "0-2"}, {"actors", "0,4"}}));
              }),
              HasSubstr("actorsGT.mat: actor 4 requested but actor3D has 4 actors (0-3)"));
}

TEST(CampusReader, FixtureGroundTruthAndProjection) {
  RPT_REQUIRE_SHARED_DATA("campus/actorsGT.mat");
  const std::vector<Sequence> sequences =
      ReadDataset(Request("campus", test::SharedData("campus"), {{"frames", "0-2"}}));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& campus = sequences[0];
  EXPECT_EQ(campus.name, "campus");
  ASSERT_EQ(campus.cameras.size(), 3u);
  for (const Camera& camera : campus.cameras) {
    EXPECT_EQ(camera.width, 360);
    EXPECT_EQ(camera.height, 288);
  }
  ASSERT_EQ(campus.frames.size(), 3u);
  EXPECT_EQ(campus.frames[0].id, "campus_000000");
  const Poses3D& gt = campus.frames[0].gt;
  ASSERT_EQ(gt.track_ids, (std::vector<int>{0}));  // only actor 0 is present in the subset
  EXPECT_NEAR(Joint(gt, 0, 0).x(), 1.2796, 1e-4);
  EXPECT_NEAR(Joint(gt, 0, 0).y(), 1.8390, 1e-4);
  EXPECT_NEAR(Joint(gt, 0, 0).z(), 0.0857, 1e-4);

  Eigen::Vector2d uv;
  ASSERT_TRUE(campus.cameras[0].Project(Joint(gt, 0, 0), &uv));
  EXPECT_NEAR(uv.x(), 152.86, 0.01);
  EXPECT_NEAR(uv.y(), 204.39, 0.01);
  const io::MatFile mat = io::ReadMat(test::SharedData("campus/actorsGT.mat"));
  const io::MatValue& stored = mat.Get("actor2D").Cell(0).Cell(0).Cell(0);  // uint8 14x2
  EXPECT_NEAR((uv - Eigen::Vector2d(stored.At(0, 0), stored.At(0, 1))).norm(), 0.0, 1.0);
}

TEST(CampusReader, EmptyDetectionCacheGivesFramesWithoutPersons) {
  RPT_REQUIRE_SHARED_DATA("campus/pred_campus_maskrcnn_hrnet_coco.pkl");
  const Sequence campus =
      ReadDataset(Request("campus", test::SharedData("campus"), {{"frames", "0-2"}, {"detections", "voxelpose"}}))[0];
  EXPECT_EQ(campus.detection_joints, CocoBodyJoints());
  for (const SequenceFrame& frame : campus.frames) {
    ASSERT_EQ(frame.views.size(), 3u);
    for (const Poses2D& view : frame.views) EXPECT_EQ(view.num_persons(), 0);
  }
}

// ---------------------------------------------------------------------------------------
// Files written here

std::string Num(double v, int digits = 17) {
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, v);
  return buffer;
}

// A 3-camera VoxelPose calibration around the origin, one with distortion; R printed with
// `r_digits` significant digits.
std::string CalibrationJson(bool first_camera_has_R = true, int r_digits = 17) {
  std::string text = "{";
  for (int c = 0; c < 3; ++c) {
    const double yaw = 2.0 * M_PI * c / 3.0;
    const Eigen::Vector3d center(4.0 * std::cos(yaw), 4.0 * std::sin(yaw), 2.0);
    // Camera axes: z towards (0, 0, 1), x horizontal, y down.
    const Eigen::Vector3d z = (Eigen::Vector3d(0, 0, 1) - center).normalized();
    const Eigen::Vector3d x = z.cross(Eigen::Vector3d(0, 0, 1)).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Eigen::Matrix3d R;
    R << x.transpose(), y.transpose(), z.transpose();
    text += std::string(c ? ", " : "") + "\"" + std::to_string(c) + "\": {";
    if (c != 0 || first_camera_has_R) {
      text += "\"R\": [";
      for (int r = 0; r < 3; ++r)
        text += std::string(r ? "," : "") + "[" + Num(R(r, 0), r_digits) + "," + Num(R(r, 1), r_digits) + "," +
                Num(R(r, 2), r_digits) + "]";
      text += "], ";
    }
    const Eigen::Vector3d mm = center * 1000.0;
    text += "\"T\": [[" + Num(mm.x()) + "], [" + Num(mm.y()) + "], [" + Num(mm.z()) + "]], ";
    text += "\"fx\": 500, \"fy\": 500, \"cx\": 516, \"cy\": 388, ";
    text +=
        c == 1 ? "\"k\": [[0.01], [0.002], [0.0]], \"p\": [[0.001], [0.0]]" : "\"k\": [[0],[0],[0]], \"p\": [[0],[0]]";
    text += "}";
  }
  return text + "}";
}

// A standing person at (x, y): joint j at height 0.1 * j, 14x3 column-major.
std::vector<double> StandingPose(double x, double y) {
  std::vector<double> column_major(42);
  for (int j = 0; j < 14; ++j) {
    column_major[j] = x + 0.01 * j;
    column_major[14 + j] = y - 0.01 * j;
    column_major[28 + j] = 0.1 * j + 0.05;
  }
  return column_major;
}

// actorsGT.mat with actor3D 1x2: actor 0 present in frames 0, 1, 3; actor 1 in frame 1; the
// empties use both MATLAB shapes. `frame_cell` replaces actor 1 frame 1 when given.
test::ByteVec ActorsMat(bool compressed, const test::ByteVec& replace_actor1_frame1 = {}) {
  auto pose = [](double x, double y) {
    return m::Matrix(m::kDoubleClass, {14, 3}, "", m::Doubles(StandingPose(x, y)));
  };
  const test::ByteVec empty10 = m::Matrix(m::kDoubleClass, {1, 0}, "", m::Doubles({}));
  const test::ByteVec empty00 = m::Matrix(m::kDoubleClass, {0, 0}, "", m::Doubles({}));
  test::ByteVec actor0, actor1;
  for (const auto& cell : {pose(0.5, 0.5), pose(0.6, 0.4), empty10, pose(0.8, 0.2)}) test::Append(actor0, cell);
  for (const auto& cell :
       {empty00, replace_actor1_frame1.empty() ? pose(-1.0, 1.0) : replace_actor1_frame1, empty10, empty00}) {
    test::Append(actor1, cell);
  }
  test::ByteVec actors;
  test::Append(actors, m::Matrix(m::kCellClass, {4, 1}, "", actor0));
  test::Append(actors, m::Matrix(m::kCellClass, {4, 1}, "", actor1));
  const test::ByteVec variable = m::Matrix(m::kCellClass, {1, 2}, "actor3D", actors);
  test::ByteVec file = m::Header();
  test::Append(file, compressed ? m::Compressed(variable) : variable);
  return file;
}

void WriteShelfRoot(const test::TempDir& dir, const test::ByteVec& mat,
                    const std::string& calibration = CalibrationJson()) {
  dir.Write("actorsGT.mat", mat);
  dir.Write("calibration_shelf.json", test::ByteVec(calibration.begin(), calibration.end()));
}

TEST(ShelfReader, GeneratedFilesGroundTruth) {
  for (const bool compressed : {false, true}) {
    SCOPED_TRACE(compressed ? "compressed" : "uncompressed");
    test::TempDir dir;
    WriteShelfRoot(dir, ActorsMat(compressed));
    const Sequence shelf = ReadDataset(Request("shelf", dir.path(), {{"frames", "0-3"}, {"fps", "50"}}))[0];
    ASSERT_EQ(shelf.cameras.size(), 3u);
    EXPECT_EQ(shelf.cameras[1].model, DistortionModel::kOpenCV);
    EXPECT_EQ(shelf.cameras[1].dist, (std::array<double, 5>{0.01, 0.002, 0.001, 0.0, 0.0}));
    EXPECT_EQ(shelf.cameras[0].model, DistortionModel::kNone);
    EXPECT_TRUE(shelf.cameras[2].Center().isApprox(
        Eigen::Vector3d(4.0 * std::cos(4.0 * M_PI / 3.0), 4.0 * std::sin(4.0 * M_PI / 3.0), 2.0), 1e-12));
    ASSERT_EQ(shelf.frames.size(), 4u);
    EXPECT_DOUBLE_EQ(shelf.frames[3].timestamp_s, 3.0 / 50.0);
    EXPECT_EQ(shelf.frames[0].gt.track_ids, (std::vector<int>{0}));
    EXPECT_EQ(shelf.frames[1].gt.track_ids, (std::vector<int>{0, 1}));
    EXPECT_EQ(shelf.frames[2].gt.num_persons(), 0);
    EXPECT_EQ(shelf.frames[3].gt.track_ids, (std::vector<int>{0}));
    const Poses3D& gt = shelf.frames[1].gt;
    EXPECT_TRUE(Joint(gt, 1, 5).isApprox(Eigen::Vector3d(-1.0 + 0.05, 1.0 - 0.05, 0.55), 1e-12));
    EXPECT_TRUE(
        Joint(gt, 0, 14).isApprox(Eigen::Vector3d(0.6 + 0.125, 0.4 - 0.125, 1.3), 1e-12));  // nose = head centre

    // The people stand inside the images of the cameras looking at them.
    Eigen::Vector2d uv;
    ASSERT_TRUE(shelf.cameras[1].Project(Joint(gt, 0, 0), &uv));
    EXPECT_GT(uv.x(), 0);
    EXPECT_LT(uv.x(), 1032);
  }
}

TEST(ShelfReader, RotationsWithSixDigitsAreCountedOnTheSequence) {
  test::TempDir dir;
  WriteShelfRoot(dir, ActorsMat(false), CalibrationJson(true, 6));
  const Sequence shelf = ReadDataset(Request("shelf", dir.path(), {{"frames", "0-1"}}))[0];
  for (const Camera& camera : shelf.cameras) {
    EXPECT_LT((camera.R.transpose() * camera.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  }
  ASSERT_EQ(shelf.warnings.items().size(), 1u);
  EXPECT_EQ(shelf.warnings.items()[0].source, (dir.path() / "calibration_shelf.json").string());
  EXPECT_EQ(shelf.warnings.items()[0].what, "rotations re-orthonormalised");
  EXPECT_EQ(shelf.warnings.items()[0].count, 3);
  EXPECT_EQ(ReadDataset(Request("shelf", dir.path(), {{"frames", "0"}}))[0].warnings.total(), 3);
  WriteShelfRoot(dir, ActorsMat(false));
  EXPECT_TRUE(ReadDataset(Request("shelf", dir.path(), {{"frames", "0"}}))[0].warnings.empty())
      << "17 digits: round-off";
}

TEST(ShelfReader, ActorSelectionOnGeneratedFiles) {
  test::TempDir dir;
  WriteShelfRoot(dir, ActorsMat(false));
  const Sequence shelf = ReadDataset(Request("shelf", dir.path(), {{"frames", "1"}, {"actors", "1"}}))[0];
  EXPECT_EQ(shelf.frames[0].gt.track_ids, (std::vector<int>{1}));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"actors", "2"}, {"frames", "0"}}));
              }),
              HasSubstr("actor 2 requested but actor3D has 2 actors (0-1)"));
}

TEST(ShelfReader, MalformedInputNamesFileAndPlace) {
  test::TempDir dir;
  // No files at all: the calibration is read first.
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "0"}}));
              }),
              HasSubstr((dir.path() / "calibration_shelf.json").string() + ": file not found"));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path() / "nothing", {{"frames", "0"}}));
              }),
              HasSubstr("is not a directory"));

  WriteShelfRoot(dir, ActorsMat(false), CalibrationJson(/*first_camera_has_R=*/false));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "0"}}));
              }),
              HasSubstr("calibration_shelf.json: /0/R: missing"));

  WriteShelfRoot(dir, ActorsMat(false));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "2-4"}}));
              }),
              HasSubstr("actorsGT.mat: frame 4 requested but actor3D has 4 frames (0-3)"));

  // A NaN coordinate and a wrongly shaped pose (actor 1, frame 1 = actor3D{1,2}{2,1}).
  std::vector<double> nan_pose = StandingPose(0, 0);
  nan_pose[20] = std::numeric_limits<double>::quiet_NaN();
  WriteShelfRoot(dir, ActorsMat(false, m::Matrix(m::kDoubleClass, {14, 3}, "", m::Doubles(nan_pose))));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "0-3"}}));
              }),
              HasSubstr("actorsGT.mat: actor3D{1,2}{2,1}: contains NaN or infinity"));
  WriteShelfRoot(dir,
                 ActorsMat(false, m::Matrix(m::kDoubleClass, {13, 3}, "", m::Doubles(std::vector<double>(39, 1.0)))));
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "0-3"}}));
              }),
              HasSubstr("actorsGT.mat: actor3D{1,2}{2,1}: expected a 14x3 numeric matrix, got 13x3 double"));
  // Frames outside the selection are not inspected.
  EXPECT_NO_THROW(ReadDataset(Request("shelf", dir.path(), {{"frames", "0,2-3"}})));

  // A file without actor3D.
  test::ByteVec other = m::Header();
  test::Append(other, m::Matrix(m::kDoubleClass, {1, 1}, "x", m::Doubles({1})));
  WriteShelfRoot(dir, other);
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("shelf", dir.path(), {{"frames", "0"}}));
              }),
              HasSubstr("variable 'actor3D' not found"));
}

TEST(ShelfReader, BadParamsAreConfigErrors) {
  test::TempDir dir;
  WriteShelfRoot(dir, ActorsMat(false));
  const auto config_error = [&](std::map<std::string, std::string> params) {
    return test::ErrorMessage<ConfigError>([&] { ReadDataset(Request("shelf", dir.path(), params)); });
  };
  EXPECT_THAT(config_error({{"frames", "0"}, {"nose_proxy", "middle"}}),
              HasSubstr("shelf.nose_proxy: 'middle' is not one of center, top, bottom"));
  // An actor given twice is refused like a camera given twice (it was merged silently).
  EXPECT_THAT(config_error({{"frames", "0"}, {"actors", "1,0,1"}}), HasSubstr("shelf.actors: actor 1 is listed twice"));
  EXPECT_THAT(config_error({{"frames", "0"}, {"detections", "openpose"}}),
              HasSubstr("'openpose' is not one of none, voxelpose"));
  EXPECT_THAT(config_error({{"frames", "0"}, {"fps", "-1"}}), HasSubstr("fps: '-1' is not a number > 0"));
  EXPECT_THAT(config_error({{"frames", "a-b"}}), HasSubstr("frames"));
  EXPECT_THAT(config_error({{"frames", "0"}, {"actors", "x"}}), HasSubstr("shelf.actors: 'x'"));
  EXPECT_THAT(config_error({{"frames", "0"}, {"camera", "1"}}), HasSubstr("unknown parameter 'camera'"));
}

TEST(CampusReader, InfoDefaultsAndGeneratedFiles) {
  const DatasetInfo info = CampusInfo();
  EXPECT_EQ(info.name, "campus");
  EXPECT_EQ(info.params.at(0).name, "frames");
  EXPECT_EQ(info.params.at(0).default_value, "350-470,650-750");
  EXPECT_EQ(ShelfInfo().name, "shelf");
  EXPECT_EQ(ShelfInfo().params.at(0).default_value, "300-600");

  test::TempDir dir;
  dir.Write("actorsGT.mat", ActorsMat(false));
  const std::string calibration = CalibrationJson();
  dir.Write("calibration_campus.json", test::ByteVec(calibration.begin(), calibration.end()));
  const Sequence campus = ReadDataset(Request("campus", dir.path(), {{"frames", "0-3:3"}}))[0];
  ASSERT_EQ(campus.frames.size(), 2u);
  EXPECT_EQ(campus.frames[1].id, "campus_000003");
  EXPECT_EQ(campus.cameras[0].width, 360);
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request("campus", dir.path(), {{"frames", "0"}, {"detections", "voxelpose"}}));
              }),
              HasSubstr("pred_campus_maskrcnn_hrnet_coco.pkl: file not found"));
}

}  // namespace
}  // namespace rpt
