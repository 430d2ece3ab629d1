// SPDX-License-Identifier: MIT
// The MVOR reader: the real files in shared/data/mvor (skipped when absent; never copied into the
// project) and a small annotation file of the same schema written by the tests.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"
#include "datasets/readers/mvor.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
using engine::ReadDataset;
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

DatasetRequest Request(const fs::path& root, std::map<std::string, std::string> params = {}) {
  DatasetRequest request;
  request.dataset = "mvor";
  request.root = root;
  request.params = std::move(params);
  return request;
}

double Median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// ---------------------------------------------------------------------------------------
// Real files.

TEST(MvorFixture, FramesPersonsCamerasAndDetections) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const std::vector<Sequence> sequences = ReadDataset(Request(test::SharedData("mvor")));
  ASSERT_EQ(sequences.size(), 4u);
  size_t frames = 0, persons = 0, detections = 0;
  for (const Sequence& s : sequences) {
    ASSERT_EQ(s.cameras.size(), 3u);
    EXPECT_EQ(s.cameras[0].name, "cam1");
    EXPECT_EQ(s.cameras[2].width, 640);
    EXPECT_EQ(s.cameras[2].height, 480);
    EXPECT_EQ(s.evaluated_joints.size(), 8u);
    frames += s.frames.size();
    std::vector<double> gaps;
    for (size_t f = 0; f < s.frames.size(); ++f) {
      persons += s.frames[f].gt.num_persons();
      for (const Poses2D& view : s.frames[f].views) detections += view.num_persons();
      if (f > 0) gaps.push_back(s.frames[f].timestamp_s - s.frames[f - 1].timestamp_s);
    }
    EXPECT_EQ(s.frames.front().timestamp_s, 0.0);
    EXPECT_GT(*std::min_element(gaps.begin(), gaps.end()), 0.0) << s.name << ": times increase";
    EXPECT_NEAR(Median(gaps), 75.0, 1.0) << s.name << ": frames about 75 s apart";
  }
  EXPECT_EQ(frames, 732u);
  EXPECT_EQ(persons, 1061u);
  // Four frames give two 3D persons person_id 0: the second is untracked (-1), counted, so that
  // the labels rpt convert writes read back (generic labels refuse a repeated id).
  for (const Sequence& s : sequences) {
    for (const SequenceFrame& frame : s.frames) {
      std::vector<int> ids;
      for (const int id : frame.gt.track_ids) {
        if (id >= 0) ids.push_back(id);
      }
      std::sort(ids.begin(), ids.end());
      EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end()) << frame.id;
      if (frame.id == "mvor_day1_000024") {
        EXPECT_EQ(frame.gt.track_ids, (std::vector<int>{0, -1}));
      }
    }
  }
  long repeated_ids = 0;  // counted per day, where the frames are converted
  for (const Sequence& s : sequences) {
    for (const InputWarning& w : s.warnings.items()) {
      if (w.what.find("person_id repeats") != std::string::npos) repeated_ids += w.count;
    }
  }
  EXPECT_EQ(repeated_ids, 4);

  // Detections: every entry of the OpenPose file with keypoints, counted independently.
  std::ifstream in(test::SharedData("mvor/openpose_kps.json"));
  const nlohmann::json results = nlohmann::json::parse(in);
  size_t with_keypoints = 0, above_one = 0;
  for (const auto& r : results) {
    if (r["coco_keypoints"].empty()) continue;
    ++with_keypoints;
    for (size_t i = 2; i < r["coco_keypoints"].size(); i += 3) above_one += r["coco_keypoints"][i].get<double>() > 1.0;
  }
  EXPECT_EQ(detections, with_keypoints);
  // Scores slightly above 1 are accepted, clamped and counted once (the first sequence carries
  // the file's corrections).
  long counted = 0;
  for (const InputWarning& w : sequences[0].warnings.items()) {
    if (w.what == "scores above 1 clamped to 1") counted = w.count;
  }
  EXPECT_EQ(counted, static_cast<long>(above_one));
  for (size_t i = 1; i < sequences.size(); ++i) {  // only the frames' own: the repeated person ids above
    for (const InputWarning& w : sequences[i].warnings.items()) EXPECT_NE(w.what.find("person_id repeats"), std::string::npos) << w.what;
  }
}

// The world frame is right when the 3D labels, projected through our cameras, land on the 2D
// labels: MVOR's 3D and 2D annotations were made independently (median 7.7 / 8.9 / 7.9 px).
TEST(MvorFixture, ProjectedGroundTruthLandsOnThe2dLabels) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const std::vector<Sequence> sequences = ReadDataset(Request(test::SharedData("mvor"), {{"detections", "none"}}));
  std::ifstream in(test::SharedData("mvor/camma_mvor_2018.json"));
  const nlohmann::json root = nlohmann::json::parse(in);
  // 2D labels by (frame id, camera, person id): 10 points (head, neck, shoulders, hips, elbows, wrists).
  std::map<std::tuple<std::string, int, int>, std::vector<double>> labels;
  for (const auto& a : root["annotations"]) {
    const long long id = a["image_id"].get<long long>();
    const int day = static_cast<int>(id / 10000000000LL), cam = static_cast<int>(id / 10000000 % 1000);
    char frame[32];
    std::snprintf(frame, sizeof(frame), "mvor_day%d_%06d", day, static_cast<int>(id % 10000000));
    labels[{frame, cam - 1, a["person_id"].get<int>()}] = a["keypoints"].get<std::vector<double>>();
  }
  const std::vector<std::string> order = {"head",      "shoulder_middle", "shoulder_left", "shoulder_right", "hip_left",
                                          "hip_right", "elbow_left",      "elbow_right",   "wrist_left",     "wrist_right"};
  std::vector<std::vector<double>> errors(3);
  for (const Sequence& s : sequences) {
    for (const SequenceFrame& frame : s.frames) {
      for (int p = 0; p < frame.gt.num_persons(); ++p) {
        for (int c = 0; c < 3; ++c) {
          const auto it = labels.find({frame.id, c, frame.gt.track_ids[p]});
          if (it == labels.end()) continue;
          for (int j = 0; j < 10; ++j) {
            const int g = FindJoint(s.gt_joints, order[j]);
            if (it->second[3 * j + 2] <= 0 || frame.gt.Person(p)(3, g) <= 0) continue;
            Eigen::Vector2d uv;
            if (!s.cameras[c].Project(frame.gt.Person(p).col(g).head<3>(), &uv)) continue;
            errors[c].push_back((uv - Eigen::Vector2d(it->second[3 * j], it->second[3 * j + 1])).norm());
          }
        }
      }
    }
  }
  const double expected[3] = {7.69, 8.94, 7.92};
  for (int c = 0; c < 3; ++c) {
    ASSERT_GT(errors[c].size(), 1000u);
    EXPECT_NEAR(Median(errors[c]), expected[c], 0.05) << "cam" << c + 1;
  }
}

TEST(MvorFixture, ParamsSelectDaysAndJoints) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const std::vector<Sequence> day3 =
      ReadDataset(Request(test::SharedData("mvor"), {{"days", "3"}, {"detections", "none"}, {"evaluated", "paper"}}));
  ASSERT_EQ(day3.size(), 1u);
  EXPECT_EQ(day3[0].name, "mvor/day3");
  EXPECT_EQ(day3[0].evaluated_joints.front(), "nose");
  EXPECT_EQ(day3[0].evaluated_joints.size(), 9u);
  for (const SequenceFrame& f : day3[0].frames) {
    EXPECT_TRUE(f.id.starts_with("mvor_day3_"));
    EXPECT_TRUE(f.views.empty()) << "no detections attached";
  }
}

// ---------------------------------------------------------------------------------------
// Written files: one day, two frames, hand-made cameras.

nlohmann::json Rigid(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  nlohmann::json m = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.push_back(R(r, c));
    m.push_back(t[r]);
  }
  for (double v : {0.0, 0.0, 0.0, 1.0}) m.push_back(v);
  return m;
}

nlohmann::json SmallAnnotations() {
  nlohmann::json intrinsics = nlohmann::json::array();
  for (int c = 0; c < 3; ++c) {
    intrinsics.push_back({{"focallength", {500.0, 500.0}}, {"principalpoint", {320.0, 240.0}},
                          {"distortion", {0.1, 0.0, 0.0, 0.0, 0.0}}, {"skew_value", 0}, {"imagesize", {640, 480}}});
  }
  // Camera 1 -> room: a 90 degree turn about x (camera z forward -> room y), then 2 m up and 1 m along x.
  Eigen::Matrix3d turn;
  turn << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  // Camera 2 sits 1 m to the right of camera 1, camera 3 turned 10 degrees; rotations rounded to 6 digits.
  const double a = 10.0 * M_PI / 180.0;
  Eigen::Matrix3d yaw;
  yaw << std::round(std::cos(a) * 1e6) / 1e6, 0, std::round(std::sin(a) * 1e6) / 1e6, 0, 1, 0,
      -std::round(std::sin(a) * 1e6) / 1e6, 0, std::round(std::cos(a) * 1e6) / 1e6;
  nlohmann::json cameras = {
      {"camParams",
       {{"intrinsics", intrinsics},
        {"extrinsics",
         {Rigid(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
          Rigid(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1000, 0, 0)), Rigid(yaw, Eigen::Vector3d(-500, 0, 0))}},
        {"firstCamToRoomRef", Rigid(turn, Eigen::Vector3d(1000, 0, 1000))}}}};
  nlohmann::json images = nlohmann::json::array(), frames = nlohmann::json::array();
  const char* times[2] = {"2015-04-01 06:47:08.500000", "2015-04-01 06:48:23.750000"};
  for (int f = 0; f < 2; ++f) {
    nlohmann::json set = nlohmann::json::array();
    for (int c = 1; c <= 3; ++c) {
      char name[64];
      std::snprintf(name, sizeof(name), "day1/cam%d/color/%06d.png", c, 5 + f);
      nlohmann::json image = {{"id", 10000000000LL + c * 10000000LL + 5 + f}, {"file_name", name}, {"cam_id", c},
                              {"day_id", 1}, {"width", 640}, {"height", 480}, {"date_captured", times[f]}};
      images.push_back(image);
      set.push_back(image);
    }
    frames.push_back({{"id", "x"}, {"images", set}});
  }
  // One person in frame 1 (the second): every point 3 m in front of camera 1, 10 cm apart along x.
  std::vector<double> points;
  for (int j = 0; j < 12; ++j) {
    for (double v : {100.0 * j, 0.0, 3000.0, j == 11 ? 0.0 : 2.0}) points.push_back(v);
  }
  nlohmann::json persons = {{{"image_ids", "10010000006_10020000006_10030000006"}, {"person_id", 4}, {"ref_camera", 2},
                             {"keypoints3D", points}, {"id", "1"}}};
  return {{"cameras_info", cameras}, {"images", images}, {"multiview_images", frames}, {"annotations3D", persons}};
}

void WriteJson(const fs::path& path, const nlohmann::json& json) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << json.dump();
}

TEST(MvorReader, ConvertsToTheRoomFrameInMetres) {
  test::TempDir dir;
  WriteJson(dir.path() / "annotations/camma_mvor_2018.json", SmallAnnotations());
  const std::vector<Sequence> sequences = ReadDataset(Request(dir.path(), {{"detections", "none"}}));
  ASSERT_EQ(sequences.size(), 1u) << "days without frames are not listed";
  const Sequence& s = sequences[0];
  ASSERT_EQ(s.frames.size(), 2u);
  EXPECT_EQ(s.frames[1].id, "mvor_day1_000006");
  EXPECT_NEAR(s.frames[1].timestamp_s, 75.25, 1e-9);
  ASSERT_EQ(s.frames[0].gt.num_persons(), 0);
  ASSERT_EQ(s.frames[1].gt.num_persons(), 1);
  EXPECT_EQ(s.frames[1].gt.track_ids[0], 4);
  const auto person = s.frames[1].gt.Person(0);
  // Camera-1 point (0, 0, 3000) mm -> room (1000, 3000, 1000) mm -> world (1, 3, 1 + 1) m.
  EXPECT_LT((person.col(0).head<3>() - Eigen::Vector3d(1, 3, 2)).norm(), 1e-9);
  EXPECT_EQ(person(3, 0), 1.0);
  EXPECT_EQ(person(3, 11), 0.0) << "flag 0: not visible";
  EXPECT_LT((person.col(12) - person.col(0)).norm(), 1e-12) << "nose is a copy of the head";
  // Every camera sees the camera-1 point where its extrinsics say: camera 2 is 1 m to camera 1's right.
  Eigen::Vector2d uv;
  ASSERT_TRUE(s.cameras[0].Project(person.col(0).head<3>(), &uv));
  EXPECT_LT((uv - Eigen::Vector2d(320, 240)).norm(), 1e-6);
  ASSERT_TRUE(s.cameras[1].Project(person.col(0).head<3>(), &uv));
  EXPECT_LT((uv - Eigen::Vector2d(320 - 500.0 / 3.0, 240)).norm(), 1e-6);
  EXPECT_EQ(s.cameras[0].dist, (std::array<double, 5>{})) << "distortion ignored by default";
  // The rounded rotation of camera 3 is accepted and counted.
  ASSERT_EQ(s.warnings.items().size(), 1u);
  EXPECT_EQ(s.warnings.items()[0].what, "rotations re-orthonormalised");
  EXPECT_THAT(s.warnings.items()[0].source, HasSubstr("camma_mvor_2018.json"));
}

TEST(MvorReader, DistortionFileAppliesTheNumbersAsK1K2K3P1P2) {
  test::TempDir dir;
  nlohmann::json json = SmallAnnotations();
  json["cameras_info"]["camParams"]["intrinsics"][0]["distortion"] = {0.1, 0.2, 0.3, 0.4, 0.5};
  WriteJson(dir.path() / "camma_mvor_2018.json", json);
  const std::vector<Sequence> s = ReadDataset(Request(dir.path(), {{"detections", "none"}, {"distortion", "file"}}));
  EXPECT_EQ(s[0].cameras[0].model, DistortionModel::kOpenCV);
  EXPECT_EQ(s[0].cameras[0].dist, (std::array<double, 5>{0.1, 0.2, 0.4, 0.5, 0.3}));
}

TEST(MvorReader, BadParamsAndFilesAreNamed) {
  test::TempDir dir;
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadDataset(Request(dir.path(), {{"days", "5"}})); }), HasSubstr("days"));
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadDataset(Request(dir.path(), {{"days", "2,1,2"}})); }),
              HasSubstr("mvor.days: '2' is listed twice"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "alphapose"}}));
              }),
              HasSubstr("not one of openpose, none"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path() / "missing")); }), HasSubstr("not a directory"));
  EXPECT_THAT(test::InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("camma_mvor_2018.json"));
  WriteJson(dir.path() / "camma_mvor_2018.json", SmallAnnotations());
  EXPECT_THAT(
      test::InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
      HasSubstr(
          "openpose_kps.json not found (the OpenPose detections shipped with MVOR); use --param detections=none"));
  nlohmann::json bad = SmallAnnotations();
  bad["cameras_info"]["camParams"]["extrinsics"][1][0] = 1.1;  // not a rotation
  WriteJson(dir.path() / "camma_mvor_2018.json", bad);
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "none"}}));
              }),
              HasSubstr("/cameras_info/camParams/extrinsics/1: R is not a rotation"));
  bad = SmallAnnotations();
  bad["multiview_images"][0]["images"][2]["file_name"] = "day1/cam3/color/000099.png";
  WriteJson(dir.path() / "camma_mvor_2018.json", bad);
  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "none"}}));
              }),
              HasSubstr("/multiview_images/0/images/2: day or frame number differs"));
}

}  // namespace
}  // namespace rpt
