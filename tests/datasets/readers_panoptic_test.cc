// SPDX-License-Identifier: MIT
// CMU Panoptic reader: the mmpose subset in shared/data (160906_band1/2, 20 annotation files
// each) and small sequences written by the tests.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"
#include "datasets/frame_source.h"
#include "datasets/readers/panoptic.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
using engine::ReadDataset;
namespace {

using ::testing::HasSubstr;


DatasetRequest Request(const std::filesystem::path& root, std::map<std::string, std::string> params) {
  DatasetRequest request;
  request.dataset = "panoptic";
  request.root = root;
  request.params = std::move(params);
  return request;
}

std::filesystem::path WriteText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

nlohmann::json LoadJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// panoptic-toolbox panutils.projectPoints, written out: world in cm (y down), R/t/K/distCoef
// exactly as stored.
Eigen::Vector2d PanopticProject(const nlohmann::json& camera, const Eigen::Vector3d& X_cm) {
  Eigen::Matrix3d R, K;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      R(r, c) = camera["R"][r][c].get<double>();
      K(r, c) = camera["K"][r][c].get<double>();
    }
  }
  const Eigen::Vector3d t(camera["t"][0][0].get<double>(), camera["t"][1][0].get<double>(),
                          camera["t"][2][0].get<double>());
  const auto d = camera["distCoef"].get<std::vector<double>>();
  const Eigen::Vector3d x = R * X_cm + t;
  const double a = x.x() / x.z(), b = x.y() / x.z();
  const double r = a * a + b * b;
  const double radial = 1 + d[0] * r + d[1] * r * r + d[4] * r * r * r;
  const double ad = a * radial + 2 * d[2] * a * b + d[3] * (r + 2 * a * a);
  const double bd = b * radial + d[2] * (r + 2 * b * b) + 2 * d[3] * a * b;
  return Eigen::Vector2d(K(0, 0) * ad + K(0, 1) * bd + K(0, 2), K(1, 0) * ad + K(1, 1) * bd + K(1, 2));
}

const nlohmann::json* FindCamera(const nlohmann::json& calibration, const std::string& name) {
  for (const auto& camera : calibration["cameras"]) {
    if (camera["name"] == name) return &camera;
  }
  return nullptr;
}

// ---------------------------------------------------------------------------------------
// Real fixture (mmpose subset; skipped when shared/data is absent)

TEST(PanopticReader, FixtureSequenceCamerasAndFrames) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const std::vector<Sequence> sequences =
      ReadDataset(Request(test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"every", "1"}}));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& band1 = sequences[0];
  EXPECT_EQ(band1.name, "panoptic/160906_band1");
  EXPECT_EQ(band1.gt_joints, PanopticJoints());
  ASSERT_EQ(band1.cameras.size(), 5u);
  const std::vector<std::string> names = {"00_03", "00_06", "00_12", "00_13", "00_23"};
  for (size_t c = 0; c < names.size(); ++c) {
    EXPECT_EQ(band1.cameras[c].name, names[c]);
    EXPECT_EQ(band1.cameras[c].width, 1920);
    EXPECT_EQ(band1.cameras[c].height, 1080);
    EXPECT_EQ(band1.cameras[c].model, DistortionModel::kOpenCV);
  }
  ASSERT_EQ(band1.frames.size(), 20u);
  const SequenceFrame& frame = band1.frames[0];
  EXPECT_EQ(frame.id, "panoptic_160906_band1_000168");
  EXPECT_DOUBLE_EQ(frame.timestamp_s, 168 / 29.97);
  EXPECT_EQ(frame.gt.track_ids, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(band1.frames[19].id, "panoptic_160906_band1_000187");

  // z up, metres: the neck above the body centre (people may sit), the body centre 0.3-1.3 m up.
  const int neck = FindJoint(band1.gt_joints, "neck");
  const int center = FindJoint(band1.gt_joints, "body_center");
  for (int p = 0; p < frame.gt.num_persons(); ++p) {
    const auto person = frame.gt.Person(p);
    EXPECT_GT(person(2, neck) - person(2, center), 0.15);
    EXPECT_LT(person(2, neck) - person(2, center), 0.8);
    EXPECT_GT(person(2, center), 0.3);
    EXPECT_LT(person(2, center), 1.3);
    // VoxelPose's room (centre (0, -0.5, 0.8) m, size (8, 8, 2) m) contains the root.
    EXPECT_LT((person.col(center).head<3>() - band1.room.center_m).cwiseAbs().maxCoeff(), 4.0);
  }
  // Missing joints (c = -1 in the file) get score 0; others keep their confidence.
  bool saw_missing = false;
  for (int p = 0; p < frame.gt.num_persons(); ++p) {
    for (int j = 0; j < 19; ++j) {
      const double score = frame.gt.Person(p)(3, j);
      EXPECT_GE(score, 0.0);
      EXPECT_LE(score, 1.0);
      saw_missing |= score == 0.0;
    }
  }
  EXPECT_TRUE(saw_missing);
}

TEST(PanopticReader, ConvertedCamerasReproduceTheOriginalProjection) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const Sequence band1 =
      ReadDataset(Request(test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"max_frames", "1"}}))[0];
  const nlohmann::json calibration = LoadJson(test::SharedData("panoptic/160906_band1/calibration_160906_band1.json"));
  const nlohmann::json scene =
      LoadJson(test::SharedData("panoptic/160906_band1/hdPose3d_stage1_coco19/body3DScene_00000168.json"));
  ASSERT_EQ(band1.frames[0].id, "panoptic_160906_band1_000168");
  const Poses3D& gt = band1.frames[0].gt;
  ASSERT_EQ(gt.num_persons(), static_cast<int>(scene["bodies"].size()));
  int compared = 0;
  for (const Camera& camera : band1.cameras) {
    const nlohmann::json* original = FindCamera(calibration, camera.name);
    ASSERT_NE(original, nullptr);
    for (int p = 0; p < gt.num_persons(); ++p) {
      const auto joints = scene["bodies"][p]["joints19"].get<std::vector<double>>();
      for (int j = 0; j < 19; j += 3) {
        if (joints[4 * j + 3] <= 0.1) continue;
        const Eigen::Vector3d X_cm(joints[4 * j], joints[4 * j + 1], joints[4 * j + 2]);
        // The reader's converted joint is the converted file point.
        EXPECT_TRUE(gt.Person(p).col(j).head<3>().isApprox(PanopticPointToWorld(X_cm), 1e-12));
        Eigen::Vector2d uv;
        ASSERT_TRUE(camera.Project(gt.Person(p).col(j).head<3>(), &uv));
        EXPECT_LT((uv - PanopticProject(*original, X_cm)).norm(), 1e-6)
            << camera.name << " person " << p << " joint " << j;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 50);
}

TEST(PanopticReader, VisibleJointsFallInsideTheDefaultCameras) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const Sequence band1 =
      ReadDataset(Request(test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"max_frames", "1"}}))[0];
  const Poses3D& gt = band1.frames[0].gt;
  ASSERT_EQ(gt.num_persons(), 3);
  for (const Camera& camera : band1.cameras) {
    int visible = 0, inside = 0;
    for (int p = 0; p < gt.num_persons(); ++p) {
      for (int j = 0; j < gt.num_joints; ++j) {
        if (gt.Person(p)(3, j) <= 0.1) continue;
        ++visible;
        Eigen::Vector2d uv;
        if (camera.Project(gt.Person(p).col(j).head<3>(), &uv) && uv.x() >= 0 && uv.x() < 1920 && uv.y() >= 0 &&
            uv.y() < 1080)
          ++inside;
      }
    }
    const double fraction = static_cast<double>(inside) / visible;
    EXPECT_GE(fraction, 0.67) << camera.name;
    EXPECT_LE(fraction, 1.0) << camera.name;
  }
}

TEST(PanopticReader, EveryMaxFramesAndAllHdCameras) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band2");
  const std::filesystem::path root = test::SharedData("panoptic");
  const std::string both = "160906_band1,160906_band2";
  const auto every1 = ReadDataset(Request(root, {{"sequences", both}, {"every", "1"}}));
  ASSERT_EQ(every1.size(), 2u);
  EXPECT_EQ(every1[0].frames.size(), 20u);
  EXPECT_EQ(every1[1].frames.size(), 20u);
  EXPECT_EQ(every1[1].frames[0].id, "panoptic_160906_band2_000139");

  const auto every12 = ReadDataset(Request(root, {{"sequences", both}}));  // default every=12
  ASSERT_EQ(every12[0].frames.size(), 2u);
  EXPECT_EQ(every12[0].frames[1].id, "panoptic_160906_band1_000180");
  EXPECT_EQ(every12[1].frames[1].id, "panoptic_160906_band2_000151");

  const auto limited = ReadDataset(Request(root, {{"sequences", "160906_band2"}, {"every", "3"}, {"max_frames", "4"}}));
  ASSERT_EQ(limited[0].frames.size(), 4u);
  EXPECT_EQ(limited[0].frames[3].id, "panoptic_160906_band2_000148");

  const auto hd = ReadDataset(Request(root, {{"sequences", "160906_band1"}, {"cameras", "hd"}, {"max_frames", "1"}}));
  ASSERT_EQ(hd[0].cameras.size(), 31u);
  for (int c = 0; c < 31; ++c) {
    char name[8];
    std::snprintf(name, sizeof(name), "00_%02d", c);
    EXPECT_EQ(hd[0].cameras[c].name, name);
  }
}

TEST(PanopticReader, DefaultSequencesAreReportedMissing) {
  RPT_REQUIRE_SHARED_DATA("panoptic");
  EXPECT_THAT(test::InputErrorOf([] { ReadDataset(Request(test::SharedData("panoptic"), {})); }),
              HasSubstr("panoptic: sequence '160906_pizza1' not found"));
  EXPECT_THAT(
      test::InputErrorOf([] {
        ReadDataset(Request(test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"cameras", "00_03,00_99"}}));
      }),
      HasSubstr("calibration_160906_band1.json: camera '00_99' not found; HD cameras: 00_00, 00_01, 00_02"));
}

TEST(PanopticReader, StreamsOneAnnotationFilePerFramePulled) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const DatasetRequest request =
      Request(test::SharedData("panoptic"), {{"sequences", "160906_band1,160906_band2"}, {"every", "1"}});
  const std::vector<Sequence> read = ReadDataset(request);
  std::vector<std::unique_ptr<FrameSource>> sources = OpenPanoptic(request);
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0]->num_frames(), -1) << "skip_empty: the count is known once the files are read";
  for (size_t s = 0; s < sources.size(); ++s) {
    EXPECT_EQ(sources[s]->header().cameras.size(), read[s].cameras.size());
    SequenceFrame frame;  // one buffer for every frame
    size_t f = 0;
    while (sources[s]->Next(&frame)) {
      ASSERT_LT(f, read[s].frames.size());
      EXPECT_EQ(frame.id, read[s].frames[f].id);
      EXPECT_EQ(frame.gt.data, read[s].frames[f].gt.data);
      ++f;
    }
    EXPECT_EQ(f, read[s].frames.size());
  }
  const std::vector<std::unique_ptr<FrameSource>> counted = OpenPanoptic(
      Request(test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"every", "3"}, {"skip_empty", "false"}}));
  const Sequence all = Materialize(*OpenPanoptic(Request(
      test::SharedData("panoptic"), {{"sequences", "160906_band1"}, {"every", "3"}, {"skip_empty", "false"}}))[0]);
  EXPECT_EQ(counted[0]->num_frames(), 7) << "20 files, every 3rd: known in advance without skip_empty";
  EXPECT_EQ(static_cast<long>(all.frames.size()), counted[0]->num_frames());
}

// ---------------------------------------------------------------------------------------
// Files written here

std::string Num(double v, int digits = 17) {
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, v);
  return buffer;
}

// A Panoptic camera at `center_cm` (Panoptic world: y down) looking at (0, -100, 0) cm; R printed
// with `r_digits` significant digits.
std::string PanopticCameraJson(const std::string& name, const std::string& type, const Eigen::Vector3d& center_cm,
                               const std::string& override_R = "", int r_digits = 17) {
  const Eigen::Vector3d z = (Eigen::Vector3d(0, -100, 0) - center_cm).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d(0, 1, 0).cross(z).normalized();  // world "down" is +y
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R << x.transpose(), y.transpose(), z.transpose();
  const Eigen::Vector3d t = -R * center_cm;
  std::string r_json = "[";
  for (int r = 0; r < 3; ++r)
    r_json += std::string(r ? "," : "") + "[" + Num(R(r, 0), r_digits) + "," + Num(R(r, 1), r_digits) + "," +
              Num(R(r, 2), r_digits) + "]";
  r_json += "]";
  if (!override_R.empty()) r_json = override_R;
  const bool hd = type == "hd";
  std::string s = "{\"name\": \"" + name + "\", \"type\": \"" + type + "\", \"resolution\": [" +
                  (hd ? "1920, 1080" : "640, 480") +
                  "], \"panel\": 0, \"node\": 0, \"K\": [[1500, 0, 960], [0, 1500, 540], [0, 0, 1]], " +
                  "\"distCoef\": [-0.2, 0.15, 0.001, -0.0005, 0.02]";
  if (override_R != "none") s += ", \"R\": " + r_json;
  s += ", \"t\": [[" + Num(t.x()) + "], [" + Num(t.y()) + "], [" + Num(t.z()) + "]]}";
  return s;
}

std::string CalibrationJson(const std::string& first_R = "", int r_digits = 17) {
  return "{\"calibDataSource\": \"test\", \"cameras\": [" +
         PanopticCameraJson("00_00", "hd", Eigen::Vector3d(0, -200, -400), first_R, r_digits) + ", " +
         PanopticCameraJson("01_01", "vga", Eigen::Vector3d(400, -150, 0), "", r_digits) + ", " +
         PanopticCameraJson("00_01", "hd", Eigen::Vector3d(-400, -250, 10), "", r_digits) + "]}";
}

// joints19 text: joint j at (10 + j, -150 + 5 j, 20) cm with confidence c(j).
std::string Joints19(const std::function<double(int)>& confidence, int missing_from = 19) {
  std::string s = "[";
  for (int j = 0; j < 19; ++j) {
    const bool missing = j >= missing_from;
    s += std::string(j ? ", " : "") +
         (missing ? "0, 0, 0, -1" : Num(10 + j) + ", " + Num(-150 + 5 * j) + ", 20, " + Num(confidence(j)));
  }
  return s + "]";
}

std::string Scene(const std::string& bodies) {
  return "{ \"version\": 0.7, \"univTime\": 1.5, \"fpsType\": \"hd_29_97\", \"bodies\": [" + bodies + "] }";
}

// seqA: frame 10 one body with joints 15-18 missing; frame 11 no bodies; frame 12 a body with an
// invisible root (dropped) and a valid one; frame 13 a valid body.
void WriteSequence(const std::filesystem::path& root, const std::string& calibration = CalibrationJson()) {
  const std::filesystem::path seq = root / "seqA";
  WriteText(seq / "calibration_seqA.json", calibration);
  const std::filesystem::path poses = seq / "hdPose3d_stage1_coco19";
  WriteText(poses / "body3DScene_00000010.json",
            Scene("{\"id\": 4, \"joints19\": " + Joints19([](int j) { return j == 1 ? 0.05 : 0.7; }, 15) + "}"));
  WriteText(poses / "body3DScene_00000011.json", Scene(""));
  WriteText(poses / "body3DScene_00000012.json",
            Scene("{\"id\": 1, \"joints19\": " + Joints19([](int j) { return j == 2 ? 0.1 : 0.9; }) +
                  "}, {\"id\": 2, \"joints19\": " + Joints19([](int) { return 0.3; }) + "}"));
  WriteText(poses / "body3DScene_00000013.json",
            Scene("{\"id\": 2, \"joints19\": " + Joints19([](int) { return 1.0; }) + "}"));
}

TEST(PanopticReader, GeneratedFilesMissingJointsEmptyBodiesAndRoots) {
  test::TempDir dir;
  WriteSequence(dir.path());
  const std::map<std::string, std::string> base = {{"sequences", "seqA"}, {"cameras", "00_00,00_01"}, {"every", "1"}};
  // Not body3DScene_<number>.json: ignored, and counted (one line for the folder).
  const std::filesystem::path poses = dir.path() / "seqA" / "hdPose3d_stage1_coco19";
  WriteText(poses / "notes.json", "not a pose file");
  WriteText(poses / "body3DScene_0000001x.json", Scene(""));
  const Sequence kept = ReadDataset(Request(dir.path(), base))[0];  // skip_empty=true
  ASSERT_EQ(kept.warnings.items().size(), 2u);
  EXPECT_EQ(
      kept.warnings.items()[0].Line(),
      poses.string() + ": 2 entries not named body3DScene_<number>.json ignored (e.g. 'body3DScene_0000001x.json')");
  EXPECT_EQ(kept.warnings.items()[0].kind, InputWarningKind::kUnused);
  // The body left out by VoxelPose's rule is counted (it was dropped without a word).
  EXPECT_EQ(kept.warnings.items()[1].Line(),
            poses.string() + ": 1 bodies whose body_center has confidence <= 0.1 left out of the ground truth "
                             "(VoxelPose's rule; a person triangulated there counts as Invalid)");
  EXPECT_EQ(kept.warnings.items()[1].kind, InputWarningKind::kMissing);
  ASSERT_EQ(kept.frames.size(), 3u);
  EXPECT_EQ(kept.frames[0].id, "panoptic_seqA_000010");
  EXPECT_EQ(kept.frames[1].id, "panoptic_seqA_000012");
  EXPECT_EQ(kept.frames[2].id, "panoptic_seqA_000013");
  EXPECT_EQ(kept.frames[1].gt.track_ids, (std::vector<int>{2}));  // body 1's root has c = 0.1: dropped

  const Poses3D& gt = kept.frames[0].gt;
  ASSERT_EQ(gt.track_ids, (std::vector<int>{4}));
  EXPECT_EQ(gt.num_joints, 19);
  EXPECT_DOUBLE_EQ(gt.Person(0)(3, 0), 0.7);
  EXPECT_DOUBLE_EQ(gt.Person(0)(3, 1), 0.05);  // kept, but below the 0.1 visibility threshold
  for (int j = 15; j < 19; ++j) EXPECT_EQ(gt.Person(0)(3, j), 0.0) << j;
  // (10, -150, 20) cm, y down -> (0.10, 0.20, 1.50) m, z up.
  EXPECT_TRUE(gt.Person(0).col(0).head<3>().isApprox(Eigen::Vector3d(0.10, 0.20, 1.50), 1e-12));

  std::map<std::string, std::string> keep_empty = base;
  keep_empty["skip_empty"] = "false";
  const Sequence all = ReadDataset(Request(dir.path(), keep_empty))[0];
  ASSERT_EQ(all.frames.size(), 4u);
  EXPECT_EQ(all.frames[1].id, "panoptic_seqA_000011");
  EXPECT_EQ(all.frames[1].gt.num_persons(), 0);

  std::map<std::string, std::string> every2 = keep_empty;
  every2["every"] = "2";
  const Sequence sampled = ReadDataset(Request(dir.path(), every2))[0];
  ASSERT_EQ(sampled.frames.size(), 2u);
  EXPECT_EQ(sampled.frames[1].id, "panoptic_seqA_000012");

  // Cameras: "hd" = the two HD ones in file order; a VGA camera by name keeps its resolution.
  const Sequence hd = ReadDataset(Request(dir.path(), {{"sequences", "seqA"}, {"cameras", "hd"}}))[0];
  ASSERT_EQ(hd.cameras.size(), 2u);
  EXPECT_EQ(hd.cameras[0].name, "00_00");
  EXPECT_EQ(hd.cameras[1].name, "00_01");
  // The studio has 31: the 29 the file lacks are said (a calibration missing a camera was used silently).
  const auto said = [](const Sequence& s) {
    for (const InputWarning& w : s.warnings.items()) {
      if (w.Line().ends_with(": 29 HD cameras of the studio's 31 missing from the file: cameras=hd uses the 2 it has")) {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(said(hd));
  EXPECT_FALSE(said(ReadDataset(Request(dir.path(), {{"sequences", "seqA"}, {"cameras", "00_00,00_01"}}))[0]));
  const Sequence vga = ReadDataset(Request(dir.path(), {{"sequences", "seqA"}, {"cameras", "01_01"}}))[0];
  EXPECT_EQ(vga.cameras[0].width, 640);
  EXPECT_EQ(vga.cameras[0].dist, (std::array<double, 5>{-0.2, 0.15, 0.001, -0.0005, 0.02}));

  // The converted camera projects the converted point where the original projects the original.
  const nlohmann::json calibration = LoadJson(dir.path() / "seqA/calibration_seqA.json");
  for (const Camera& camera : kept.cameras) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(camera.Project(PanopticPointToWorld(Eigen::Vector3d(30, -120, 40)), &uv));
    EXPECT_LT((uv - PanopticProject(*FindCamera(calibration, camera.name), Eigen::Vector3d(30, -120, 40))).norm(),
              1e-6);
    EXPECT_EQ(camera.Validate(), "");
  }
}

TEST(PanopticReader, MalformedInputNamesFileAndPlace) {
  test::TempDir dir;
  WriteSequence(dir.path());
  const std::filesystem::path poses = dir.path() / "seqA" / "hdPose3d_stage1_coco19";
  const std::map<std::string, std::string> base = {{"sequences", "seqA"}, {"cameras", "00_00"}, {"every", "1"}};

  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"sequences", "seqA,seqB"}}));
              }),
              HasSubstr("panoptic: sequence 'seqB' not found"));
  EXPECT_THAT(
      test::InputErrorOf([&] {
        ReadDataset(Request(dir.path(), {{"sequences", "seqA"}, {"cameras", "00_00,00_07"}}));
      }),
      HasSubstr(
          "calibration_seqA.json: camera '00_07' not found; HD cameras: 00_00, 00_01 (plus 1 VGA/Kinect cameras)"));

  // A NaN (not JSON) and a null coordinate.
  WriteText(poses / "body3DScene_00000013.json", Scene("{\"id\": 2, \"joints19\": [NaN, 1, 2, 0.5]}"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("body3DScene_00000013.json:1:"));
  std::string with_null = Joints19([](int) { return 0.5; });
  with_null.replace(1, 2, "null");
  WriteText(poses / "body3DScene_00000013.json", Scene("{\"id\": 2, \"joints19\": " + with_null + "}"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("body3DScene_00000013.json: /bodies/0/joints19"));
  WriteText(poses / "body3DScene_00000013.json", Scene("{\"id\": 2, \"joints19\": [1, 2, 3, 0.5]}"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("body3DScene_00000013.json: /bodies/0/joints19: expected"));
  WriteText(poses / "body3DScene_00000013.json", "{\"bodies\": 3}");
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("body3DScene_00000013.json: /bodies: expected an array"));

  // Cameras: missing R, an R 0.44 away from a rotation (beyond the 1e-3 tolerance), missing file.
  WriteSequence(dir.path(), CalibrationJson("none"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("calibration_seqA.json: /cameras/0/R: missing"));
  WriteSequence(dir.path(), CalibrationJson("[[1, 0, 0], [0, 1.2, 0], [0, 0, 1]]"));
  EXPECT_THAT(
      test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
      HasSubstr("calibration_seqA.json: /cameras/0/R (camera '00_00'): R is not a rotation (max |R^T R - I| = 0.44"));
  std::filesystem::remove(dir.path() / "seqA" / "calibration_seqA.json");
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("calibration_seqA.json: file not found"));

  // No annotation folder.
  WriteSequence(dir.path());
  std::filesystem::remove_all(poses);
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), base)); }),
              HasSubstr("hdPose3d_stage1_coco19: annotation folder not found"));
}

TEST(PanopticReader, RotationsWithSixDigitsAreReorthonormalisedAndCounted) {
  test::TempDir dir;
  WriteSequence(dir.path(), CalibrationJson("", 6));
  const std::map<std::string, std::string> params = {{"sequences", "seqA"}, {"cameras", "00_00,00_01"}, {"every", "1"}};
  const Sequence sequence = ReadDataset(Request(dir.path(), params))[0];
  ASSERT_EQ(sequence.cameras.size(), 2u);
  for (const Camera& camera : sequence.cameras) {
    EXPECT_LT((camera.R.transpose() * camera.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  }
  // Only the two selected cameras are read (the VGA camera's R is not used, so not counted); the
  // other warning is frame 12's body left out (ReadBodies).
  ASSERT_EQ(sequence.warnings.items().size(), 2u);
  const InputWarning& w = sequence.warnings.items()[0];
  EXPECT_EQ(w.source, (dir.path() / "seqA" / "calibration_seqA.json").string());
  EXPECT_EQ(w.what, "rotations re-orthonormalised");
  EXPECT_EQ(w.count, 2);
  EXPECT_GT(w.worst, 1e-9);
  EXPECT_LT(w.worst, 1e-5);

  WriteSequence(dir.path());  // 17 digits: exact to round-off, nothing to report
  const InputWarnings exact = ReadDataset(Request(dir.path(), params))[0].warnings;
  EXPECT_TRUE(std::none_of(exact.items().begin(), exact.items().end(),
                           [](const InputWarning& x) { return x.what == "rotations re-orthonormalised"; }));
  // 1e-2 off is a wrong matrix, not rounding.
  WriteSequence(dir.path(), CalibrationJson("[[1.005, 0, 0], [0, 1.005, 0], [0, 0, 1.005]]"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path(), params)); }),
              HasSubstr((dir.path() / "seqA" / "calibration_seqA.json").string() +
                        ": /cameras/0/R (camera '00_00'): R is not a rotation (max |R^T R - I| = 0.010025"));
}

TEST(PanopticReader, BadParamsAreConfigErrors) {
  test::TempDir dir;
  WriteSequence(dir.path());
  const auto config_error = [&](std::map<std::string, std::string> params) {
    params.emplace("sequences", "seqA");
    return test::ErrorMessage<ConfigError>([&] { ReadDataset(Request(dir.path(), params)); });
  };
  EXPECT_THAT(config_error({{"every", "0"}}), HasSubstr("--param every=0: panoptic.every: '0' is not an integer >= 1"));
  EXPECT_THAT(config_error({{"max_frames", "-2"}}), HasSubstr("max_frames"));
  EXPECT_THAT(config_error({{"skip_empty", "maybe"}}), HasSubstr("panoptic.skip_empty: 'maybe' is not true or false"));
  EXPECT_THAT(config_error({{"cameras", ","}}), HasSubstr("panoptic.cameras: no cameras selected by ','"));
  EXPECT_THAT(config_error({{"interval", "3"}}), HasSubstr("unknown parameter 'interval'"));
  EXPECT_EQ(PanopticParams{}.cameras, "00_03,00_06,00_12,00_13,00_23");
  EXPECT_THAT(config_error({{"camera", "00_03"}}), HasSubstr("did you mean 'cameras'?"));
  EXPECT_EQ(test::ErrorMessage<ConfigError>([&] {
              ReadDataset(Request(dir.path(), {{"sequences", ","}}));
            }),
            "panoptic.sequences: no sequences selected");
  // Given twice, a camera was one view weighed double and a sequence was read twice (the run then
  // failed late, "cannot merge accumulators").
  EXPECT_EQ(test::ErrorMessage<ConfigError>([&] {
              ReadDataset(Request(dir.path(), {{"sequences", "seqA,seqA"}}));
            }),
            "panoptic.sequences: 'seqA' is listed twice");
  EXPECT_THAT(config_error({{"cameras", "00_00,00_00"}}), HasSubstr("panoptic.cameras: '00_00' is listed twice"));
  // The slash shell completion adds is not part of the name (it made the calibration's path
  // "seqA/calibration_seqA/.json"); a slash inside names another folder.
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"sequences", "seqA/"}, {"cameras", "hd"}}))[0].name,
            ReadDataset(Request(dir.path(), {{"sequences", "seqA"}, {"cameras", "hd"}}))[0].name);
  EXPECT_THAT(config_error({{"sequences", "seqA/sub"}}),
              HasSubstr("panoptic.sequences: 'seqA/sub' is not a folder name directly under the root"));
}

}  // namespace
}  // namespace rpt
