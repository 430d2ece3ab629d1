// SPDX-License-Identifier: MIT
#include "datasets/readers/egohumans.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>

#include "core/errors.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/reader_stream_test.h"
#include "tests/datasets/readers_h36m_ego_test_util.h"
#include "tests/datasets/tolerance_test_util.h"

namespace rpt {
using engine::ReadDataset;
using engine::OpenDataset;
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::InputErrorOf;
using test::Num;

// One exo camera of the synthetic scene: fisheye intrinsics and its metric pose in the aria01 frame.
struct ExoSpec {
  std::string name;
  int colmap_id;
  double fx, fy, cx, cy, k1, k2, k3, k4;
  Eigen::Vector3d center;  // aria01 frame, metres
  bool manual = false;     // extrinsics from camXX.npy instead of images.txt
};

const std::vector<ExoSpec>& Exos() {
  static const std::vector<ExoSpec> exos = {
      {"cam01", 1, 1750, 1752, 1920, 1080, 0.05, -0.01, 0.002, -0.0003, {4.0, 0.3, 1.5}},
      {"cam02", 2, 1700, 1701, 1910, 1075, 0.04, -0.02, 0.001, 0.0001, {-3.0, 3.0, 2.0}},
      {"cam03", 3, 1800, 1799, 1930, 1085, 0.03, 0.0, 0.0, 0.0, {0.5, -4.0, 1.2}, true},
  };
  return exos;
}

// colmap_from_aria[aria01]: a similarity (scale 1.7).
Eigen::Matrix4d ColmapFromAnchor() {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = 1.7 * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.topRightCorner<3, 1>() = Eigen::Vector3d(0.3, -0.2, 1.1);
  return T;
}

// COLMAP pose cam_from_colmap (rigid) of a camera whose metric aria01-frame pose is (R, -R C).
Eigen::Matrix4d CamFromColmap(const ExoSpec& exo) {
  const Eigen::Matrix4d T = ColmapFromAnchor();
  const double s = std::cbrt(T.topLeftCorner<3, 3>().determinant());
  const Eigen::Matrix3d Q = T.topLeftCorner<3, 3>() / s;
  const Eigen::Vector3d u = T.topRightCorner<3, 1>();
  const Eigen::Matrix3d R = test::LookAt(exo.center, Eigen::Vector3d(0, 0, 1));
  const Eigen::Vector3d t = -R * exo.center;
  Eigen::Matrix4d E = Eigen::Matrix4d::Identity();
  E.topLeftCorner<3, 3>() = R * Q.transpose();
  E.topRightCorner<3, 1>() = s * t - E.topLeftCorner<3, 3>() * u;
  return E;
}

// egohumans ExoCamera.project: E = [R|t](colmap) * colmap_from_aria, then OPENCV_FISHEYE.
Eigen::Vector2d EgohumansProject(const ExoSpec& exo, const Eigen::Vector3d& X) {
  const Eigen::Matrix4d E = CamFromColmap(exo) * ColmapFromAnchor();
  const Eigen::Vector3d p = (E * X.homogeneous()).head<3>();
  const double a = p.x() / p.z(), b = p.y() / p.z();
  const double r = std::hypot(a, b);
  const double theta = std::atan(r);
  const double t2 = theta * theta;
  const double theta_d = theta * (1 + exo.k1 * t2 + exo.k2 * t2 * t2 + exo.k3 * t2 * t2 * t2 + exo.k4 * t2 * t2 * t2 * t2);
  const double scale = r > 1e-12 ? theta_d / r : 1.0;
  return Eigen::Vector2d(exo.fx * scale * a + exo.cx, exo.fy * scale * b + exo.cy);
}

// COCO-17 joints (metres, aria01 frame) of person `p` at time stamp `t`.
Eigen::Matrix<double, 3, 17> Person(int p, int t) {
  Eigen::Matrix<double, 3, 17> X;
  for (int j = 0; j < 17; ++j) {
    X.col(j) << 0.8 * p - 0.4 + 0.1 * std::sin(j + 0.2 * t), 0.5 * p + 0.08 * std::cos(1.3 * j), 1.7 - 0.09 * j + 0.01 * t;
  }
  return X;
}

// Valid flag of person p, joint j at time t: aria02 loses joint 5 at t = 2 and everything at t = 3.
bool Valid(int p, int j, int t) { return !(p == 1 && ((t == 2 && j == 5) || t == 3)); }

std::vector<double> Flat(const Eigen::Matrix4d& m) {
  std::vector<double> values;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values.push_back(m(r, c));
  }
  return values;
}

test::Obj Matrix4Obj(const Eigen::Matrix4d& m) { return test::PyArray({4, 4}, Flat(m)); }

struct TreeOptions {
  bool nan_in_gt = false;
  bool bad_quaternion = false;   // image 3's quaternion scaled by 1.2
  bool gt_wrong_shape = false;
  int quaternion_digits = 17;    // significant digits of the quaternions in images.txt
  double quaternion_scale = 1.0;  // image 3's quaternion scaled by this
  int anchor_digits = 17;        // significant digits of colmap_from_aria[aria01]
  double anchor_stretch = 1.0;   // colmap_from_aria[aria01] stretched along y: not a similarity
  double joint0_score = 1.25;    // 2D cache score of joint 0 (HRNet may exceed 1)
};

// `m` with every entry rounded to `digits` significant digits.
Eigen::Matrix4d Rounded(const Eigen::Matrix4d& m, int digits) {
  Eigen::Matrix4d out = m;
  for (Eigen::Index i = 0; i < 16; ++i) out.data()[i] = std::stod(test::NumDigits(out.data()[i], digits));
  return out;
}

// Writes data/01_tagging/001_tagging with time stamps 1..3 and returns the sequence directory.
fs::path WriteTree(const fs::path& data, const TreeOptions& options = {}) {
  const fs::path seq = data / "01_tagging" / "001_tagging";
  const fs::path work = seq / "colmap" / "workplace";
  std::string cameras = "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n# Number of cameras: 4\n";
  for (const ExoSpec& e : Exos()) {
    cameras += std::to_string(e.colmap_id) + " OPENCV_FISHEYE 3840 2160 " + Num(e.fx) + " " + Num(e.fy) + " " + Num(e.cx) + " " + Num(e.cy) +
               " " + Num(e.k1) + " " + Num(e.k2) + " " + Num(e.k3) + " " + Num(e.k4) + "\n";
  }
  cameras += "4 FOV 1408 1408 600 600 704 704 0.9\n";  // an Aria camera: ignored
  test::WriteText(work / "cameras.txt", cameras);

  std::string images = "# Image list with two lines of data per image:\n#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n#   POINTS2D[] as (X, Y, POINT3D_ID)\n# Number of images: 5\n";
  auto image_line = [&](int id, const Eigen::Matrix4d& E, int camera, const std::string& name) {
    Eigen::Quaterniond q(Eigen::Matrix3d(E.topLeftCorner<3, 3>()));
    if (options.bad_quaternion && id == 3) q.coeffs() *= 1.2;
    if (id == 3) q.coeffs() *= options.quaternion_scale;
    const int d = options.quaternion_digits;
    images += std::to_string(id) + " " + test::NumDigits(q.w(), d) + " " + test::NumDigits(q.x(), d) + " " +
              test::NumDigits(q.y(), d) + " " + test::NumDigits(q.z(), d) + " " + Num(E(0, 3)) + " " +
              Num(E(1, 3)) + " " + Num(E(2, 3)) + " " + std::to_string(camera) + " " + name + "\n" + "100.5 200.5 12 300 400 -1\n";
  };
  Eigen::Matrix4d wrong = CamFromColmap(Exos()[0]);
  wrong.topRightCorner<3, 1>() += Eigen::Vector3d(0.5, 0.1, -0.2);
  image_line(1, CamFromColmap(Exos()[0]), 1, "cam01/00001.jpg");
  image_line(2, wrong, 1, "cam01/00050.jpg");  // farther in time: not used for time stamp 1
  image_line(3, CamFromColmap(Exos()[1]), 2, "cam02/00003.jpg");
  image_line(4, wrong, 3, "cam03/00001.jpg");  // overridden by the manual cam03.npy
  image_line(5, Eigen::Matrix4d::Identity(), 4, "aria01/00001.jpg");
  test::WriteText(work / "images.txt", images);
  test::WriteBytes(work / "cam03.npy",
                   test::NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }", test::RawOf(Flat(CamFromColmap(Exos()[2])))));

  Eigen::Matrix4d other = Eigen::Matrix4d::Identity();
  other.topRightCorner<3, 1>() = Eigen::Vector3d(5, 5, 5);
  Eigen::Matrix4d anchor = Rounded(ColmapFromAnchor(), options.anchor_digits);
  anchor.row(1).head<3>() *= options.anchor_stretch;
  test::WriteBytes(work / "colmap_from_aria_transforms.pkl",
                   test::PickleOf(test::PyDict({{test::PyStr("aria01"), Matrix4Obj(anchor)},
                                                {test::PyStr("aria02"), Matrix4Obj(other)}})));

  for (int t = 1; t <= 3; ++t) {
    std::vector<std::pair<test::Obj, test::Obj>> gt;
    for (int p = 0; p < 2; ++p) {
      const auto X = Person(p, t);
      std::vector<double> values;
      for (int j = 0; j < 17; ++j) {
        const bool valid = Valid(p, j, t);
        for (int d = 0; d < 3; ++d) values.push_back(valid ? X(d, j) : 0.0);
        values.push_back(valid ? 1.0 : 0.0);
      }
      if (options.nan_in_gt && t == 2 && p == 0) values[4 * 3 + 1] = std::nan("");
      const std::vector<std::int64_t> shape = options.gt_wrong_shape && t == 2 ? std::vector<std::int64_t>{17, 2, 2}
                                                                               : std::vector<std::int64_t>{17, 4};
      gt.emplace_back(test::PyStr("aria0" + std::to_string(p + 1)), test::PyArray(shape, values));
    }
    const std::string file = "0000" + std::to_string(t) + ".npy";
    test::WriteBytes(seq / "processed_data" / "poses3d" / file, test::NpyOfObject(test::PyDict(gt)));
    if (t == 1) test::WriteBytes(seq / "processed_data" / "fit_poses3d" / file, test::NpyOfObject(test::PyDict(gt)));

    for (const ExoSpec& e : Exos()) {
      std::vector<test::Obj> people;
      for (int p = 0; p < 2; ++p) {
        const auto X = Person(p, t);
        std::vector<double> keypoints(133 * 3, 0.0);
        for (int j = 0; j < 17; ++j) {
          if (!Valid(p, j, t)) continue;
          const Eigen::Vector2d uv = EgohumansProject(e, X.col(j));
          keypoints[static_cast<std::size_t>(3 * j)] = uv.x();
          keypoints[static_cast<std::size_t>(3 * j + 1)] = uv.y();
          keypoints[static_cast<std::size_t>(3 * j + 2)] = j == 0 ? options.joint0_score : 0.9;
        }
        people.push_back(test::PyDict({{test::PyStr("human_name"), test::PyStr("aria0" + std::to_string(p + 1))},
                                       {test::PyStr("bbox"), test::PyArray({5}, {10, 20, 300, 400, 0.99})},
                                       {test::PyStr("keypoints"), test::PyArray({133, 3}, keypoints)}}));
      }
      if (t == 3 && e.name == "cam02") people.clear();  // nobody detected
      test::WriteBytes(seq / "processed_data" / "poses2d" / e.name / "rgb" / file, test::NpyOfObjectList(people));
    }
  }
  return seq;
}

DatasetRequest Request(const fs::path& root, std::map<std::string, std::string> params = {}) {
  DatasetRequest request;
  request.dataset = "egohumans";
  request.root = root;
  request.params = std::move(params);
  return request;
}

TEST(EgohumansReader, GtProjectsOntoTheTwoDCache) {
  test::TempDir dir;
  const fs::path data = dir.path() / "data";
  WriteTree(data);
  const auto sequences = ReadDataset(Request(data, {{"detections", "cache"}}));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& seq = sequences[0];
  EXPECT_EQ(seq.name, "egohumans/01_tagging/001_tagging");
  EXPECT_EQ(seq.gt_joints, CocoBodyJoints());
  EXPECT_EQ(seq.detection_joints, CocoWholeBodyJoints());
  ASSERT_EQ(seq.cameras.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c) {
    const Camera& camera = seq.cameras[c];
    EXPECT_EQ(camera.name, Exos()[c].name);
    EXPECT_EQ(camera.model, DistortionModel::kFisheye);
    EXPECT_EQ(camera.width, 3840);
    EXPECT_EQ(camera.height, 2160);
    EXPECT_DOUBLE_EQ(camera.dist[1], Exos()[c].k2);
    // Metric pose in the anchor frame despite the scaled colmap_from_aria.
    EXPECT_LT((camera.Center() - Exos()[c].center).norm(), 1e-9) << camera.name;
  }
  ASSERT_EQ(seq.frames.size(), 3u);
  EXPECT_EQ(seq.frames[0].id, "egohumans_01_tagging_001_tagging_00001");
  EXPECT_DOUBLE_EQ(seq.frames[2].timestamp_s, 2 / 20.0);

  double worst_px = 0;
  int checked = 0;
  for (int t = 1; t <= 3; ++t) {
    const SequenceFrame& frame = seq.frames[static_cast<std::size_t>(t - 1)];
    const Poses3D& gt = frame.gt;
    ASSERT_EQ(gt.num_persons(), t == 3 ? 1 : 2);
    ASSERT_EQ(frame.views.size(), 3u);
    for (int p = 0; p < gt.num_persons(); ++p) {
      EXPECT_EQ(gt.track_ids[static_cast<std::size_t>(p)], p + 1);
      const auto person = gt.Person(p);
      for (int j = 0; j < 17; ++j) {
        EXPECT_EQ(person(3, j), Valid(p, j, t) ? 1.0 : 0.0);
        if (!Valid(p, j, t)) continue;
        EXPECT_LT((person.col(j).head<3>() - Person(p, t).col(j)).norm(), 1e-12);
        for (std::size_t c = 0; c < 3; ++c) {
          const Poses2D& view = frame.views[c];
          if (t == 3 && c == 1) {
            EXPECT_EQ(view.num_persons(), 0);
            continue;
          }
          ASSERT_EQ(view.num_persons(), 2);
          const auto detection = view.Person(p);
          Eigen::Vector2d uv;
          ASSERT_TRUE(seq.cameras[c].Project(person.col(j).head<3>(), &uv));
          worst_px = std::max(worst_px, (uv - detection.col(j).head<2>()).norm());
          EXPECT_EQ(detection(2, j), j == 0 ? 1.0 : 0.9);  // 1.25 clamped to 1
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 200);
  EXPECT_LT(worst_px, 1e-6);
  // The clamped scores are counted in one line for the sequence's cache folder: joint 0 of every
  // detected person (2 per view at t = 1, 2; only aria01 at t = 3, and cam02 sees nobody then).
  const std::string cache_dir = (data / "01_tagging" / "001_tagging" / "processed_data" / "poses2d").string();
  test::ExpectOneWarning(seq.warnings, cache_dir, test::kScoresClamped, 6 + 6 + 2);

  // Without detections=cache the same walk reads no 2D.
  const Sequence without = ReadDataset(Request(data))[0];
  EXPECT_TRUE(without.frames[0].views.empty());
  EXPECT_EQ(without.frames.size(), seq.frames.size());
}

TEST(EgohumansReader, RootLevelsAndParams) {
  test::TempDir dir;
  const fs::path data = dir.path() / "data";
  const fs::path seq_dir = WriteTree(data);
  // root = one big sequence, or the sequence itself.
  EXPECT_EQ(ReadDataset(Request(data / "01_tagging"))[0].name, "egohumans/01_tagging/001_tagging");
  const auto single = ReadDataset(Request(seq_dir, {{"cameras", "cam02,cam01"}, {"every", "2"}}));
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].cameras.size(), 2u);
  EXPECT_EQ(single[0].cameras[0].name, "cam01");
  ASSERT_EQ(single[0].frames.size(), 2u);
  EXPECT_EQ(single[0].frames[1].id, "egohumans_01_tagging_001_tagging_00003");
  EXPECT_EQ(ReadDataset(Request(data, {{"max_frames", "1"}}))[0].frames.size(), 1u);
  EXPECT_EQ(ReadDataset(Request(data, {{"gt", "fit_poses3d"}}))[0].frames.size(), 1u);
  EXPECT_EQ(ReadDataset(Request(data, {{"sequences", "001_tagging"}})).size(), 1u);
  // Another anchor moves the cameras (GT stays in the file's frame).
  const auto other = ReadDataset(Request(data, {{"anchor", "aria02"}}));
  EXPECT_GT((other[0].cameras[0].Center() - Exos()[0].center).norm(), 0.1);

  EXPECT_THROW(ReadDataset(Request(data, {{"gt", "smpl"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(data, {{"detections", "hrnet"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(data, {{"fps", "-3"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(data, {{"frames", "1-3"}})), ConfigError);
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(data, {{"sequences", "02_lego/001_lego"}}));
              }),
              HasSubstr("unknown sequence '02_lego/001_lego' (found 01_tagging/001_tagging)"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(data, {{"cameras", "cam09"}}));
              }),
              HasSubstr("cameras.txt: unknown exo camera 'cam09'"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(data, {{"anchor", "aria07"}}));
              }),
              HasSubstr("colmap_from_aria_transforms.pkl: top level: missing key 'aria07'"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(data, {{"gt", "refine_poses3d"}}));
              }),
              HasSubstr("refine_poses3d: ground-truth directory not found"));
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path() / "nothing")); }),
              HasSubstr("nothing: not a directory"));
}

TEST(EgohumansReader, RoundedQuaternionsAndAnchorAreCorrectedAndCounted) {
  test::TempDir dir;
  const fs::path data = dir.path() / "data";
  const fs::path seq_dir = WriteTree(data, {.quaternion_digits = 6, .anchor_digits = 6});
  const Sequence seq = ReadDataset(Request(data))[0];
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_LT(test::OrthonormalityError(seq.cameras[c].R), 1e-12);
    EXPECT_LT((seq.cameras[c].Center() - Exos()[c].center).norm(), 1e-4) << seq.cameras[c].name;
  }
  const fs::path work = seq_dir / "colmap" / "workplace";
  const std::string anchor = " composed with " + (work / "colmap_from_aria_transforms.pkl").string() + "['aria01']";
  // Four rounded quaternions (the identity of the Aria image is exact); the rounded similarity
  // makes every camera's composed rotation off by ~1e-6: one line per file combination.
  ASSERT_EQ(seq.warnings.items().size(), 3u) << seq.warnings.items()[0].Line();
  EXPECT_EQ(seq.warnings.items()[0].source, (work / "images.txt").string());
  EXPECT_EQ(seq.warnings.items()[0].what, test::kQuaternionsFixed);
  EXPECT_EQ(seq.warnings.items()[0].count, 4);
  EXPECT_EQ(seq.warnings.items()[1].source, (work / "images.txt").string() + anchor);
  EXPECT_EQ(seq.warnings.items()[1].what, test::kRotationsFixed);
  EXPECT_EQ(seq.warnings.items()[1].count, 2);
  EXPECT_EQ(seq.warnings.items()[2].source, (work / "cam03.npy").string() + anchor);
  EXPECT_EQ(seq.warnings.items()[2].count, 1);
}

TEST(EgohumansReader, RotationsBeyondTheToleranceNameFileAndLine) {
  {
    test::TempDir dir;
    WriteTree(dir.path(), {.quaternion_scale = 1.01});
    EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("images.txt:9: quaternion ("));
    EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
                HasSubstr(") has norm 1.01, expected a unit quaternion"));
  }
  test::TempDir dir;
  WriteTree(dir.path(), {.anchor_stretch = 1.01});
  EXPECT_THAT(
      InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
      HasSubstr("images.txt:5 composed with " +
                (dir.path() / "01_tagging" / "001_tagging" / "colmap" / "workplace" / "colmap_from_aria_transforms.pkl")
                    .string() +
                "['aria01']: camera_from_anchor / scale: R is not a rotation"));
}

TEST(EgohumansReader, CacheScoresSlightlyAboveOneAreClampedAndCounted) {
  test::TempDir dir;
  const fs::path seq_dir = WriteTree(dir.path(), {.joint0_score = 1.018});
  const Sequence seq = ReadDataset(Request(dir.path(), {{"detections", "cache"}}))[0];
  for (const SequenceFrame& frame : seq.frames) {
    for (const Poses2D& view : frame.views) {
      for (int p = 0; p < view.num_persons(); ++p) EXPECT_LE(view.Person(p)(2, 0), 1.0);
    }
  }
  EXPECT_EQ(seq.frames[0].views[0].Person(0)(2, 0), 1.0);
  test::ExpectOneWarning(seq.warnings, (seq_dir / "processed_data" / "poses2d").string(), test::kScoresClamped, 14);
  EXPECT_DOUBLE_EQ(seq.warnings.items()[0].worst, 1.018);
}

TEST(EgohumansReader, CacheScoresNegativeLargeOrNanNameFileAndJoint) {
  for (const double score : {1.6, -0.1, std::nan("")}) {
    test::TempDir dir;
    WriteTree(dir.path(), {.joint0_score = score});
    const std::string what = std::isnan(score) ? "joint 0: NaN or infinite value"
                             : score > 1      ? "joint 0: score 1.6 outside [0, 1]"
                                              : "joint 0: score -0.1 outside [0, 1]";
    EXPECT_THAT(InputErrorOf([&] {
                  ReadDataset(Request(dir.path(), {{"detections", "cache"}}));
                }),
                HasSubstr("poses2d/cam01/rgb/00001.npy: [0].keypoints: " + what));
  }
}

TEST(EgohumansReader, GroundTruthEntriesNotNamedByTimeStampAreCounted) {
  test::TempDir dir;
  const fs::path seq_dir = WriteTree(dir.path());
  const fs::path gt_dir = seq_dir / "processed_data" / "poses3d";
  const size_t frames = ReadDataset(Request(dir.path()))[0].frames.size();
  // Before: ignored without a word (a renamed or misnamed frame simply vanished).
  test::WriteText(gt_dir / "00009_old.npy", "x");
  test::WriteText(gt_dir / "notes.txt", "x");
  const Sequence seq = ReadDataset(Request(dir.path()))[0];
  EXPECT_EQ(seq.frames.size(), frames);
  test::ExpectOneWarning(seq.warnings, gt_dir.string(),
                         "entries not named <time stamp>.npy ignored (e.g. '00009_old.npy')", 2);
  EXPECT_EQ(seq.warnings.items()[0].kind, InputWarningKind::kUnused);
}

// The exo pose comes from the camera's image nearest in time to the first GT time stamp. A GT time
// stamp 0 and an only image cam02/2147483647.jpg are INT_MAX apart: that distance used to leave the
// nearest image unset (a null pointer read); it is computed in 64 bits now.
TEST(EgohumansReader, ImageTimeStampsAnIntApartFromTheGtStillGiveThePose) {
  test::TempDir dir;
  const fs::path seq = WriteTree(dir.path());
  const fs::path gt_dir = seq / "processed_data" / "poses3d";
  fs::copy_file(gt_dir / "00001.npy", gt_dir / "00000.npy");
  const fs::path images = seq / "colmap" / "workplace" / "images.txt";
  std::ifstream in(images);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find("cam02/00003.jpg");
  ASSERT_NE(at, std::string::npos);
  test::WriteText(images, text.replace(at, 15, "cam02/2147483647.jpg"));
  const Sequence sequence = ReadDataset(Request(dir.path(), {{"max_frames", "1"}}))[0];
  ASSERT_EQ(sequence.frames.size(), 1u);
  EXPECT_EQ(sequence.frames[0].id, "egohumans_01_tagging_001_tagging_00000");
  ASSERT_EQ(sequence.cameras.size(), 3u);
  EXPECT_EQ(sequence.cameras[1].name, "cam02");
  EXPECT_LT((sequence.cameras[1].Center() - Exos()[1].center).norm(), 1e-9);
}

TEST(EgohumansReader, MalformedInputsNameFileAndPlace) {
  {
    test::TempDir dir;
    WriteTree(dir.path(), {.nan_in_gt = true});
    EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
                HasSubstr("poses3d/00002.npy: key 'aria01': joint 3: NaN or infinite coordinate"));
  }
  {
    test::TempDir dir;
    WriteTree(dir.path(), {.gt_wrong_shape = true});
    EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
                HasSubstr("poses3d/00002.npy: key 'aria01': expected shape (17, 4)"));
  }
  {
    test::TempDir dir;
    WriteTree(dir.path(), {.bad_quaternion = true});
    EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("images.txt:9: quaternion"));
  }
  test::TempDir dir;
  const fs::path seq = WriteTree(dir.path());
  // Truncated GT file.
  const fs::path gt = seq / "processed_data" / "poses3d" / "00003.npy";
  fs::resize_file(gt, fs::file_size(gt) - 20);
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("poses3d/00003.npy"));
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"max_frames", "2"}}))[0].frames.size(), 2u);
  // Missing / malformed 2D cache.
  fs::remove(seq / "processed_data" / "poses2d" / "cam02" / "rgb" / "00001.npy");
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "cache"}, {"max_frames", "2"}}));
              }),
              HasSubstr("poses2d/cam02/rgb/00001.npy: 2D pose cache file not found"));
  test::WriteBytes(seq / "processed_data" / "poses2d" / "cam02" / "rgb" / "00001.npy",
                   test::NpyOfObjectList({test::PyDict({{test::PyStr("keypoints"), test::PyArray({17, 3}, std::vector<double>(51, 1.0))}})}));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "cache"}, {"max_frames", "1"}}));
              }),
              HasSubstr("cam02/rgb/00001.npy: [0].keypoints: expected shape (133, 3)"));
  // A malformed 4x4 manual calibration and a missing cameras.txt.
  const fs::path work = seq / "colmap" / "workplace";
  test::WriteBytes(work / "cam03.npy", test::NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }", test::RawOf(std::vector<double>(12, 0.0))));
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("cam03.npy: top level: expected 16 numbers, got shape (3, 4)"));
  fs::remove(work / "cameras.txt");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("cameras.txt: file not found"));
}

// The reader contract (tests/datasets/reader_stream_test.cc): streamed equals materialised, with the
// 2D cache (its scores above 1 counted as the frames are pulled).
using test::ReaderStreamTest;
INSTANTIATE_TEST_SUITE_P(Egohumans, ReaderStreamTest,
                         ::testing::Values(test::ReaderFixture{
                             "WithCache",
                             {},
                             [](const fs::path& dir) {
                               WriteTree(dir / "data");
                               return OpenDataset(Request(dir / "data", {{"detections", "cache"}}));
                             }}),
                         test::ReaderFixtureName);

}  // namespace
}  // namespace rpt
